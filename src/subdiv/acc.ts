/**
 * Approximate Catmull-Clark (ACC) patches: the CPU yardstick (f64) of the three schemes of NVIDIA's
 * 2009 instanced-tessellation sample, restated in ../shared/notes/acc-and-instanced.md §0–5:
 *
 *   bezier-acc   Loop & Schaefer 2008: 16-point bicubic geometry patch + two tangent patches
 *                (T_u quadratic×cubic, T_v cubic×quadratic) whose cross product is the shading normal.
 *   gregory-acc  Loop, Schaefer, Ni & Castaño 2009: 20-point Gregory quad, 15-point Gregory triangle
 *                (quartic, our G1 blend rule of notes §3.2, not the sample's inconsistent one).
 *   pm-acc       24-point c-patch (4 quartic sectors) for quads, 19-point Pm triangle (3 sectors + centre).
 *
 * In every scheme a regular quad (4 interior valence-4 corners whose rings are all quads) is the
 * bicubic B-spline converted to Bézier form, exactly (notes §1). The other constructions are the
 * ones of the notes; where the notes leave a choice we take:
 *   - Gregory edge length s_n: nvmesh's table (it produced the sample's data; notes §3.1).
 *   - λ_n, σ_n, cos tables: the closed forms in f64 (not the Pm code's rounded σ table), any valence.
 *   - Diagonal D_i of a ring face: quad = opposite vertex; triangle = centroid (Bezier, Gregory:
 *     the exact CC limit) or edge midpoint (Pm, as nvmesh; its corners next to triangles miss the limit).
 *   - Triangles in a Bezier-ACC cage: the 19-point Pm triangle (as the sample), with c = the exact
 *     limit (centroid rule) and, on every edge shared with a quad, the quad's Loop–Schaefer edge
 *     points M_j as tangent points (kind PM_TRI_LS); on triangle–triangle edges the Pm tangent points
 *     (of the midpoint rule, which the Pm twist terms need: an all-triangle cage is G1).
 *     The sample's plain Pm triangle has a different boundary cubic from the Bezier quad next to it
 *     and cracks (notes §2.5); this one is watertight. Its normal is the Pm triangle's own: across
 *     quad–triangle edges, and triangle–triangle edges ending at a vertex that also has quads (the
 *     M_j are not coplanar with the Pm tangent points), the normal is not continuous (creature:
 *     up to ≈15°; with M_j on every edge it was 34°).
 *
 * Boundaries and creases (the best each scheme offers here; none of the sources' boundary rules
 * could be read, so this is our construction, stated in full and tested):
 *   - Sharpness as the exact reference has it (computeSharpness: boundary edges infinitely sharp, the
 *     cage's `interpolateboundary` mode, 'edge-and-corner' by default: a boundary vertex of one face
 *     is a corner). A vertex with 2 infinitely sharp edges is a CREASE vertex, one with more (or an
 *     infinitely sharp vertex tag) a CORNER; 0 or 1 (a dart) is smooth and built as before.
 *   - Crease and corner vertices are split into SECTORS, the faces between two consecutive sharp
 *     edges; a patch corner reads only its own sector (so the two sides of a crease never mix).
 *   - Every sharp edge's boundary cubic is the cubic B-spline of the crease polygon, in every scheme:
 *     corner point p = (e_a + 4v + e_b)/6 (crease; e_a, e_b its sharp neighbours) or v (corner; OpenSubdiv's
 *     corner rule), edge points (2v + e)/3. Between two crease/corner vertices this IS the exact
 *     Catmull-Clark boundary/crease curve; next to a dart or a smooth vertex it is not (the exact
 *     curve is not a cubic there). Both faces along a crease compute the same curve: watertight.
 *   - Tangents in a sector of k faces: t_j (toward sector edge j = 0..k) = cos(jθ)·A + sin(jθ)·B,
 *     θ = π/k, A = (e_a − e_b)/2 (the boundary cubic's end derivative) and B the exact Catmull-Clark
 *     cross-crease limit tangent (limit.ts creaseCrossMask; k = 2 closed form), scaled so its interior
 *     weights sum to 1; corners: t_j = sin((k−j)θ)·(e_a − v) + sin(jθ)·(e_b − v), θ = π/(2k). The
 *     crease tangent plane is the exact one. Both families satisfy t_{j−1} + t_{j+1} = 2cos θ·t_j,
 *     the relation the three schemes' G1 conditions use with cos(2π/n): each scheme runs unchanged
 *     with the pseudo-valence n' = 2π/θ (2k crease, 4k corner), so it stays G1 across every
 *     smooth edge (checked), and a regular boundary/crease/corner patch (k = 2 / k = 1, quads) is the
 *     exact B-spline (phantom-point) patch, routed to REGULAR as in the interior.
 *   - On sharp edges the schemes' cross terms have no neighbour: Gregory's F on that edge is the
 *     Loop–Schaefer interior point, Pm's ê is (2v + e)/3 (what a reflected phantom face gives).
 *   - Semi-sharp creases and corners (0 < σ < 10) are NOT modelled: those with σ ≥ 1 are built
 *     infinitely sharp, the rest smooth (AccOptions.semiSharp = 'smooth' drops them all), with a
 *     warning; the error table shows what that costs (sharp is the closer of the two everywhere
 *     we measured). A sharp vertex with fewer than 2 sharp edges (a cone
 *     point) is built as a smooth vertex pinned at v (its limit; the tangents are the smooth masks',
 *     the cone is not modelled). A crease sector of one face is built (its corner has no tangent
 *     plane, as in Catmull-Clark; its normal there is degenerate).
 *   - Interior vertices of valence 2 are built with the n = 2 masks and a warning (Catmull-Clark's
 *     own limit there needs refinement, and has no tangent plane at the vertex; Bezier ACC's
 *     tangent-patch normal is degenerate exactly there).
 *   - Faces with more than 4 corners: refused. The sample only has quads and triangles; a split would
 *     change the neighbours' rings and is not the schemes' own construction. Holes: refused.
 *
 * ---------------------------------------------------------------------------------------------------
 * ONE LAYOUT FOR ALL SCHEMES (the GPU build wgsl/acc/build.wgsl writes it, wgsl/acc/surface.wgsl reads it)
 *
 *   patch p = cage face p (every face is a patch).
 *   patches   2 u32 per patch: kind, first control point.
 *   points    control points (xyz; f64×3 here, vec4<f32> on the GPU with w unused), per kind:
 *     REGULAR     16  b_ij at i + 4j (i along u, j along v; corners c0..c3 at (0,0),(3,0),(3,3),(0,3))
 *     BEZIER      32  16 as REGULAR, then U_{a,c} (a = 0, 2; c = 0..3) at 16 + 2a + c, then
 *                     V_{c,a} (a = 0, 2; c = 0..3) at 24 + 2a + c (the sample's 32 float3, §2.4). The middle
 *                     rows U_{1,c} = 3(b_{2c} − b_{1c}), V_{c,1} = 3(b_{c2} − b_{c1}) are recomputed (§2.4).
 *     GREGORY_QUAD 20 per corner k: P_k, E_k⁺, E_k⁻, F_k⁺, F_k⁻ at 5k + 0..4 (⁺ toward corner k+1)
 *     GREGORY_TRI 15  the same with 3 corners
 *     PM_QUAD     24  per sector k (corners k, k+1, centre): c_k, t_k⁺, t_{k+1}⁻, b211, b121, b112 at 6k + 0..5
 *     PM_TRI      19  3 sectors as PM_QUAD, then the centre C at 18
 *     PM_TRI_LS   19  as PM_TRI (Bezier-ACC triangles, see above)
 *
 *   Construction topology (CPU, linear time; read by the GPU build):
 *     corners   2 u32 per patch corner, 4 corners per patch (triangles leave the 4th unused):
 *               cage vertex, rotation r = the index of this face in the vertex's ring
 *     ringOffs  nVerts + 1: vertex v's ring is ringData[ringOffs[v] .. ringOffs[v+1]) = 2n words:
 *               e_0..e_{n−1} (the ring's neighbours), then d_0..d_{n−1}: the vertex of ring face i
 *               opposite v (quad) or TRI_FACE (triangle; its D_i follows the scheme's rule).
 *               n = the number of edges: a boundary vertex has one edge more than faces, and its
 *               last d is NO_FACE (the ring starts at its leading boundary edge).
 *     sectors   1 u32 per patch corner (4 per patch): type | k << 2 | a << 16, type SECTOR_SMOOTH
 *               (the whole cyclic ring), SECTOR_CREASE or SECTOR_CORNER: the corner's sector is ring
 *               edges a .. a+k (mod n) and ring faces a .. a+k−1; see "Boundaries and creases".
 *     Ring convention (notes §0, OpenSubdiv's): face i contains the directed edges v→e_i and
 *     e_{i+1}→v. Seen from a patch corner with rotation r, local e_j = e_{(r+j) mod n}: local e_0 is
 *     the face's next corner, e_1 its previous one, local face 0 the patch itself.
 *
 *   Evaluation parameters: quads (u, v) with c0 = (0,0), c1 = (1,0), c2 = (1,1), c3 = (0,1) (the exact
 *   reference's); triangles (u, v) = (w1, w2), the barycentric weights of face corners 1 and 2
 *   (w0 = 1 − u − v), i.e. the tessellator's weights on a triangle face (prepare.ts fans it as (c0,c1,c2)).
 */
