// CPU reference (f64) of the displaced limit surface: P' = P + h(uv)·N on the exact
// Catmull-Clark limit (evaluate.ts), h = (sample − midLevel)·scale, with the bilinear height
// lookup of mesh/heightmap.ts and the face-varying "linear all" UVs of mesh/uv.ts.
//
// Displaced normal (from the height map's derivatives and the limit tangents, never from
// finite differences of output vertices):
//   ∂h/∂u = scale·(∂sample/∂uv · ∂uv/∂u), ∂h/∂v likewise (bilinear patch gradient in texel
//   space, mapped through the face's uv Jacobian);
//   ∂P'/∂u ≈ ∂P/∂u + ∂h/∂u·N,  ∂P'/∂v ≈ ∂P/∂v + ∂h/∂v·N,  N' = normalize(∂P'/∂u × ∂P'/∂v).
// The exact derivative has a third term, h·∂N/∂u. We DROP it, as bump and displacement
// shading conventionally do, because (1) it needs second derivatives of the limit surface,
// which the evaluators (CPU and GPU) do not produce and which do not exist at extraordinary
// vertices, and (2) its size relative to ∂P/∂u is about |h|·κ (height times curvature), small
// for displacement that is detail on a smooth surface. The tests measure the angle it costs
// against finite differences of P' and check that adding it back (from finite differences of N,
// in the test only) closes the gap.
// At an irregular vertex (SurfacePoint.atVertex) ∂P/∂u, ∂P/∂v are limit tangents, not
// parametric derivatives (those are 0 or ∞ there), so N' there uses them as they are and is a
// convention, not a derivative (`normalExact` false). Where the limit normal is undefined
// (a corner of sharp creases, a cone point) the point moves along its owner face's one-sided
// normal (the sector normal the evaluator returns, as the GPU does), `normalExact` false; only
// where the evaluator has no normal at all does it stay: P' = P and N' is NaN.
//
// Seam rule (crack-free by construction, matching the compute tessellator's weld): a point on
// a cage edge or at a cage vertex takes its uv, height and normal from ONE face, its owner:
//   - vertex v: the lowest-id face with a limit surface that has v as a corner;
//   - edge a–b: the lowest-id face with a limit surface that has the edge, the point addressed
//     by x in [0, 1] along the edge's canonical direction, lower vertex index → higher;
// so a seam point gets one uv whichever face asks. This is what src/gpu/tess/prepare.ts builds:
// triangles are emitted in face order, vertexOwner/edgeOwner keep the FIRST triangle that has
// the vertex/edge, and wgsl/tess/weld.wgsl evaluates every corner and edge vertex through that
// one triangle (its face's uvs), edges in the canonical direction. (prepare.ts skips only
// tagged holes; faces made holes by boundary mode 'none' are skipped here too, and never own a
// weld vertex that has a surface.) tests/subdiv/displacement.test.ts checks the owners against
// prepareMesh.
//
// Precision budget for a GPU comparison (the GPU reads the SAME integer texels, so 8-bit
// quantisation is not an error between the two, only a property of the map): an f32 uv error
// δuv moves the sample by at most δuv·(texels per uv unit)·(largest texel step), and h by that
// times scale. For an 8-bit map the largest step is 1 (0 to 255 between neighbours), so
// |δh| ≤ scale·W·δuv; with δuv ≈ 1e-7 (a few f32 ulps of uv in [0, 1]), W = 512 and
// scale = 0.06 that is 3e-6, below 1e-5 of any model diagonal here. Sharp maps with large
// W·scale/diagonal need a looser bound or uv kept in f32 away from texel lines.
import type { Cage } from '../mesh/types.ts';
import { type HeightMap, type HeightWrap, sampleHeight } from '../mesh/heightmap.ts';
import { requireUvs, uvAtSubFace } from '../mesh/uv.ts';
import { type Topology, findEdge } from '../mesh/topology.ts';
import type { Surface, SurfacePoint } from './evaluate.ts';
import { cross } from './limit.ts';

type V3 = [number, number, number];

export interface DisplacementOptions {
  /** World units per unit of (sample − midLevel). */
  scale: number;
  /** Sample value (in [0, 1]) that means "no displacement". */
  midLevel: number;
  /** Texel addressing outside [0, 1]² (heightmap.ts). Default 'repeat'. */
  wrap?: HeightWrap;
}

/** A point on the surface in the exact reference's addressing (as gpu/face-params.ts FaceParam). */
export type SurfaceParam = { face: number; u: number; v: number } | { face: number; k: number; s: number; t: number };

export interface DisplacedPoint {
  /** Displaced position P + h·N. */
  P: V3;
  /** Displaced unit normal (see the header for the dropped h·∂N term). */
  N: V3;
  /** Height h = (sample − midLevel)·scale and its derivatives along the face parameters. */
  h: number;
  dhdu: number;
  dhdv: number;
  uv: [number, number];
  /** The undisplaced limit point. */
  base: SurfacePoint;
  /** The face (and parameters) the evaluation went through (the owner, for seam points). */
  at: SurfaceParam;
  /** false at irregular vertices (convention, see header) and where the limit normal is undefined. */
  normalExact: boolean;
}

