/**
 * Approximate Catmull-Clark (ACC) patches: the CPU yardstick (f64) of the three schemes of NVIDIA's
 * 2009 "Instanced Tessellation" sample, after the papers below:
 *
 *   bezier-acc   Loop & Schaefer 2008: 16-point bicubic geometry patch + two tangent patches
 *                (T_u quadratic×cubic, T_v cubic×quadratic) whose cross product is the shading normal.
 *   gregory-acc  Loop, Schaefer, Ni & Castaño 2009: 20-point Gregory quad, 15-point Gregory triangle
 *                (quartic, our G1 blend rule (acc-evaluate.ts), not the sample's inconsistent one).
 *   pm-acc       24-point c-patch (4 quartic sectors) for quads, 19-point Pm triangle (3 sectors + centre).
 *
 * In every scheme a regular quad (4 interior valence-4 corners whose rings are all quads) is the
 * bicubic B-spline converted to Bézier form, exactly. The other constructions are the
 * papers'; where they leave a choice we take:
 *   - Gregory edge length s_n: nvmesh's table (Castaño's nvmesh produced the sample's data).
 *   - λ_n, σ_n, cos tables: the closed forms in f64 (not the Pm code's rounded σ table), any valence.
 *   - Diagonal D_i of a ring face: quad = opposite vertex; triangle = centroid (Bezier, Gregory:
 *     the exact CC limit) or edge midpoint (Pm, as nvmesh; its corners next to triangles miss the limit).
 *   - Triangles in a Bezier-ACC cage: the 19-point Pm triangle (as the sample), with c = the exact
 *     limit (centroid rule) and, on every edge shared with a quad, the quad's Loop–Schaefer edge
 *     points M_j as tangent points (kind PM_TRI_LS); on triangle–triangle edges the Pm tangent points
 *     (of the midpoint rule, which the Pm twist terms need: an all-triangle cage is G1).
 *     The sample's plain Pm triangle has a different boundary cubic from the Bezier quad next to it
 *     and cracks; this one is watertight. Its normal is the Pm triangle's own: across
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
 *     the cone is not modelled). A crease sector of one face is built (the patch's two tangents
 *     at that corner are parallel: the corner has no normal of its own; the evaluators take the
 *     patch's normal just inside, ACC_DEGENERATE_STEP below).
 *   - Interior vertices of valence 2 are built with the n = 2 masks and a warning (Catmull-Clark's
 *     own limit there needs refinement, and has no tangent plane at the vertex; Bezier ACC's
 *     tangent-patch normal is degenerate exactly there: the same rule gives it one).
 *   - Faces with more than 4 corners: refused here (the sample only has quads and triangles; a split
 *     of those faces alone would change the neighbours' rings). accCage gives such a cage one
 *     Catmull-Clark step first, as the papers propose: the same limit, all quads. Holes: their
 *     patches are built (the ring points are there) and never drawn.
 *
 * ---------------------------------------------------------------------------------------------------
 * ONE LAYOUT FOR ALL SCHEMES (the GPU build wgsl/acc/build.wgsl writes it, wgsl/acc/surface.wgsl reads it)
 *
 *   patch p = cage face p (every face is a patch).
 *   patches   2 u32 per patch: kind, first control point.
 *   points    control points (xyz; f64×3 here, vec4<f32> on the GPU with w unused), per kind:
 *     REGULAR     16  b_ij at i + 4j (i along u, j along v; corners c0..c3 at (0,0),(3,0),(3,3),(0,3))
 *     BEZIER      32  16 as REGULAR, then U_{a,c} (a = 0, 2; c = 0..3) at 16 + 2a + c, then
 *                     V_{c,a} (a = 0, 2; c = 0..3) at 24 + 2a + c (the sample's 32 float3). The middle
 *                     rows U_{1,c} = 3(b_{2c} − b_{1c}), V_{c,1} = 3(b_{c2} − b_{c1}) are recomputed (as the sample does).
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
 *     sectors   1 u32 per patch corner (4 per patch): packSector(type, k, a), type SECTOR_SMOOTH
 *               (the whole cyclic ring), SECTOR_CREASE or SECTOR_CORNER: the corner's sector is ring
 *               edges a .. a+k (mod n) and ring faces a .. a+k−1; see "Boundaries and creases".
 *     Ring convention (OpenSubdiv's): face i contains the directed edges v→e_i and
 *     e_{i+1}→v. Seen from a patch corner with rotation r, local e_j = e_{(r+j) mod n}: local e_0 is
 *     the face's next corner, e_1 its previous one, local face 0 the patch itself.
 *
 *   Evaluation parameters: quads (u, v) with c0 = (0,0), c1 = (1,0), c2 = (1,1), c3 = (0,1) (the exact
 *   reference's); triangles (u, v) = (w1, w2), the barycentric weights of face corners 1 and 2
 *   (w0 = 1 − u − v), i.e. the tessellator's weights on a triangle face (prepare.ts fans it as (c0,c1,c2)).
 *
 * ---------------------------------------------------------------------------------------------------
 * THE FILES: this one holds the schemes, patch kinds, constants (and their f32 tables for the GPU)
 * and the construction topology; src/subdiv/acc-patches.ts builds the patches' control points,
 * src/subdiv/acc-evaluate.ts evaluates them (AccSurface).
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
import { hasNgons, refineCage } from './refine-cage.ts';

/** The sharpness from which the schemes build a crease or corner infinitely sharp (semiSharp
 * 'sharp', the default): below it, smooth. The tessellator splits normals there too (prepare.ts). */