import {
  type Cage,
  type Topology,
  DEFAULT_OPTIONS,
  SHARPNESS_INFINITE,
  buildTopology,
  computeSharpness,
  vertexRing,
} from '../mesh/index.ts';
import { creaseCrossMask } from './limit.ts';

export type AccScheme = 'bezier-acc' | 'gregory-acc' | 'pm-acc';
export const ACC_SCHEMES: readonly AccScheme[] = ['bezier-acc', 'gregory-acc', 'pm-acc'];

export const KIND_REGULAR = 0;
export const KIND_BEZIER = 1;
export const KIND_GREGORY_QUAD = 2;
export const KIND_GREGORY_TRI = 3;
export const KIND_PM_QUAD = 4;
export const KIND_PM_TRI = 5;
export const KIND_PM_TRI_LS = 6;
/** Control points per patch kind. */
export const KIND_POINTS = [16, 32, 20, 15, 24, 19, 19] as const;
export const KIND_NAMES = ['regular', 'bezier', 'gregory-quad', 'gregory-tri', 'pm-quad', 'pm-tri', 'pm-tri-ls'] as const;
/** d_i marker: ring face i is a triangle. */
export const TRI_FACE = 0xffffffff;
/** d_i marker: no ring face i (the gap of a boundary vertex's ring). */
export const NO_FACE = 0xfffffffe;
export const SECTOR_SMOOTH = 0;
export const SECTOR_CREASE = 1;
export const SECTOR_CORNER = 2;
/** An infinitely sharp vertex with fewer than 2 sharp edges (a cone point): the smooth ring, p = v. */
export const SECTOR_CONE = 3;

export class AccError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'AccError';
  }
}

// ------------------------------------------------------------------------------------------------
// Constants (notes §0). Shared with the GPU: the build pass reads them from a table written in f64
// and rounded to f32 once (WGSL's cos is as coarse as 2^-11 on some GPUs).

/** Gregory edge-point length s_n of nvmesh (notes §3.1), n = 3..12; 0.831134 for n ≥ 13. */
const S_TABLE = [0, 0, 0, 0.667791, 1, 1.11268, 1.1284, 1.10289, 1.06062, 1.01262, 0.963949, 0.916926, 0.872541];

export interface ValenceConstants {
  n: number;
  /** cos(2π/n), sin(2π/n). */
  c: number;
  s: number;
  /** Subdominant CC eigenvalue λ_n and the Loop–Schaefer σ_n. */
  lambda: number;
  sigma: number;
  /** Gregory edge length factor s_n. */
  sn: number;
  /** Loop–Schaefer tangent masks α_k, β_k, k = 0..n−1 (t_j = Σ α_{i−j} e_i + β_{i−j} D_i). */
  alpha: number[];
  beta: number[];
  /** cos(2πk/n), k = 0..n−1 (Pm tangent points). */
  cosk: number[];
}

const valenceCache = new Map<number, ValenceConstants>();
export function valenceConstants(n: number): ValenceConstants {
  let k = valenceCache.get(n);
  if (k) return k;
  const c = Math.cos((2 * Math.PI) / n),
    s = Math.sin((2 * Math.PI) / n),
    ch = Math.cos(Math.PI / n);
  const sigma = 1 / Math.sqrt(4 + ch * ch);
  const lambda = (5 + c + ch * Math.sqrt(18 + 2 * c)) / 16;
  const alpha: number[] = [],
    beta: number[] = [],
    cosk: number[] = [];
  for (let i = 0; i < n; i++) {
    cosk.push(Math.cos((2 * Math.PI * i) / n));
    alpha.push(((1 + sigma * ch) / n) * Math.cos((2 * Math.PI * i) / n));
    beta.push((sigma / n) * Math.cos((2 * Math.PI * i + Math.PI) / n));
  }
  const sn = n < S_TABLE.length ? S_TABLE[n] : 0.831134;
  k = { n, c, s, lambda, sigma, sn, alpha, beta, cosk };
  valenceCache.set(n, k);
  return k;
}

/**
 * Constants of a crease or corner sector of k faces (see "Boundaries and creases" above): the
 * pseudo-valence n' = 2π/θ, cos θ, sin θ, the tangent coefficients t_j = ca[j]·A + cb[j]·B
 * (j = 0..k) and, for creases, the cross-tangent mask B over [v, e_0..e_k, d_0..d_{k−1}].
 */
export interface SectorConstants {
  type: number;
  k: number;
  np: number;
  c: number;
  s: number;
  ca: number[];
  cb: number[];
  mask: number[];
}
const sectorCache = new Map<number, SectorConstants>();
export function sectorConstants(type: number, k: number): SectorConstants {
  const key = 2 * k + (type === SECTOR_CORNER ? 1 : 0);
  let r = sectorCache.get(key);
  if (r) return r;
  const corner = type === SECTOR_CORNER;
  const th = corner ? Math.PI / (2 * k) : Math.PI / k;
  const ca: number[] = [],
    cb: number[] = [];
  for (let j = 0; j <= k; j++) {
    ca.push(corner ? Math.sin((k - j) * th) : Math.cos(j * th));
    cb.push(Math.sin(j * th));
  }
  let mask: number[] = [];
  if (!corner) {
    // Exact CC cross-crease tangent (limit.ts; k = 2 its closed form), interior weights summing to 1.
    mask = k === 2 ? [-4, -1, 4, -1, 1, 1] : k >= 3 ? Array.from(creaseCrossMask(k)) : [0, 0, 0, 0];
    let sum = 0;
    for (let i = 2; i <= k; i++) sum += mask[i];
    for (let i = k + 2; i < mask.length; i++) sum += mask[i];
    if (sum) mask = mask.map((w) => w / sum);
  }
  // A crease sector of one face (θ = π: Catmull-Clark has no tangent plane there either) has both
  // edges sharp, so no G1 condition uses it; s = 1 keeps Pm's twist scale 1/(s_0 + s_1) finite.
  r = { type, k, np: (2 * Math.PI) / th, c: Math.cos(th), s: k === 1 && !corner ? 1 : Math.sin(th), ca, cb, mask };
  sectorCache.set(key, r);
  return r;
}

// ------------------------------------------------------------------------------------------------
// Topology

export interface AccTopology {
  scheme: AccScheme;
  nVerts: number;
  nPatches: number;
  /** 2 per patch: kind, first control point. */
  patches: Uint32Array;
  /** 8 per patch: (vertex, rotation) for corners 0..3. */
  corners: Uint32Array;
  ringOffs: Uint32Array;
  ringData: Uint32Array;
  /** 4 per patch: the corner's sector, type | k << 2 | a << 16 (SECTOR_*). */
  sectors: Uint32Array;
  /** Largest crease / corner sector (faces). */
  maxSector: number;
  /** Corners per patch (3 or 4). */
  faceSize: Uint8Array;
  nPoints: number;
  maxValence: number;
  warnings: string[];
}