/**
 * The seam rule's owner faces (see the header): per cage vertex and per topology edge, the
 * lowest-id face with a limit surface that contains it, or -1.
 */
export function weldOwnerFaces(T: Topology, hasSurface: (f: number) => boolean): { vertex: Int32Array; edge: Int32Array } {
  const vertex = new Int32Array(T.nVerts).fill(-1);
  const edge = new Int32Array(T.nEdges).fill(-1);
  // Faces in increasing id order: the first one to claim a vertex or edge owns it.
  for (let f = 0; f < T.nFaces; f++) {
    if (!hasSurface(f)) continue;
    for (let h = T.faceOffsets[f]; h < T.faceOffsets[f + 1]; h++) {
      if (vertex[T.faceIndices[h]] < 0) vertex[T.faceIndices[h]] = f;
      if (edge[T.heEdge[h]] < 0) edge[T.heEdge[h]] = f;
    }
  }
  return { vertex, edge };
}

/** The parameter of the point at tau in [0, 1] along face f's own edge j → j+1 (corner j at tau = 0). */
export function faceEdgeParam(cage: Cage, f: number, j: number, tau: number): SurfaceParam {
  const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
  if (n === 4) {
    switch (j) {
      case 0:
        return { face: f, u: tau, v: 0 };
      case 1:
        return { face: f, u: 1, v: tau };
      case 2:
        return { face: f, u: 1 - tau, v: 1 };
      default:
        return { face: f, u: 0, v: 1 - tau };
    }
  }
  // Sub-face j spans vertex j (s = 0) to the edge midpoint (s = 1) along t = 0; sub-face j+1
  // spans vertex j+1 (t = 0) to the same midpoint (t = 1) along s = 0.
  return tau <= 0.5 ? { face: f, k: j, s: 2 * tau, t: 0 } : { face: f, k: (j + 1) % n, s: 0, t: 2 * (1 - tau) };
}

export class DisplacedSurface {
  readonly surface: Surface;
  readonly cage: Cage;
  readonly map: HeightMap;
  readonly options: Required<DisplacementOptions>;
  /** Owner face of each cage vertex (-1 if unused or only on faces without a surface). */
  readonly vertexOwner: Int32Array;
  /** Owner face of each cage edge (topology edge ids). */
  readonly edgeOwner: Int32Array;

  constructor(surface: Surface, map: HeightMap, options: DisplacementOptions) {
    requireUvs(surface.cage);
    if (!Number.isFinite(options.scale) || !Number.isFinite(options.midLevel))
      throw new RangeError('displacement scale and mid-level must be finite');
    this.surface = surface;
    this.cage = surface.cage;
    this.map = map;
    this.options = { wrap: 'repeat', ...options };
    const own = weldOwnerFaces(surface.topology, (f) => surface.hasLimitSurface(f));
    this.vertexOwner = own.vertex;
    this.edgeOwner = own.edge;
  }

  /** Evaluate in the given face's own uvs (no seam rule): the raw per-face displaced surface. */
  evaluateLocal(p: SurfaceParam): DisplacedPoint {
    const f = p.face;
    const n = this.surface.faceSize(f);
    const k = 'k' in p ? p.k : 0;
    const s = 'k' in p ? p.s : p.u,
      t = 'k' in p ? p.t : p.v;
    if (n === 4 && k !== 0) throw new RangeError(`sub-face ${k} does not exist on a quad`);
    const base = this.surface.evaluateSubFace(f, k, s, t);
    const uvp = uvAtSubFace(this.cage, f, k, s, t);
    const hs = sampleHeight(this.map, uvp.uv[0], uvp.uv[1], this.options.wrap);
    const { scale, midLevel } = this.options;
    const h = (hs.value - midLevel) * scale;
    const dhdu = scale * (hs.dU * uvp.dUvdu[0] + hs.dV * uvp.dUvdu[1]);
    const dhdv = scale * (hs.dU * uvp.dUvdv[0] + hs.dV * uvp.dUvdv[1]);
    const N0 = base.N;
    let P: V3, N: V3;
    // The direction to displace along: the limit normal, or where the surface has no tangent
    // plane (a corner of sharp creases, a cone point) the one-sided normal of this face's sector
    // when the evaluator gives one (the GPU displaces a weld vertex along its owner face's, the
    // same); with no normal at all the point stays.
    if (!N0.every(Number.isFinite)) {
      P = [...base.P];
      N = [NaN, NaN, NaN];
    } else {
      P = [base.P[0] + h * N0[0], base.P[1] + h * N0[1], base.P[2] + h * N0[2]];
      const Pu: V3 = [0, 0, 0],
        Pv: V3 = [0, 0, 0];
      for (let c = 0; c < 3; c++) {
        Pu[c] = base.dPdu[c] + dhdu * N0[c];
        Pv[c] = base.dPdv[c] + dhdv * N0[c];
      }
      const x = cross(Pu, Pv);
      const l = Math.hypot(x[0], x[1], x[2]);
      N = l > 0 ? [x[0] / l, x[1] / l, x[2] / l] : [NaN, NaN, NaN];
    }
    const at: SurfaceParam = 'k' in p ? { face: f, k, s, t } : { face: f, u: s, v: t };
    return { P, N, h, dhdu, dhdv, uv: uvp.uv, base, at, normalExact: base.normalDefined && !base.atVertex };
  }