export const ACC_SHARP_FROM = 1;

/** A patch point whose two tangents make a normal shorter than ACC_DEGENERATE_SIN × their lengths
 * (parallel, or one zero) has no normal of its own: it takes the patch's normal ACC_DEGENERATE_STEP
 * of the way into the patch (src/subdiv/acc-evaluate.ts AccSurface.evaluate and
 * wgsl/acc/surface.wgsl evalAccPatch, which says why). */
export const ACC_DEGENERATE_SIN = 1e-4;
export const ACC_DEGENERATE_STEP = 1e-2;

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

/** A patch corner's sector word (`sectors`), its fields as [lowest bit, width]: the kind
 * (SECTOR_*), the sector's size k in faces and its first ring edge a. The one layout of the word:
 * packSector and unpackSector read it here, and the GPU's declaration of the same word
 * (src/gpu/contract/acc.ts ACC_SECTOR_WORD) is made from it. */
export const SECTOR_WORD_FIELDS = { kind: [0, 2], k: [2, 14], a: [16, 16] } as const;

type SectorField = keyof typeof SECTOR_WORD_FIELDS;

/** The sector word of (kind, k, a); throws if a value does not fit its field. */
export function packSector(kind: number, k: number, a: number): number {
  const values: Record<SectorField, number> = { kind, k, a };
  let word = 0;
  for (const [f, [at, bits]] of Object.entries(SECTOR_WORD_FIELDS) as [SectorField, readonly [number, number]][]) {
    if (!Number.isInteger(values[f]) || values[f] < 0 || values[f] >= 2 ** bits)
      throw new AccError(`a sector's ${f} = ${values[f]} does not fit its ${bits} bits`);
    word += values[f] * 2 ** at;
  }
  return word;
}

/** The fields of a sector word (packSector's inverse). */
export function unpackSector(word: number): Record<SectorField, number> {
  const field = ([at, bits]: readonly [number, number]) => Math.floor(word / 2 ** at) % 2 ** bits;
  return { kind: field(SECTOR_WORD_FIELDS.kind), k: field(SECTOR_WORD_FIELDS.k), a: field(SECTOR_WORD_FIELDS.a) };
}

export class AccError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'AccError';
  }
}

// ------------------------------------------------------------------------------------------------
// Constants. Shared with the GPU: the build pass reads them from a table written in f64
// and rounded to f32 once (WGSL's cos is as coarse as 2^-11 on some GPUs).

/** Gregory edge-point length s_n of nvmesh (castano/nvidia-mesh-tools), n = 3..12; 0.831134 for n ≥ 13. */
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
  /** 4 per patch: the corner's sector, packSector(type, k, a) (SECTOR_*). */
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
   * schemes' regular exactness, and the guard that the Pm c-patch is NOT exact there).
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

/** The cage an ACC scheme builds its patches on, and why it is not the cage given. */
export interface AccCage {
  cage: Cage;
  /** Set when the cage was refined: what the stats and the CLI say. */
  note: string | null;
  /** The Catmull-Clark steps taken (0: the cage itself). */
  steps: number;
}

const accCages = new WeakMap<Cage, AccCage>();

/** The most Catmull-Clark steps accCage takes for semi-sharp creases, and the most patches they may
 * make (each step makes 4 of a quad); creases still semi-sharp after them are built as
 * AccOptions.semiSharp says. */
export const ACC_MAX_STEPS = 4;
export const ACC_MAX_PATCHES = 1 << 15;