export interface AccOptions {
  /**
   * Build regular quads with the scheme's own quad construction instead of the B-spline (tests: the
   * schemes' regular exactness, and the guard that the Pm c-patch is NOT exact there, notes §8.3).
   */
  noRegular?: boolean;
  /**
   * Semi-sharp tags (0 < σ < 10): 'sharp' (default) builds those with σ ≥ 1 as infinitely sharp
   * and drops the rest; 'smooth' drops them all. Neither is Catmull-Clark's semi-sharp surface;
   * 'sharp' is the closer one on every cage we measured (RMS position error 2–30× lower, e.g.
   * creased-box 0.41% against 2.3% of the diagonal).
   */
  semiSharp?: 'smooth' | 'sharp';
}

/**
 * Derive everything the construction needs from the cage's connectivity (once per topology, linear
 * time). Throws AccError for faces with more than 4 corners, holes and the sharp configurations
 * listed at the top (creases and boundaries are built).
 */
export function buildAccTopology(cage: Cage, scheme: AccScheme, topology?: Topology, options: AccOptions = {}): AccTopology {
  const topo = topology ?? buildTopology(cage);
  const nV = topo.nVerts,
    nF = topo.nFaces;
  const problems: string[] = [];
  for (let f = 0; f < nF; f++) {
    const n = topo.faceOffsets[f + 1] - topo.faceOffsets[f];
    if (n > 4) problems.push(`face ${f + 1} has ${n} corners (ACC patches are quads and triangles only)`);
  }
  const sharp = computeSharpness(cage, topo, { ...DEFAULT_OPTIONS, ...cage.fileOptions });
  if (cage.holes.length) problems.push(`face ${cage.holes[0] + 1} is a hole (not supported)`);
  else if (sharp.hole.some((h) => h)) problems.push(`boundary mode 'none' makes holes (not supported)`);
  const fail = (list: string[]) =>
    new AccError(`${scheme}: ${list.slice(0, 3).join('; ')}${list.length > 3 ? `; … (${list.length - 3} more)` : ''}`);
  if (problems.length) throw fail(problems);
  const warnings: string[] = [];
  const asSharp = options.semiSharp !== 'smooth';
  const isInf = (x: number) => x >= SHARPNESS_INFINITE || (asSharp && x >= 1);
  let semi = 0;
  for (const x of sharp.edge) if (x > 0 && x < SHARPNESS_INFINITE) semi++;
  for (const x of sharp.vertex) if (x > 0 && x < SHARPNESS_INFINITE) semi++;
  if (semi)
    warnings.push(
      `${semi} semi-sharp crease/corner tags built ${asSharp ? 'infinitely sharp (σ ≥ 1) or smooth' : 'smooth'}: ${scheme} models infinitely sharp creases and corners only`,
    );

  // Rings: e_i and d_i per vertex (a boundary vertex has one more edge than faces), and the rotation
  // of every half-edge (face corner) in its ring.
  const ringOffs = new Uint32Array(nV + 1);
  const ringOf: ({ he: number[]; boundary: boolean } | null)[] = [];
  for (let v = 0; v < nV; v++) {
    const nf = topo.vertHeOffsets[v + 1] - topo.vertHeOffsets[v];
    const ring = nf ? vertexRing(topo, v, topo.vertRingStart[v]) : null;
    if (nf && !ring) throw new AccError(`${scheme}: vertex ${v + 1} is non-manifold`);
    ringOf.push(ring);
    ringOffs[v + 1] = ringOffs[v] + 2 * (nf + (ring?.boundary ? 1 : 0));
  }
  const ringData = new Uint32Array(ringOffs[nV]);
  const heRot = new Int32Array(topo.faceIndices.length).fill(-1);
  /** Per vertex: sector type, and which ring edges are infinitely sharp. */
  const vType = new Uint8Array(nV);
  let valence2 = 0;
  const edgeSharp: boolean[][] = [];
  let maxValence = 0;
  for (let v = 0; v < nV; v++) {
    const ring = ringOf[v];
    edgeSharp.push([]);
    if (!ring) continue;
    const nf = ring.he.length,
      n = nf + (ring.boundary ? 1 : 0);
    const o = ringOffs[v];
    ring.he.forEach((h, i) => {
      heRot[h] = i;
      const f = topo.heFace[h];
      const size = topo.faceOffsets[f + 1] - topo.faceOffsets[f];
      ringData[o + i] = topo.faceIndices[topo.heNext[h]];
      ringData[o + n + i] = size === 4 ? topo.faceIndices[topo.heNext[topo.heNext[h]]] : TRI_FACE;
      edgeSharp[v].push(isInf(sharp.edge[topo.heEdge[h]]));
    });
    if (ring.boundary) {
      const h = topo.hePrev[ring.he[nf - 1]];
      ringData[o + nf] = topo.faceIndices[h];
      ringData[o + 2 * n - 1] = NO_FACE;
      edgeSharp[v].push(isInf(sharp.edge[topo.heEdge[h]]));
    }
    const nInf = edgeSharp[v].filter((x) => x).length;
    const type = isInf(sharp.vertex[v]) || nInf > 2 ? (nInf < 2 ? SECTOR_CONE : SECTOR_CORNER) : nInf === 2 ? SECTOR_CREASE : SECTOR_SMOOTH;
    const smooth = type === SECTOR_SMOOTH || type === SECTOR_CONE;
    if (smooth && n < 2) problems.push(`vertex ${v + 1} has valence ${n} (at least 2 needed)`);
    if (smooth && n === 2) valence2++;
    vType[v] = type;
    if (smooth) maxValence = Math.max(maxValence, n);
  }
  // Per face corner: its sector (start edge a, faces k) and whether it is a regular B-spline corner.
  const patches = new Uint32Array(2 * nF);
  const corners = new Uint32Array(8 * nF);
  const sectors = new Uint32Array(4 * nF);
  const faceSize = new Uint8Array(nF);
  let maxSector = 0;
  let nPoints = 0;
  for (let f = 0; f < nF; f++) {
    const a0 = topo.faceOffsets[f],
      m = topo.faceOffsets[f + 1] - a0;
    faceSize[f] = m;
    let regular = m === 4 && !options.noRegular;
    for (let c = 0; c < m; c++) {
      const v = topo.faceIndices[a0 + c],
        r = heRot[a0 + c];
      corners[8 * f + 2 * c] = v;
      corners[8 * f + 2 * c + 1] = r;
      const o = ringOffs[v],
        n = (ringOffs[v + 1] - o) / 2;
      const quadFace = (i: number) => ringData[o + n + (i % n)] !== TRI_FACE;
      const type = vType[v];
      if (type === SECTOR_SMOOTH || type === SECTOR_CONE) {
        sectors[4 * f + c] = type;
        let ok = type === SECTOR_SMOOTH && n === 4 && !edgeSharp[v].some((x) => x);
        for (let i = 0; ok && i < n; i++) if (!quadFace(i)) ok = false;
        if (!ok) regular = false;
        continue;
      }
      // Sector: back from edge r to a sharp edge, forward from edge r+1 to the next one.
      let a = r;
      while (!edgeSharp[v][a]) a = (a + n - 1) % n;
      let k = 1;
      while (!edgeSharp[v][(a + k) % n]) k++;
      sectors[4 * f + c] = type | (k << 2) | (a << 16);
      maxSector = Math.max(maxSector, k);
      let ok = type === SECTOR_CREASE ? k === 2 : k === 1;
      for (let i = 0; ok && i < k; i++) if (!quadFace(a + i)) ok = false;
      if (!ok) regular = false;
    }
    const kind = regular
      ? KIND_REGULAR
      : m === 4
        ? scheme === 'bezier-acc'
          ? KIND_BEZIER
          : scheme === 'gregory-acc'
            ? KIND_GREGORY_QUAD
            : KIND_PM_QUAD
        : scheme === 'bezier-acc'
          ? KIND_PM_TRI_LS
          : scheme === 'gregory-acc'
            ? KIND_GREGORY_TRI
            : KIND_PM_TRI;
    patches[2 * f] = kind;
    patches[2 * f + 1] = nPoints;
    nPoints += KIND_POINTS[kind];
  }
  if (problems.length) throw fail(problems);
  if (valence2)
    warnings.push(
      `${valence2} interior vertices of valence 2: built with the n = 2 masks (not Catmull-Clark's limit there, which needs refinement; no tangent plane at the vertex, as in Catmull-Clark)`,
    );
  return {
    scheme,
    nVerts: nV,
    nPatches: nF,
    patches,
    corners,
    ringOffs,
    ringData,
    sectors,
    maxSector,
    faceSize,
    nPoints,
    maxValence,
    warnings,
  };
}