  /** The displaced limit point of cage vertex v, through its owner face. */
  vertex(v: number): DisplacedPoint {
    const f = this.vertexOwner[v];
    if (f < 0) throw new RangeError(`vertex ${v} is on no face with a limit surface`);
    const j = this.cornerOf(f, v);
    return this.evaluateLocal(this.cornerParam(f, j));
  }

  /**
   * The displaced point at x in [0, 1] along the cage edge joining a and b, x measured from
   * the lower vertex index to the higher (the weld's canonical direction), through the owner face.
   */
  edgePoint(a: number, b: number, x: number): DisplacedPoint {
    if (!(x >= 0 && x <= 1)) throw new RangeError(`edge parameter ${x} outside [0, 1]`);
    const e = findEdge(this.surface.topology, a, b);
    if (e < 0) throw new RangeError(`vertices ${a} and ${b} are not joined by an edge`);
    const lo = Math.min(a, b);
    if (x === 0) return this.vertex(lo);
    if (x === 1) return this.vertex(a + b - lo);
    const f = this.edgeOwner[e];
    if (f < 0) throw new RangeError(`edge ${a}-${b} is on no face with a limit surface`);
    const n = this.surface.faceSize(f);
    const start = this.cage.faceOffsets[f];
    let j = 0;
    for (; j < n; j++) {
      const p = this.cage.faceIndices[start + j],
        q = this.cage.faceIndices[start + ((j + 1) % n)];
      if ((p === a && q === b) || (p === b && q === a)) break;
    }
    // tau runs along the face's own edge j → j+1.
    const tau = this.cage.faceIndices[start + j] === lo ? x : 1 - x;
    return this.evaluateLocal(faceEdgeParam(this.cage, f, j, tau));
  }

  /**
   * The displaced point at a face-local parameter WITH the seam rule: points on the face's
   * boundary (cage edges and corners) are redirected to their owner face through the edge's
   * canonical x, so every face sharing the point gets the same result: bit-identical when the
   * faces' parameters give the same x (always for dyadic parameters; otherwise within the
   * rounding of 1 − (1 − x)).
   */
  at(p: SurfaceParam): DisplacedPoint {
    const f = p.face;
    const n = this.surface.faceSize(f);
    const start = this.cage.faceOffsets[f];
    const vid = (j: number): number => this.cage.faceIndices[start + (((j % n) + n) % n)];
    // Locate the point on the face boundary: corner j, or edge j → j+1 at tau.
    let corner = -1,
      edge = -1,
      tau = 0;
    if ('k' in p && n !== 4) {
      const { k, s, t } = p;
      if (s === 0 && t === 0) corner = k;
      else if (t === 0 && s < 1) {
        edge = k;
        tau = s / 2;
      } else if (s === 0 && t < 1) {
        edge = (k + n - 1) % n;
        tau = 1 - t / 2;
      }
    } else {
      const u = 'k' in p ? p.s : p.u,
        v = 'k' in p ? p.t : p.v;
      const c = [
        [0, 0],
        [1, 0],
        [1, 1],
        [0, 1],
      ].findIndex(([cu, cv]) => u === cu && v === cv);
      if (c >= 0) corner = c;
      else if (v === 0) {
        edge = 0;
        tau = u;
      } else if (u === 1) {
        edge = 1;
        tau = v;
      } else if (v === 1) {
        edge = 2;
        tau = 1 - u;
      } else if (u === 0) {
        edge = 3;
        tau = 1 - v;
      }
    }
    if (corner >= 0) return this.vertex(vid(corner));
    if (edge >= 0) {
      // Always through the canonical x, even when this face is the owner: x is the one quantity
      // both sides (and the GPU weld) share, so equal x gives bit-identical results.
      const a = vid(edge),
        b = vid(edge + 1);
      return this.edgePoint(a, b, a < b ? tau : 1 - tau);
    }
    return this.evaluateLocal(p);
  }

  private cornerOf(f: number, v: number): number {
    const start = this.cage.faceOffsets[f],
      n = this.surface.faceSize(f);
    for (let j = 0; j < n; j++) if (this.cage.faceIndices[start + j] === v) return j;
    throw new Error(`vertex ${v} is not on face ${f}`);
  }

  private cornerParam(f: number, j: number): SurfaceParam {
    if (this.surface.faceSize(f) !== 4) return { face: f, k: j, s: 0, t: 0 };
    const [u, v] = [
      [0, 0],
      [1, 0],
      [1, 1],
      [0, 1],
    ][j];
    return { face: f, u, v };
  }
}