/**
 * The cage the ACC schemes take in place of `cage`: the cage itself, or k Catmull-Clark steps of
 * the whole cage first (src/subdiv/refine-cage.ts: the same limit surface, every face a quad):
 *   - one where it has n-gons (faces of 5 corners or more: the schemes' patches are quads and
 *     triangles), as the papers propose;
 *   - ceil(σ) where its sharpest semi-sharp crease or corner has sharpness σ (0 < σ < 10): each
 *     step decays every sharpness by one (OpenSubdiv's uniform or Chaikin rule), so after them
 *     none is left, and the schemes, which model only smooth and infinitely sharp features, build
 *     the semi-sharp surface from its exact refinement instead of rounding σ to 0 or ∞ (the error
 *     views show the difference: tests/subdiv/acc-cage.test.ts);
 * at most ACC_MAX_STEPS and ACC_MAX_PATCHES patches (the n-gon step always), the rest built
 * sharp or smooth as before, which the note says. The whole cage, not only where it is needed: a
 * patch's edges are built from both sides' points, and only a step of both sides keeps them
 * watertight. Kept per cage (one object for every scheme and view).
 */
export function accCage(cage: Cage): AccCage {
  let r = accCages.get(cage);
  if (!r) {
    const ngons = hasNgons(cage);
    let sigma = 0;
    for (const t of [...cage.creases, ...cage.corners])
      if (t.sharpness > 0 && t.sharpness < SHARPNESS_INFINITE) sigma = Math.max(sigma, t.sharpness);
    const want = Math.max(ngons ? 1 : 0, Math.ceil(sigma));
    // Patches after k steps: the cage's face corners after the first (a face of n corners makes n
    // quads), 4 times as many after each next.
    let patches = cage.faceIndices.length;
    let steps = 0;
    while (steps < want && (steps === 0 ? ngons || patches <= ACC_MAX_PATCHES : steps < ACC_MAX_STEPS && 4 * patches <= ACC_MAX_PATCHES)) {
      if (steps > 0) patches *= 4;
      steps++;
    }
    let refined = cage;
    for (let k = 0; k < steps; k++) refined = refineCage(refined).cage;
    if (steps === 0) r = { cage, note: null, steps };
    else {
      const why = [ngons ? 'the cage has n-gons' : '', sigma > 0 ? `semi-sharp creases up to ${+sigma.toPrecision(3)} decay` : '']
        .filter(Boolean)
        .join('; ');
      const left = steps < Math.ceil(sigma) ? `; what is left of sharper creases is built sharp (≥ ${ACC_SHARP_FROM}) or smooth` : '';
      const faces = (refined.faceOffsets.length - 1).toLocaleString('en-US');
      r = {
        cage: refined,
        note: `${steps === 1 ? 'one Catmull-Clark step' : `${steps} Catmull-Clark steps`} first (${why}): ${faces} patches${left}`,
        steps,
      };
    }
    accCages.set(cage, r);
  }
  return r;
}

/**
 * Derive everything the construction needs from the cage's connectivity (once per topology, linear
 * time). Throws AccError for faces with more than 4 corners and the sharp configurations
 * listed at the top (creases and boundaries are built).
 */
export function buildAccTopology(cage: Cage, scheme: AccScheme, topology?: Topology, options: AccOptions = {}): AccTopology {
  const topo = topology ?? buildTopology(cage);
  const nV = topo.nVerts,
    nF = topo.nFaces;
  const problems: string[] = [];
  for (let f = 0; f < nF; f++) {
    const n = topo.faceOffsets[f + 1] - topo.faceOffsets[f];
    if (n > 4) problems.push(`face ${f + 1} has ${n} corners (ACC patches are quads and triangles only: accCage refines such a cage once)`);
  }
  // Holes (tagged, or made by boundary mode 'none') keep their patches: their corners are the
  // neighbours' ring points as in Catmull-Clark (a hole removes a face's surface, not its points),
  // and the tessellators never evaluate them (src/gpu/tess/prepare.ts drops their triangles).
  const sharp = computeSharpness(cage, topo, { ...DEFAULT_OPTIONS, ...cage.fileOptions });
  const fail = (list: string[]) =>
    new AccError(`${scheme}: ${list.slice(0, 3).join('; ')}${list.length > 3 ? `; … (${list.length - 3} more)` : ''}`);
  if (problems.length) throw fail(problems);
  const warnings: string[] = [];
  const asSharp = options.semiSharp !== 'smooth';
  const isInf = (x: number) => x >= SHARPNESS_INFINITE || (asSharp && x >= ACC_SHARP_FROM);
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
        sectors[4 * f + c] = packSector(type, 0, 0);
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
      sectors[4 * f + c] = packSector(type, k, a);
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