// ------------------------------------------------------------------------------------------------
// Construction (the same steps as wgsl/acc/build.wgsl, one patch at a time)

export type V3 = [number, number, number];
const add = (a: V3, b: V3): V3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const subv = (a: V3, b: V3): V3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const mul = (a: V3, s: number): V3 => [a[0] * s, a[1] * s, a[2] * s];
/** Σ w_i·p_i. */
const comb = (...terms: [number, V3][]): V3 => {
  const r: V3 = [0, 0, 0];
  for (const [w, p] of terms) {
    r[0] += w * p[0];
    r[1] += w * p[1];
    r[2] += w * p[2];
  }
  return r;
};
export const cross3 = (a: V3, b: V3): V3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
/** As the GPU's accNormal: a zero vector stays zero (a degenerate corner, where CC has no normal either). */
const normalize3 = (a: V3): V3 => {
  const l = Math.hypot(a[0], a[1], a[2]);
  return l > 0 ? mul(a, 1 / l) : [0, 0, 0];
};

/** Everything a patch needs from one of its corners (notes §0, §2.1–2.2, §3.1, §4.1). */
export interface CornerInfo {
  n: number;
  k: ValenceConstants;
  /** The vertex itself. */
  v: V3;
  /** Limit position (with the scheme's triangle rule for D). */
  p: V3;
  /** Loop–Schaefer mask tangents toward local e_0 (next corner) and e_1 (previous corner). */
  t0: V3;
  t1: V3;
  /** Loop–Schaefer interior point of the patch's own face, and edge points toward e_0 and e_1. */
  f0: V3;
  m0: V3;
  m1: V3;
  /** Gregory transversals for the edges toward e_0 (r⁺) and e_1 (r⁻), pointing into the face. */
  rp: V3;
  rm: V3;
  /** Pm valence-4-rule edge points toward e_0, e_1, and Pm tangent points t^(0), t^(1). */
  eh0: V3;
  eh1: V3;
  tp0: V3;
  tp1: V3;
  /** The face across the edge toward e_0 (local ring face n−1) / toward e_1 (ring face 1) is a quad. */
  quadNext: boolean;
  quadPrev: boolean;
  /** The edge toward e_0 / e_1 is a sharp edge bounding the corner's sector (crease, boundary). */
  sharpNext: boolean;
  sharpPrev: boolean;
}

/**
 * Corner info of vertex `vert` seen from a face at ring rotation `rot`. `midpointRule`: a triangle's
 * diagonal D is the midpoint of its other two vertices (Pm, nvmesh) instead of its centroid.
 */
export function cornerInfo(T: AccTopology, P: ArrayLike<number>, vert: number, rot: number, midpointRule: boolean, sector = 0): CornerInfo {
  const type = sector & 3;
  if (type === SECTOR_CREASE || type === SECTOR_CORNER) return sectorCornerInfo(T, P, vert, rot, midpointRule, sector);
  const o = T.ringOffs[vert],
    n = (T.ringOffs[vert + 1] - o) / 2;
  const pt = (i: number): V3 => [P[3 * i], P[3 * i + 1], P[3 * i + 2]];
  const v = pt(vert);
  const e: V3[] = [],
    D: V3[] = [];
  const isQuad = (j: number) => T.ringData[o + n + ((rot + j) % n)] !== TRI_FACE;
  for (let j = 0; j < n; j++) e.push(pt(T.ringData[o + ((rot + j) % n)]));
  for (let j = 0; j < n; j++) {
    const d = T.ringData[o + n + ((rot + j) % n)];
    const a = e[j],
      b = e[(j + 1) % n];
    D.push(d !== TRI_FACE ? pt(d) : midpointRule ? comb([0.5, a], [0.5, b]) : comb([1 / 3, v], [1 / 3, a], [1 / 3, b]));
  }
  const k = valenceConstants(n);
  // Limit position p = (n²v + 4Σe + ΣD) / (n(n+5)).
  let se: V3 = [0, 0, 0],
    sd: V3 = [0, 0, 0];
  for (let j = 0; j < n; j++) {
    se = add(se, e[j]);
    sd = add(sd, D[j]);
  }
  // A cone point (SECTOR_CONE) stays where it is, as in Catmull-Clark.
  const p = type === SECTOR_CONE ? v : mul(add(add(mul(v, n * n), mul(se, 4)), sd), 1 / (n * (n + 5)));
  const tan = (jj: number): V3 => {
    const r: V3 = [0, 0, 0];
    for (let i = 0; i < n; i++) {
      const m = (((i - jj) % n) + n) % n;
      for (let c = 0; c < 3; c++) r[c] += k.alpha[m] * e[i][c] + k.beta[m] * D[i][c];
    }
    return r;
  };
  const f = (i: number): V3 => {
    const j = ((i % n) + n) % n;
    return mul(add(add(mul(v, n), mul(add(e[j], e[(j + 1) % n]), 2)), D[j]), 1 / (n + 5));
  };
  const fm = f(-1),
    f0 = f(0),
    f1 = f(1);
  const eh = (i: number): V3 => {
    const j = ((i % n) + n) % n,
      jm = (j + n - 1) % n,
      jp = (j + 1) % n;
    return comb([8 / 18, v], [4 / 18, e[j]], [2 / 18, e[jm]], [2 / 18, e[jp]], [1 / 18, D[jm]], [1 / 18, D[j]]);
  };
  // Pm tangent points t^(j) = p + (1/(nλ)) Σ_i cos(2π(j−i)/n) ê_i (Σ cos = 0: affine).
  const ehs: V3[] = [];
  for (let i = 0; i < n; i++) ehs.push(eh(i));
  const tpm = (jj: number): V3 => {
    let r: V3 = [0, 0, 0];
    for (let i = 0; i < n; i++) r = add(r, mul(ehs[i], k.cosk[(((jj - i) % n) + n) % n]));
    return add(p, mul(r, 1 / (n * k.lambda)));
  };
  return {
    n,
    k,
    v,
    p,
    t0: tan(0),
    t1: tan(1),
    f0,
    m0: mul(add(fm, f0), 0.5),
    m1: mul(add(f0, f1), 0.5),
    rp: add(mul(subv(e[1], e[n - 1]), 1 / 3), mul(subv(D[0], D[n - 1]), 1 / 6)),
    rm: add(mul(subv(e[0], e[2 % n]), 1 / 3), mul(subv(D[0], D[1]), 1 / 6)),
    eh0: ehs[0],
    eh1: ehs[1],
    tp0: tpm(0),
    tp1: tpm(1),
    quadNext: isQuad(n - 1),
    quadPrev: isQuad(1),
    sharpNext: false,
    sharpPrev: false,
  };
}

/**
 * Corner info of a crease or corner vertex, from its sector only ("Boundaries and creases" above):
 * the same quantities as cornerInfo, with the sector's tangent family, the pseudo-valence n' in the
 * Loop–Schaefer interior points and the B-spline boundary rules on the sector's sharp edges.
 */
