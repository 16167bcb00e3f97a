// tessellab benchmark: how long OpenSubdiv takes, in this process, to go from an OBJ cage to
// its exact limit surface evaluated on every face. Timed phases (std::chrono::steady_clock):
//   load      read and parse the OBJ (obj_reader.h)
//   topology  Far::TopologyRefiner creation + Bfr::RefinerSurfaceFactory
//   surfaces  for every face: Bfr::Surface<double> at the most exact setting (approximation
//             level 10 for smooth and sharp features, as tools/osd-check/osd_eval uses) and
//             its patch points from the cage positions
//   eval      (N+1)^2 samples per quad and per sub-face of a non-quad (OpenSubdiv's own
//             sub-face parameterisation): position and both derivatives
// then, from the parsed cage again, what an engine built on Far's adaptive patches prepares once per
// topology (the peer of tessellab's CPU preparation, src/gpu/cc/build.ts):
//   far       a fresh Far::TopologyRefiner, RefineAdaptive at isolation level 2, and
//             Far::PatchTableFactory::Create with Gregory basis end caps (their local points'
//             stencils included)
// and prints one JSON line:
//   {"faces", "samples", "failed", "ms_load", "ms_topology", "ms_surfaces", "ms_setup"
//    (= topology + surfaces), "ms_eval", "ms_total" (= load + setup + eval), "checksum",
//    "far_patches", "ms_far_refine", "ms_far_patches", "ms_far" (= refine + patches)}
// `failed` counts faces Bfr could not give a surface (none on the talk's four cages); the
// checksum (sum of all coordinates) keeps the evaluation from being optimised away.
//
//   osd_time [--grid N] [--approx L] [--float] model.obj      (defaults: N = 8, L = 10, double)
//
// OpenSubdiv's default options, as everywhere in tessellab: edge-and-corner boundaries,
// uniform creasing, Catmark triangles; the file's option tags are ignored.
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include "refiner.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

using namespace OpenSubdiv;
using Clock = std::chrono::steady_clock;

static double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

template <typename REAL>
static int run(const Obj &o, Far::TopologyRefiner &refiner, int N, int approx, double times[2], long &samples, int &failed, double &checksum) {
    Bfr::SurfaceFactory::Options fopts;
    fopts.SetApproxLevelSmooth(approx);
    fopts.SetApproxLevelSharp(approx);
    Bfr::RefinerSurfaceFactory<> factory(refiner, fopts);
    Bfr::Surface<REAL> surf;
    std::vector<REAL> cage(o.pos.begin(), o.pos.end()), patchPts;
    Clock::duration tSurf{}, tEval{};
    const int nFaces = (int)o.counts.size();
    for (int f = 0; f < nFaces; f++) {
        if (!factory.FaceHasLimitSurface(f)) continue;
        Clock::time_point a = Clock::now();
        if (!factory.InitVertexSurface(f, &surf)) { failed++; continue; }
        patchPts.resize(3 * surf.GetNumPatchPoints());
        surf.PreparePatchPoints(cage.data(), 3, patchPts.data(), 3);
        Clock::time_point b = Clock::now();
        const int n = o.counts[f];
        const int nsub = n == 4 ? 1 : n;
        Bfr::Parameterization param = surf.GetParameterization();
        for (int k = 0; k < nsub; k++) {
            for (int j = 0; j <= N; j++) {
                for (int i = 0; i <= N; i++) {
                    REAL st[2] = {(REAL)i / N, (REAL)j / N}, uv[2];
                    if (n == 4) { uv[0] = st[0]; uv[1] = st[1]; }
                    else param.ConvertNormalizedSubFaceToCoord(k, st, uv);
                    REAL p[3], du[3], dv[3];
                    surf.Evaluate(uv, patchPts.data(), 3, p, du, dv);
                    checksum += (double)p[0] + (double)p[1] + (double)p[2] + 1e-9 * ((double)du[0] + (double)dv[2]);
                    samples++;
                }
            }
        }
        Clock::time_point c = Clock::now();
        tSurf += b - a;
        tEval += c - b;
    }
    times[0] = ms(tSurf);
    times[1] = ms(tEval);
    return 0;
}

