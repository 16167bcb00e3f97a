// tessellab cross-check: evaluate a cage's exact limit surface with OpenSubdiv
// (Bfr surfaces; Far::PatchTable for faces next to interior valence-2 vertices,
// which hit a Bfr bug in 3.5.0) and print it in the same JSON layout as
// `npm run subdiv -- --uniform N model.obj`.
//
//   osd_eval [--file-options] [--far] N model.obj
//
// Our own OBJ reading (obj_reader.h); no code from OpenSubdiv's examples is used.
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include "refiner.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace OpenSubdiv;

int main(int argc, char **argv) {
    bool fileOptions = false, forceFar = false;
    int ai = 1;
    for (; ai < argc && argv[ai][0] == '-' && argv[ai][1] == '-'; ai++) {
        std::string a = argv[ai];
        if (a == "--file-options") fileOptions = true;
        else if (a == "--far") forceFar = true;
        else { std::fprintf(stderr, "unknown option %s\n", argv[ai]); return 64; }
    }
    if (argc - ai != 2) { std::fprintf(stderr, "usage: osd_eval [--file-options] [--far] N model.obj\n"); return 64; }
    int N = std::atoi(argv[ai]);
    Obj o;
    if (!readObj(argv[ai + 1], o)) { std::fprintf(stderr, "cannot read %s\n", argv[ai + 1]); return 66; }

    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    sdc.SetCreasingMethod(Sdc::Options::CREASE_UNIFORM);
    sdc.SetTriangleSubdivision(Sdc::Options::TRI_SUB_CATMARK);
    if (fileOptions) {
        if (o.boundary == 0) sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_NONE);
        if (o.boundary == 2) sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
        if (o.chaikin == 1) sdc.SetCreasingMethod(Sdc::Options::CREASE_CHAIKIN);
    }
    std::unique_ptr<Far::TopologyRefiner> refiner = createRefiner(o, sdc);
    const int numVertices = (int)o.pos.size() / 3;
    const int numFaces = (int)o.counts.size();
    if (!refiner) { std::fprintf(stderr, "OpenSubdiv refused the topology\n"); return 3; }
    Far::TopologyLevel const &base = refiner->GetLevel(0);

    // Faces touching an interior valence-2 vertex go through Far::PatchTable.
    std::vector<char> useFar(o.counts.size(), forceFar ? 1 : 0);
    for (int v = 0; v < numVertices; v++) {
        if (base.IsVertexBoundary(v) || base.GetVertexEdges(v).size() != 2) continue;
        if (base.GetVertexFaces(v).size() != 2) continue;
        Far::ConstIndexArray fs = base.GetVertexFaces(v);
        for (int i = 0; i < fs.size(); i++) useFar[fs[i]] = 1;
    }
    bool anyFar = false;
    for (char c : useFar) anyFar |= c != 0;

    // Far adaptive patch table (only if needed).
    std::unique_ptr<Far::TopologyRefiner> refiner2;
    std::unique_ptr<Far::PatchTable const> patches;
    std::unique_ptr<Far::PatchMap> patchMap;
    std::vector<double> allPts;
    std::unique_ptr<Far::PtexIndices> ptex;
    if (anyFar) {
        refiner2 = createRefiner(o, sdc);
        Far::PatchTableFactory::Options popts(10);
        popts.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
        popts.useInfSharpPatch = true;
        popts.SetPatchPrecision<double>();
        Far::TopologyRefiner::AdaptiveOptions aopts = popts.GetRefineAdaptiveOptions();
        refiner2->RefineAdaptive(aopts);
        patches.reset(Far::PatchTableFactory::Create(*refiner2, popts));
        Far::StencilTableFactoryReal<double>::Options sopts;
        sopts.generateOffsets = true;
        sopts.generateIntermediateLevels = true;
        std::unique_ptr<Far::StencilTableReal<double> const> st(
            Far::StencilTableFactoryReal<double>::Create(*refiner2, sopts));
        Far::StencilTableReal<double> const *local = patches->GetLocalPointStencilTable<double>();
        Far::StencilTableReal<double> const *full = st.get();
        std::unique_ptr<Far::StencilTableReal<double> const> merged;
        if (local) {
            merged.reset(Far::StencilTableFactoryReal<double>::AppendLocalPointStencilTable(*refiner2, st.get(), local, true));
            full = merged.get();
        }
        int nCtrl = numVertices;
        int nSt = full->GetNumStencils();
        allPts.assign(3 * (nCtrl + nSt), 0.0);
        for (int i = 0; i < 3 * nCtrl; i++) allPts[i] = o.pos[i];
        for (int s = 0; s < nSt; s++) {
            auto sten = full->GetStencil(s);
            int sz = sten.GetSize();
            Far::Index const *idx = sten.GetVertexIndices();
            double const *w = sten.GetWeights();
            for (int k = 0; k < sz; k++)
                for (int c = 0; c < 3; c++) allPts[3 * (nCtrl + s) + c] += w[k] * o.pos[3 * idx[k] + c];
        }
        patchMap.reset(new Far::PatchMap(*patches));
        ptex.reset(new Far::PtexIndices(*refiner2));
    }

    Bfr::SurfaceFactory::Options fopts;
    fopts.SetApproxLevelSmooth(10);
    fopts.SetApproxLevelSharp(10);
    Bfr::RefinerSurfaceFactory<> factory(*refiner, fopts);
    Bfr::Surface<double> surf;
    std::vector<double> patchPts;

    std::printf("{\"faces\":[\n");
    for (int f = 0; f < numFaces; f++) {
        int n = o.counts[f];
        if (f) std::printf(",\n");
        if (!factory.FaceHasLimitSurface(f)) { std::printf("{\"f\":%d,\"n\":%d,\"hole\":true,\"sub\":[]}", f, n); continue; }
        bool far = useFar[f] != 0;
        if (!far) {
            if (!factory.InitVertexSurface(f, &surf)) { std::fprintf(stderr, "face %d: no Bfr surface\n", f); return 4; }
            patchPts.resize(3 * surf.GetNumPatchPoints());
            surf.PreparePatchPoints(o.pos.data(), 3, patchPts.data(), 3);
        }
        std::printf("{\"f\":%d,\"n\":%d%s,\"sub\":[", f, n, far ? ",\"far\":true" : "");
        int nsub = n == 4 ? 1 : n;
        for (int k = 0; k < nsub; k++) {
            std::vector<double> P, Nn;
            for (int j = 0; j <= N; j++) {
                for (int i = 0; i <= N; i++) {
                    double st[2] = {(double)i / N, (double)j / N};
                    double p[3], du[3], dv[3];
                    if (!far) {
                        double uv[2];
                        Bfr::Parameterization param = surf.GetParameterization();
                        if (n == 4) { uv[0] = st[0]; uv[1] = st[1]; }
                        else param.ConvertNormalizedSubFaceToCoord(k, st, uv);
                        surf.Evaluate(uv, patchPts.data(), 3, p, du, dv);
                    } else {
                        int pf = ptex->GetFaceId(f) + (n == 4 ? 0 : k);
                        Far::PatchTable::PatchHandle const *hnd = patchMap->FindPatch(pf, st[0], st[1]);
                        if (!hnd) { std::fprintf(stderr, "face %d: no patch\n", f); return 4; }
                        double wP[20], wDu[20], wDv[20];
                        patches->EvaluateBasis(*hnd, st[0], st[1], wP, wDu, wDv);
                        Far::ConstIndexArray cvs = patches->GetPatchVertices(*hnd);
                        for (int c = 0; c < 3; c++) { p[c] = du[c] = dv[c] = 0; }
                        for (int q = 0; q < cvs.size(); q++)
                            for (int c = 0; c < 3; c++) {
                                double x = allPts[3 * cvs[q] + c];
                                p[c] += wP[q] * x; du[c] += wDu[q] * x; dv[c] += wDv[q] * x;
                            }
                    }
                    double nx = du[1] * dv[2] - du[2] * dv[1], ny = du[2] * dv[0] - du[0] * dv[2], nz = du[0] * dv[1] - du[1] * dv[0];
                    double l = std::sqrt(nx * nx + ny * ny + nz * nz);
                    for (int c = 0; c < 3; c++) P.push_back(p[c]);
                    if (l > 0 && std::isfinite(l)) { Nn.push_back(nx / l); Nn.push_back(ny / l); Nn.push_back(nz / l); }
                    else { Nn.push_back(NAN); Nn.push_back(NAN); Nn.push_back(NAN); }
                }
            }
            std::printf("%s{\"k\":%d,\"res\":%d,\"P\":[", k ? "," : "", k, N);
            for (size_t q = 0; q < P.size(); q++) std::printf("%s%.17g", q ? "," : "", P[q]);
            std::printf("],\"N\":[");
            for (size_t q = 0; q < Nn.size(); q++) {
                if (std::isfinite(Nn[q])) std::printf("%s%.17g", q ? "," : "", Nn[q]);
                else std::printf("%snull", q ? "," : "");
            }
            std::printf("]}");
        }
        std::printf("]}");
    }
    std::printf("\n]}\n");
    return 0;
}