function sectorCornerInfo(
  T: AccTopology,
  P: ArrayLike<number>,
  vert: number,
  rot: number,
  midpointRule: boolean,
  sector: number,
): CornerInfo {
  const o = T.ringOffs[vert],
    n = (T.ringOffs[vert + 1] - o) / 2;
  const type = sector & 3,
    k = (sector >>> 2) & 0x3fff,
    a = sector >>> 16;
  const K = sectorConstants(type, k);
  const pt = (i: number): V3 => [P[3 * i], P[3 * i + 1], P[3 * i + 2]];
  const v = pt(vert);
  const e: V3[] = [],
    D: V3[] = [],
    quad: boolean[] = [];
  for (let j = 0; j <= k; j++) e.push(pt(T.ringData[o + ((a + j) % n)]));
  for (let j = 0; j < k; j++) {
    const d = T.ringData[o + n + ((a + j) % n)];
    quad.push(d !== TRI_FACE);
    D.push(d !== TRI_FACE ? pt(d) : midpointRule ? comb([0.5, e[j]], [0.5, e[j + 1]]) : comb([1 / 3, v], [1 / 3, e[j]], [1 / 3, e[j + 1]]));
  }
  const i0 = (rot - a + n) % n; // this face in the sector: between sector edges i0 and i0 + 1
  let p: V3, A: V3, B: V3;
  if (type === SECTOR_CREASE) {
    p = comb([4 / 6, v], [1 / 6, e[0]], [1 / 6, e[k]]);
    A = mul(subv(e[0], e[k]), 0.5);
    B = [0, 0, 0];
    for (let j = 0; j <= k; j++) B = add(B, mul(subv(e[j], v), K.mask[1 + j]));
    for (let j = 0; j < k; j++) B = add(B, mul(subv(D[j], v), K.mask[k + 2 + j]));
  } else {
    p = v;
    A = subv(e[0], v);
    B = subv(e[k], v);
  }
  const t = (j: number): V3 => comb([K.ca[j], A], [K.cb[j], B]);
  const f = (i: number): V3 => mul(add(add(mul(v, K.np), mul(add(e[i], e[i + 1]), 2)), D[i]), 1 / (K.np + 5));
  const edgePt = (j: number): V3 => comb([2 / 3, v], [1 / 3, e[j]]);
  const eh = (j: number): V3 =>
    j === 0 || j === k
      ? edgePt(j)
      : comb([8 / 18, v], [4 / 18, e[j]], [2 / 18, e[j - 1]], [2 / 18, e[j + 1]], [1 / 18, D[j - 1]], [1 / 18, D[j]]);
  const zero: V3 = [0, 0, 0];
  const first = i0 === 0,
    last = i0 + 1 === k;
  const f0 = f(i0);
  const t0 = t(i0),
    t1 = t(i0 + 1);
  return {
    n: K.np,
    k: { n: K.np, c: K.c, s: K.s, lambda: NaN, sigma: NaN, sn: 1, alpha: [], beta: [], cosk: [] },
    v,
    p,
    t0,
    t1,
    f0,
    m0: first ? edgePt(0) : mul(add(f(i0 - 1), f0), 0.5),
    m1: last ? edgePt(k) : mul(add(f0, f(i0 + 1)), 0.5),
    rp: first ? zero : add(mul(subv(e[i0 + 1], e[i0 - 1]), 1 / 3), mul(subv(D[i0], D[i0 - 1]), 1 / 6)),
    rm: last ? zero : add(mul(subv(e[i0], e[i0 + 2]), 1 / 3), mul(subv(D[i0], D[i0 + 1]), 1 / 6)),
    eh0: eh(i0),
    eh1: eh(i0 + 1),
    tp0: add(p, mul(t0, 1 / 3)),
    tp1: add(p, mul(t1, 1 / 3)),
    quadNext: !first && quad[i0 - 1],
    quadPrev: !last && quad[i0 + 1],
    sharpNext: first,
    sharpPrev: last,
  };
}

/** Grid position of quad corner k and its unit steps toward the next and previous corner. */
const QUAD_GRID: { c: [number, number]; nx: [number, number]; pv: [number, number] }[] = [
  { c: [0, 0], nx: [1, 0], pv: [0, 1] },
  { c: [3, 0], nx: [0, 1], pv: [-1, 0] },
  { c: [3, 3], nx: [-1, 0], pv: [0, -1] },
  { c: [0, 3], nx: [0, -1], pv: [1, 0] },
];

/** The 16 geometry points (b_ij at i + 4j) of a quad from its corners: Loop–Schaefer, = B-spline if regular. */
function geometryPatch(C: CornerInfo[]): V3[] {
  const b: V3[] = new Array(16);
  for (let k = 0; k < 4; k++) {
    const g = QUAD_GRID[k],
      ci = C[k];
    const at = (di: number, dj: number): number => g.c[0] + di + 4 * (g.c[1] + dj);
    b[at(0, 0)] = ci.p;
    b[at(g.nx[0], g.nx[1])] = ci.m0;
    b[at(g.pv[0], g.pv[1])] = ci.m1;
    b[at(g.nx[0] + g.pv[0], g.nx[1] + g.pv[1])] = ci.f0;
  }
  return b;
}

/**
 * Tangent-patch edge rows (notes §2.3): the cross-derivative coefficients x1, x2 pointing into the
 * face along the edge from corner A to corner B (a0, a2 the along-edge mask tangents, h1, h2 the
 * edge's inner points, g1, g2 the interior points next to them).
 */
function crossRow(cA: number, cB: number, a0: V3, a2: V3, h1: V3, h2: V3, g1: V3, g2: V3): [V3, V3] {
  const a1 = mul(subv(h2, h1), 3);
  const x1 = add(mul(subv(g1, h1), 3), mul(subv(mul(a1, 2 * cA), mul(a0, cB)), 1 / 3));
  const x2 = add(mul(subv(g2, h2), 3), mul(subv(mul(a2, cA), mul(a1, 2 * cB)), 1 / 3));
  return [x1, x2];
}

function bezierPatch(C: CornerInfo[]): V3[] {
  const b = geometryPatch(C);
  const B = (i: number, j: number): V3 => b[i + 4 * j];
  const c = C.map((x) => x.k.c);
  // ∂u, ∂v at the corners (notes §2.2 table).
  const du = [C[0].t0, mul(C[1].t1, -1), mul(C[2].t0, -1), C[3].t1];
  const dv = [C[0].t1, C[1].t0, mul(C[2].t1, -1), mul(C[3].t0, -1)];
  const U: V3[] = new Array(8),
    V: V3[] = new Array(8); // U[a/2·4 + c], V[a/2·4 + c]
  U[0] = du[0];
  U[4] = du[1];
  U[7] = du[2];
  U[3] = du[3];
  V[0] = dv[0];
  V[3] = dv[1];
  V[7] = dv[2];
  V[4] = dv[3];
  // Edge u = 0: A = P0, B = P3.
  let [x1, x2] = crossRow(c[0], c[3], C[0].t1, mul(C[3].t0, -1), B(0, 1), B(0, 2), B(1, 1), B(1, 2));
  U[1] = x1;
  U[2] = x2;
  // Edge u = 1: A = P1, B = P2, into the face is −u.
  [x1, x2] = crossRow(c[1], c[2], C[1].t0, mul(C[2].t1, -1), B(3, 1), B(3, 2), B(2, 1), B(2, 2));
  U[5] = mul(x1, -1);
  U[6] = mul(x2, -1);
  // Edge v = 0: A = P0, B = P1.
  [x1, x2] = crossRow(c[0], c[1], C[0].t0, mul(C[1].t1, -1), B(1, 0), B(2, 0), B(1, 1), B(2, 1));
  V[1] = x1;
  V[2] = x2;
  // Edge v = 1: A = P3, B = P2, into the face is −v.
  [x1, x2] = crossRow(c[3], c[2], C[3].t1, mul(C[2].t0, -1), B(1, 3), B(2, 3), B(1, 2), B(2, 2));
  V[5] = mul(x1, -1);
  V[6] = mul(x2, -1);
  return [...b, ...U, ...V];
}

/** Gregory quad (m = 4, denominators 3) or triangle (m = 3, denominators 4): notes §3.1–3.2. */
function gregoryPatch(C: CornerInfo[]): V3[] {
  const m = C.length,
    den = m === 4 ? 3 : 4;
  const E = C.map((ci) => ({ p: add(ci.p, mul(ci.t0, ci.k.sn / 3)), m: add(ci.p, mul(ci.t1, ci.k.sn / 3)) }));
  const out: V3[] = [];
  for (let k = 0; k < m; k++) {
    const kn = (k + 1) % m,
      kp = (k + m - 1) % m,
      ck = C[k].k.c;
    // On a sharp (sector-bounding) edge there is no neighbour to be G1 with: the Loop–Schaefer
    // interior point on quads (the B-spline's on a regular boundary); triangles drop the transversal.
    const Fp =
      C[k].sharpNext && m === 4
        ? C[k].f0
        : mul(comb([C[kn].k.c, C[k].p], [den - 2 * ck - C[kn].k.c, E[k].p], [2 * ck, E[kn].m], [1, C[k].rp]), 1 / den);
    const Fm =
      C[k].sharpPrev && m === 4
        ? C[k].f0
        : mul(comb([C[kp].k.c, C[k].p], [den - 2 * ck - C[kp].k.c, E[k].m], [2 * ck, E[kp].p], [1, C[k].rm]), 1 / den);
    out.push(C[k].p, E[k].p, E[k].m, Fp, Fm);
  }
  return out;
}