int main(int argc, char **argv) {
    Clock::time_point t0 = Clock::now();
    int N = 8, approx = 10;
    bool useFloat = false;
    const char *path = nullptr;
    for (int ai = 1; ai < argc; ai++) {
        std::string a = argv[ai];
        if (a == "--grid" && ai + 1 < argc) N = std::atoi(argv[++ai]);
        else if (a == "--approx" && ai + 1 < argc) approx = std::atoi(argv[++ai]);
        else if (a == "--float") useFloat = true;
        else if (a.rfind("--", 0) == 0 || path) { std::fprintf(stderr, "usage: osd_time [--grid N] [--approx L] [--float] model.obj\n"); return 64; }
        else path = argv[ai];
    }
    if (!path || N < 1 || approx < 0) { std::fprintf(stderr, "usage: osd_time [--grid N] [--approx L] [--float] model.obj\n"); return 64; }
    Obj o;
    if (!readObj(path, o)) { std::fprintf(stderr, "cannot read %s\n", path); return 66; }
    Clock::time_point t1 = Clock::now();

    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    sdc.SetCreasingMethod(Sdc::Options::CREASE_UNIFORM);
    sdc.SetTriangleSubdivision(Sdc::Options::TRI_SUB_CATMARK);
    std::unique_ptr<Far::TopologyRefiner> refiner = createRefiner(o, sdc);
    if (!refiner) { std::fprintf(stderr, "OpenSubdiv refused the topology\n"); return 3; }
    Clock::time_point t2 = Clock::now();

    // The factory is built inside run(); its construction is cheap next to the refiner's and is
    // counted with the surfaces.
    double times[2] = {0, 0}, checksum = 0;
    long samples = 0;
    int failed = 0;
    if (useFloat) run<float>(o, *refiner, N, approx, times, samples, failed, checksum);
    else run<double>(o, *refiner, N, approx, times, samples, failed, checksum);
    Clock::time_point t3 = Clock::now();

    // Far: refiner, adaptive refinement (isolation 2) and the patch table with Gregory basis end
    // caps, from the parsed cage (not timed again: the load above).
    Clock::time_point f0 = Clock::now();
    std::unique_ptr<Far::TopologyRefiner> adaptive = createRefiner(o, sdc);
    if (!adaptive) { std::fprintf(stderr, "OpenSubdiv refused the topology\n"); return 3; }
    adaptive->RefineAdaptive(Far::TopologyRefiner::AdaptiveOptions(2));
    Clock::time_point f1 = Clock::now();
    Far::PatchTableFactory::Options popts(2);
    popts.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    std::unique_ptr<Far::PatchTable> patches(Far::PatchTableFactory::Create(*adaptive, popts));
    Clock::time_point f2 = Clock::now();
    const int farPatches = patches ? patches->GetNumPatchesTotal() : 0;

    const double load = ms(t1 - t0), topology = ms(t2 - t1), total = ms(t3 - t0);
    // Surfaces and evaluation are timed per face; the loop's own overhead goes with the surfaces.
    const double surfaces = ms(t3 - t2) - times[1];
    std::printf("{\"faces\":%d,\"samples\":%ld,\"failed\":%d,\"grid\":%d,\"approx\":%d,\"real\":\"%s\",\"ms_load\":%.3f,\"ms_topology\":%.3f,\"ms_surfaces\":%.3f,\"ms_setup\":%.3f,\"ms_eval\":%.3f,\"ms_total\":%.3f,\"checksum\":%.17g,"
                "\"far_patches\":%d,\"ms_far_refine\":%.3f,\"ms_far_patches\":%.3f,\"ms_far\":%.3f}\n",
                (int)o.counts.size(), samples, failed, N, approx, useFloat ? "float" : "double", load, topology, surfaces, topology + surfaces, times[1], total, checksum,
                farPatches, ms(f1 - f0), ms(f2 - f1), ms(f2 - f0));
    return failed ? 4 : 0;
}