/**
 * Pm patch, quad c-patch (m = 4) or triangle (m = 3), notes §4.1, §4.3. `loopSchaefer`: corner and
 * tangent points are the Loop–Schaefer limit and edge points (Bezier-ACC triangles).
 */
function pmPatch(C: CornerInfo[], face: V3[], loopSchaefer: boolean): V3[] {
  const m = C.length,
    mu = m === 4 ? 1 : 1.5;
  const cc = C.map((ci) => ci.p);
  // Bezier-ACC triangles: the Loop–Schaefer edge points on edges shared with a (Bezier) quad, so the
  // boundary curves agree; the Pm tangent points on triangle–triangle edges (coplanar round a vertex).
  const tp = C.map((ci) => (loopSchaefer && ci.quadNext ? ci.m0 : ci.tp0)),
    tm = C.map((ci) => (loopSchaefer && ci.quadPrev ? ci.m1 : ci.tp1));
  const phi = face.map((P, k) =>
    m === 4
      ? comb([4 / 9, P], [2 / 9, face[(k + 1) % 4]], [2 / 9, face[(k + 3) % 4]], [1 / 9, face[(k + 2) % 4]])
      : comb([4 / 9, P], [2.5 / 9, face[(k + 1) % 3]], [2.5 / 9, face[(k + 2) % 3]]),
  );
  const b211: V3[] = [],
    b121: V3[] = [];
  for (let k = 0; k < m; k++) {
    const k1 = (k + 1) % m,
      K0 = C[k].k,
      K1 = C[k1].k;
    const U0 = subv(tp[k], cc[k]),
      U1 = subv(tm[k1], tp[k]),
      U2 = subv(cc[k1], tm[k1]);
    const S = 4 * mu * (K0.s + K1.s);
    b211.push(
      comb(
        [0.25, cc[k]],
        [0.75, tp[k]],
        [(1 + K0.c) / (4 * mu), U1],
        [(2 * mu - 1 - K1.c) / (8 * mu), U0],
        [3 / S, subv(phi[k], C[k].eh0)],
      ),
    );
    b121.push(
      comb(
        [0.25, cc[k1]],
        [0.75, tm[k1]],
        [-(1 + K1.c) / (4 * mu), U1],
        [-(2 * mu - 1 - K0.c) / (8 * mu), U2],
        [3 / S, subv(phi[k1], C[k1].eh1)],
      ),
    );
  }
  let centre: V3 = [0, 0, 0];
  for (let k = 0; k < m; k++) {
    const k1 = (k + 1) % m;
    centre = add(centre, comb([m === 4 ? 1 : 2, cc[k]], [9, phi[k]], [3, C[k].eh0], [3, C[k1].eh1]));
  }
  centre = mul(centre, 1 / (m === 4 ? 64 : 51));
  const b112: V3[] = [];
  for (let k = 0; k < m; k++) {
    if (m === 4) {
      const w = [3, 1, -1, -3];
      let s: V3 = [0, 0, 0];
      for (let j = 0; j < 4; j++) s = add(s, mul(subv(b211[(k + j) % 4], b121[(k + j + 1) % 4]), w[j]));
      b112.push(add(centre, mul(s, 1 / 16)));
    } else {
      const o = (k + 2) % 3;
      b112.push(comb([1.5, centre], [-1 / 12, cc[o]], [-1 / 24, tp[o]], [-1 / 24, tm[o]], [-1 / 6, b211[o]], [-1 / 6, b121[(k + 1) % 3]]));
    }
  }
  const out: V3[] = [];
  for (let k = 0; k < m; k++) out.push(cc[k], tp[k], tm[(k + 1) % m], b211[k], b121[k], b112[k]);
  if (m === 3) out.push(centre);
  return out;
}

/** The control points of patch f (xyz, KIND_POINTS[kind] of them) from cage positions P. */
export function buildPatch(T: AccTopology, P: ArrayLike<number>, f: number): V3[] {
  const kind = T.patches[2 * f],
    m = T.faceSize[f];
  const mid = kind === KIND_PM_QUAD || kind === KIND_PM_TRI;
  const C: CornerInfo[] = [];
  const face: V3[] = [];
  for (let k = 0; k < m; k++) {
    const v = T.corners[8 * f + 2 * k],
      rot = T.corners[8 * f + 2 * k + 1];
    const sec = T.sectors[4 * f + k];
    const ci = cornerInfo(T, P, v, rot, mid, sec);
    if (kind === KIND_PM_TRI_LS) {
      // Exact corner and Loop–Schaefer points (centroid rule), but the Pm edge and tangent points
      // of the midpoint rule: its twist terms 3(φ − ê)/S cancel across triangle–triangle edges
      // only with the ê that match the Pm face points φ (with centroid-rule ê: 4.6° kinks).
      const cm = cornerInfo(T, P, v, rot, true, sec);
      ci.eh0 = cm.eh0;
      ci.eh1 = cm.eh1;
      ci.tp0 = add(ci.p, subv(cm.tp0, cm.p));
      ci.tp1 = add(ci.p, subv(cm.tp1, cm.p));
    }
    C.push(ci);
    face.push([P[3 * v], P[3 * v + 1], P[3 * v + 2]]);
  }
  switch (kind) {
    case KIND_REGULAR:
      return geometryPatch(C);
    case KIND_BEZIER:
      return bezierPatch(C);
    case KIND_GREGORY_QUAD:
    case KIND_GREGORY_TRI:
      return gregoryPatch(C);
    case KIND_PM_QUAD:
    case KIND_PM_TRI:
      return pmPatch(C, face, false);
    case KIND_PM_TRI_LS:
      return pmPatch(C, face, true);
    default:
      throw new AccError(`unknown patch kind ${kind}`);
  }
}

/** All control points (3 f64 per point, in the layout above). */
export function buildAccPoints(T: AccTopology, P: ArrayLike<number>): Float64Array {
  const out = new Float64Array(3 * T.nPoints);
  for (let f = 0; f < T.nPatches; f++) {
    const pts = buildPatch(T, P, f);
    const o = T.patches[2 * f + 1];
    pts.forEach((p, i) => out.set(p, 3 * (o + i)));
  }
  return out;
}

// ------------------------------------------------------------------------------------------------
// Evaluation

export interface AccPoint {
  P: V3;
  /** Unit shading normal (outward for counter-clockwise faces). */
  N: V3;
}

const bern3 = (t: number): number[] => {
  const s = 1 - t;
  return [s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t];
};
const bern3d = (t: number): number[] => {
  const s = 1 - t;
  return [-3 * s * s, 3 * s * s - 6 * s * t, 6 * s * t - 3 * t * t, 3 * t * t];
};
const bern2 = (t: number): number[] => {
  const s = 1 - t;
  return [s * s, 2 * s * t, t * t];
};

/** Bicubic b_ij (i + 4j): position and the two partial derivatives. */
export function evalBicubic(b: V3[], u: number, v: number): { P: V3; Pu: V3; Pv: V3 } {
  const bu = bern3(u),
    bv = bern3(v),
    du = bern3d(u),
    dv = bern3d(v);
  const P: V3 = [0, 0, 0],
    Pu: V3 = [0, 0, 0],
    Pv: V3 = [0, 0, 0];
  for (let j = 0; j < 4; j++)
    for (let i = 0; i < 4; i++) {
      const q = b[i + 4 * j];
      for (let c = 0; c < 3; c++) {
        P[c] += bu[i] * bv[j] * q[c];
        Pu[c] += du[i] * bv[j] * q[c];
        Pv[c] += bu[i] * dv[j] * q[c];
      }
    }
  return { P, Pu, Pv };
}

/** Tangent patches of a BEZIER patch (32 points): T_u and T_v at (u, v). */
export function evalTangentPatches(q: V3[], u: number, v: number): { Tu: V3; Tv: V3 } {
  const b = (i: number, j: number): V3 => q[i + 4 * j];
  const Ua = (a: number, c: number): V3 => (a === 1 ? mul(subv(b(2, c), b(1, c)), 3) : q[16 + 2 * a + c]);
  const Va = (c: number, a: number): V3 => (a === 1 ? mul(subv(b(c, 2), b(c, 1)), 3) : q[24 + 2 * a + c]);
  const b2u = bern2(u),
    b2v = bern2(v),
    b3u = bern3(u),
    b3v = bern3(v);
  const Tu: V3 = [0, 0, 0],
    Tv: V3 = [0, 0, 0];
  for (let a = 0; a < 3; a++)
    for (let c = 0; c < 4; c++) {
      const x = Ua(a, c),
        y = Va(c, a);
      for (let d = 0; d < 3; d++) {
        Tu[d] += b2u[a] * b3v[c] * x[d];
        Tv[d] += b3u[c] * b2v[a] * y[d];
      }
    }
  return { Tu, Tv };
}

/** Blended 16-point Bézier of a GREGORY_QUAD (20 points) at (u, v) (notes §3.1). */
export function gregoryQuadBezier(q: V3[], u: number, v: number): V3[] {
  const G = (k: number, i: number): V3 => q[5 * k + i]; // i: 0 P, 1 E⁺, 2 E⁻, 3 F⁺, 4 F⁻
  const blend = (F1: V3, w1: number, F2: V3, w2: number): V3 => (w1 + w2 > 0 ? mul(add(mul(F1, w1), mul(F2, w2)), 1 / (w1 + w2)) : F1);
  const b: V3[] = new Array(16);
  const set = (i: number, j: number, p: V3) => {
    b[i + 4 * j] = p;
  };
  set(0, 0, G(0, 0));
  set(1, 0, G(0, 1));
  set(0, 1, G(0, 2));
  set(3, 0, G(1, 0));
  set(2, 0, G(1, 2));
  set(3, 1, G(1, 1));
  set(3, 3, G(2, 0));
  set(2, 3, G(2, 1));
  set(3, 2, G(2, 2));
  set(0, 3, G(3, 0));
  set(0, 2, G(3, 1));
  set(1, 3, G(3, 2));
  set(1, 1, blend(G(0, 3), u, G(0, 4), v));
  set(2, 1, blend(G(1, 3), v, G(1, 4), 1 - u));
  set(2, 2, blend(G(2, 3), 1 - u, G(2, 4), 1 - v));
  set(1, 2, blend(G(3, 3), 1 - v, G(3, 4), u));
  return b;
}

/** Index of quartic triangle coefficient Q_{abc} (a + b + c = 4) in a 15-array: by c, then b. */
export const qi = (_a: number, b: number, c: number): number => c * 5 - (c * (c - 1)) / 2 + b;

/**
 * Quartic Bézier triangle by de Casteljau down to three points R_a, R_b, R_c: the position is
 * a·R_a + b·R_b + c·R_c and the homogeneous partials are ∂/∂a = 4R_a, ∂/∂b = 4R_b, ∂/∂c = 4R_c.
 */
export function evalQuartic(Q: V3[], a: number, b: number, c: number): { P: V3; Da: V3; Db: V3; Dc: V3 } {
  let cur = Q,
    deg = 4;
  while (deg > 1) {
    const next: V3[] = [];
    const d = deg - 1;
    const idx = (bb: number, cc: number, dd: number) => cc * (dd + 1) - (cc * (cc - 1)) / 2 + bb;
    for (let cc = 0; cc <= d; cc++)
      for (let bb = 0; bb + cc <= d; bb++) {
        next[idx(bb, cc, d)] = comb([a, cur[idx(bb, cc, deg)]], [b, cur[idx(bb + 1, cc, deg)]], [c, cur[idx(bb, cc + 1, deg)]]);
      }
    cur = next;
    deg = d;
  }
  // Degree 1: index (b=0,c=0) → R_a = 0, (1,0) → R_b = 1, (0,1) → R_c = 2.
  const Ra = cur[0],
    Rb = cur[1],
    Rc = cur[2];
  return { P: comb([a, Ra], [b, Rb], [c, Rc]), Da: mul(Ra, 4), Db: mul(Rb, 4), Dc: mul(Rc, 4) };
}

/** Quartic coefficients of a GREGORY_TRI (15 points) at barycentrics λ (notes §3.2). */
export function gregoryTriQuartic(q: V3[], l: [number, number, number]): V3[] {
  const G = (k: number, i: number): V3 => q[5 * k + i];
  const Q: V3[] = new Array(15);
  const set = (a: number, b: number, c: number, p: V3) => {
    Q[qi(a, b, c)] = p;
  };
  // Quartic index (a, b, c) ↔ powers of λ0, λ1, λ2; corner k = 4 on slot k.
  const slot = (k: number, x: number, y: number): [number, number, number] => {
    // x on corner k, y on corner k+1, rest on corner k+2.
    const r: [number, number, number] = [0, 0, 0];
    r[k] = x;
    r[(k + 1) % 3] = y;
    r[(k + 2) % 3] = 4 - x - y;
    return r;
  };
  const blend = (F1: V3, w1: number, F2: V3, w2: number): V3 => (w1 + w2 > 0 ? mul(add(mul(F1, w1), mul(F2, w2)), 1 / (w1 + w2)) : F1);
  for (let k = 0; k < 3; k++) {
    const k1 = (k + 1) % 3,
      k2 = (k + 2) % 3;
    const Pk = G(k, 0),
      Ep = G(k, 1),
      Em1 = G(k1, 2);
    set(...slot(k, 4, 0), Pk);
    set(...slot(k, 3, 1), comb([0.25, Pk], [0.75, Ep]));
    set(...slot(k, 2, 2), comb([0.5, Ep], [0.5, Em1]));
    set(...slot(k, 1, 3), comb([0.75, Em1], [0.25, G(k1, 0)]));
    // Interior point next to corner k: F⁺ (edge toward k+1) weighted by λ_{k+1}, F⁻ by λ_{k−1}.
    set(...slot(k, 2, 1), blend(G(k, 3), l[k1], G(k, 4), l[k2]));
  }
  return Q;
}

/** Quartic coefficients of sector k of a Pm patch (m = 4 c-patch, m = 3 triangle): notes §4.2–4.3. */
export function pmSectorQuartic(q: V3[], m: number, k: number): V3[] {
  const S = (j: number, i: number): V3 => q[6 * (((j % m) + m) % m) + i]; // 0 c, 1 t⁺, 2 t⁻(next corner), 3 b211, 4 b121, 5 b112
  const Q: V3[] = new Array(15);
  const set = (a: number, b: number, c: number, p: V3) => {
    Q[qi(a, b, c)] = p;
  };
  const ck = S(k, 0),
    tk = S(k, 1),
    tk1 = S(k, 2),
    ck1 = S(k + 1, 0);
  set(4, 0, 0, ck);
  set(3, 1, 0, comb([0.25, ck], [0.75, tk]));
  set(2, 2, 0, comb([0.5, tk], [0.5, tk1]));
  set(1, 3, 0, comb([0.75, tk1], [0.25, ck1]));
  set(0, 4, 0, ck1);
  set(2, 1, 1, S(k, 3));
  set(1, 2, 1, S(k, 4));
  set(1, 1, 2, S(k, 5));
  // The neighbouring sectors' boundary points next to corners k and k+1.
  const prevNear = comb([0.25, ck], [0.75, S(k - 1, 2)]); // (c_k + 3 t_k⁻)/4
  const nextNear = comb([0.25, ck1], [0.75, S(k + 1, 1)]); // (c_{k+1} + 3 t_{k+1}⁺)/4
  if (m === 4) {
    set(3, 0, 1, mul(add(Q[qi(3, 1, 0)], prevNear), 0.5));
    set(0, 3, 1, mul(add(Q[qi(1, 3, 0)], nextNear), 0.5));
    set(2, 0, 2, mul(add(S(k, 3), S(k - 1, 4)), 0.5));
    set(0, 2, 2, mul(add(S(k, 4), S(k + 1, 3)), 0.5));
    set(1, 0, 3, mul(add(S(k, 5), S(k - 1, 5)), 0.5));
    set(0, 1, 3, mul(add(S(k, 5), S(k + 1, 5)), 0.5));
    set(0, 0, 4, mul(add(add(S(0, 5), S(1, 5)), add(S(2, 5), S(3, 5))), 0.25));
  } else {
    set(3, 0, 1, comb([1 / 3, ck], [1 / 3, Q[qi(3, 1, 0)]], [1 / 3, prevNear]));
    set(0, 3, 1, comb([1 / 3, ck1], [1 / 3, Q[qi(1, 3, 0)]], [1 / 3, nextNear]));
    set(2, 0, 2, comb([1 / 3, Q[qi(3, 0, 1)]], [1 / 3, S(k, 3)], [1 / 3, S(k - 1, 4)]));
    set(0, 2, 2, comb([1 / 3, Q[qi(0, 3, 1)]], [1 / 3, S(k, 4)], [1 / 3, S(k + 1, 3)]));
    set(1, 0, 3, comb([1 / 3, Q[qi(2, 0, 2)]], [1 / 3, S(k, 5)], [1 / 3, S(k - 1, 5)]));
    set(0, 1, 3, comb([1 / 3, Q[qi(0, 2, 2)]], [1 / 3, S(k, 5)], [1 / 3, S(k + 1, 5)]));
    set(0, 0, 4, q[18]);
  }
  return Q;
}

/**
 * Sector of a Pm quad at (u, v), its local (s, t, w) and their derivatives with respect to u and v
 * (notes §4.2 table), so the normal is ∂P/∂u × ∂P/∂v in every sector.
 */
export function pmQuadSector(u: number, v: number): { k: number; stw: V3; du: V3; dv: V3 } {
  if (v <= u) {
    if (u + v <= 1) return { k: 0, stw: [1 - u - v, u - v, 2 * v], du: [-1, 1, 0], dv: [-1, -1, 2] };
    return { k: 1, stw: [u - v, u + v - 1, 2 - 2 * u], du: [1, 1, -2], dv: [-1, 1, 0] };
  }
  if (u + v > 1) return { k: 2, stw: [u + v - 1, v - u, 2 - 2 * v], du: [1, -1, 0], dv: [1, 1, -2] };
  return { k: 3, stw: [v - u, 1 - u - v, 2 * u], du: [-1, -1, 2], dv: [1, -1, 0] };
}

/** Sector of a Pm triangle at (u, v) = (λ1, λ2) and derivatives of (s, t, w) (notes §4.3 table). */
export function pmTriSector(u: number, v: number): { k: number; stw: V3; du: V3; dv: V3 } {
  const l0 = 1 - u - v,
    l1 = u,
    l2 = v;
  if (l0 >= l2 && l1 >= l2) return { k: 0, stw: [l0 - l2, l1 - l2, 3 * l2], du: [-1, 1, 0], dv: [-2, -1, 3] };
  if (l2 > l0 && l1 >= l0) return { k: 1, stw: [l1 - l0, l2 - l0, 3 * l0], du: [2, 1, -3], dv: [1, 2, -3] };
  return { k: 2, stw: [l2 - l1, l0 - l1, 3 * l1], du: [-1, -2, 3], dv: [1, -1, 0] };
}

const dirDeriv = (e: { Da: V3; Db: V3; Dc: V3 }, d: V3): V3 => comb([d[0], e.Da], [d[1], e.Db], [d[2], e.Dc]);

/** Position, ∂/∂u, ∂/∂v and the shading-normal direction of one patch (q = its control points). */
export function evalPatchPoints(kind: number, q: V3[], u: number, v: number): { P: V3; Pu: V3; Pv: V3; n: V3 } {
  switch (kind) {
    case KIND_REGULAR: {
      const r = evalBicubic(q, u, v);
      return { ...r, n: cross3(r.Pu, r.Pv) };
    }
    case KIND_BEZIER: {
      const r = evalBicubic(q, u, v);
      const t = evalTangentPatches(q, u, v);
      return { ...r, n: cross3(t.Tu, t.Tv) };
    }
    case KIND_GREGORY_QUAD: {
      // Derivatives of the frozen Bézier (blend weights' derivatives ignored, as the sample and OpenSubdiv).
      const r = evalBicubic(gregoryQuadBezier(q, u, v), u, v);
      return { ...r, n: cross3(r.Pu, r.Pv) };
    }
    case KIND_GREGORY_TRI: {
      const l: V3 = [1 - u - v, u, v];
      const e = evalQuartic(gregoryTriQuartic(q, l), l[0], l[1], l[2]);
      const Pu = subv(e.Db, e.Da),
        Pv = subv(e.Dc, e.Da);
      return { P: e.P, Pu, Pv, n: cross3(Pu, Pv) };
    }
    case KIND_PM_QUAD:
    case KIND_PM_TRI:
    case KIND_PM_TRI_LS: {
      const m = kind === KIND_PM_QUAD ? 4 : 3;
      const s = m === 4 ? pmQuadSector(u, v) : pmTriSector(u, v);
      const e = evalQuartic(pmSectorQuartic(q, m, s.k), s.stw[0], s.stw[1], s.stw[2]);
      const Pu = dirDeriv(e, s.du),
        Pv = dirDeriv(e, s.dv);
      return { P: e.P, Pu, Pv, n: cross3(Pu, Pv) };
    }
    default:
      throw new AccError(`unknown patch kind ${kind}`);
  }
}

/** An ACC surface of a cage: topology, control points (f64) and evaluation by (face, u, v). */
export class AccSurface {
  readonly topology: AccTopology;
  points: Float64Array;
  constructor(
    readonly cage: Cage,
    readonly scheme: AccScheme,
    topology?: Topology,
    options: AccOptions = {},
  ) {
    this.topology = buildAccTopology(cage, scheme, topology, options);
    this.points = buildAccPoints(this.topology, cage.positions);
  }

  /** Rebuild the control points for new cage positions (same connectivity). */
  update(positions: ArrayLike<number>): void {
    this.points = buildAccPoints(this.topology, positions);
  }

  kind(face: number): number {
    return this.topology.patches[2 * face];
  }

  /** The control points of a patch. */
  patch(face: number): V3[] {
    const kind = this.topology.patches[2 * face],
      o = this.topology.patches[2 * face + 1];
    const out: V3[] = [];
    for (let i = 0; i < KIND_POINTS[kind]; i++)
      out.push([this.points[3 * (o + i)], this.points[3 * (o + i) + 1], this.points[3 * (o + i) + 2]]);
    return out;
  }

  /** Position, derivatives and unit shading normal at (face, u, v) (triangles: (u, v) = (w1, w2)). */
  evaluate(face: number, u: number, v: number): AccPoint & { Pu: V3; Pv: V3 } {
    const r = evalPatchPoints(this.kind(face), this.patch(face), u, v);
    return { P: r.P, Pu: r.Pu, Pv: r.Pv, N: normalize3(r.n) };
  }
}

/** The f32 constant table the GPU build reads per valence: see src/gpu/acc/patches.ts. */
export function valenceTable(maxValence: number): { offsets: Uint32Array; values: Float32Array } {
  const offsets = new Uint32Array(maxValence + 1);
  const vals: number[] = [];
  for (let n = 2; n <= maxValence; n++) {
    offsets[n] = vals.length;
    const k = valenceConstants(n);
    vals.push(k.c, k.s, k.lambda, k.sn, ...k.alpha, ...k.beta, ...k.cosk);
  }
  return { offsets, values: Float32Array.from(vals) };
}

/**
 * The f32 constant table of crease and corner sectors the GPU build reads: offsets[2k + corner?]
 * into values: cos θ, sin θ, n', ca[0..k], cb[0..k], then (creases) the mask[2k + 2] (sectorConstants).
 */
export function sectorTable(maxSector: number): { offsets: Uint32Array; values: Float32Array } {
  const offsets = new Uint32Array(2 * (maxSector + 1));
  const vals: number[] = [];
  for (let k = 1; k <= maxSector; k++)
    for (const type of [SECTOR_CREASE, SECTOR_CORNER]) {
      offsets[2 * k + (type === SECTOR_CORNER ? 1 : 0)] = vals.length;
      const K = sectorConstants(type, k);
      vals.push(K.c, K.s, K.np, ...K.ca, ...K.cb, ...K.mask);
    }
  return { offsets, values: Float32Array.from(vals) };
}
