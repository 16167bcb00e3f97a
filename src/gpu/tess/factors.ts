/**
 * The edge tess-factor rule and the buffer budget, in TypeScript: the reference that
 * wgsl/tess/common.wgsl (edgeFactor) mirrors, and what the unit tests hold it to.
 *
 * ADAPTIVE RULE (Hable: "the offset from the Phong midpoint to the linear midpoint, using arc
 * angle instead of screen projection"). For an edge p0–p1 with unit normals n0, n1 and
 * d = p1 − p0, Phong tessellation's midpoint minus the linear midpoint is
 *     e = (α/4)·((d·n1)n1 − (d·n0)n0),  α = 3/4,
 * symmetric in the two ends. (The Phong surface lowers α on some edges, src/gpu/surface/phong.ts; the
 * rule keeps 3/4 there, a larger bend than the surface's, so such an edge is cut a little finer.)
 * Split into k segments a curved edge's chord error falls as 1/k², so the error seen from the
 * eye, as an angle, is |e| / (k²·dist). Asking for at most one pixel
 * (pixelAngle = fovY / viewportHeight) at LOD scale 1 gives
 *     k = sqrt(lodScale·|e| / (dist·pixelAngle)).
 * That holds for k EQUAL segments. The factor F = k goes to Hable's pop-free line, whose points
 * slide in through each octave: its longest segment is up to 1.22/F long in octave [2, 4], 1.43/F
 * in [4, 8], 1.64/F in [8, 16] (tests/pattern/line.test.ts), so the chord error allowed is up to
 * (L·F)² = 1.5, 2.0, 2.7 px at LOD 1 there (3.6 near 64). Asking for the factor whose longest
 * segment is 1/k instead would cost about 1.66× the triangles (mean over k in [1, 32]) and jump
 * (k = 8 needs F = 8, k = 8.016 needs F = 13.1): the jump is a pop. Not done; issue 13 says so.
 * On an edge whose two ends both face the eye (n·toEye > 0.1·|toEye|), the part of e across the
 * line of sight, e⊥ = e − (e·r)r with r the unit ray from the eye to the Phong midpoint, counts
 * twice: |e| becomes max(|e|, 2|e⊥|). That part is what moves silhouettes and occlusion contours
 * on screen, and a contour short of the limit's shows the surface behind it (issue 13's outline
 * and brow speckles). Measured against |e| alone (e2e/artifacts.spec.ts, tests/no-folds,
 * tests/cc-folds): speckles suzanne CC 32 → 26, Phong 18 → 17, pawn CC 6 → 4, Phong 7 → 4,
 * creature CC 5 → 6 (an outline corner a pixel off); folded triangles on the creature CC 8 → 7,
 * Phong 17 → 14; in the demo's first view (`npm run tessellate -- M --adaptive --flat-baseline
 * --demo-view --stats`) 5–21% more triangles: creature 3,772 → 3,958, bigguy 8,214 → 9,322,
 * suzanne 3,808 → 4,608. Counting it on every edge instead folds the box and the
 * gear (0 → 4, 0 → 2). The GPU's copy of this measure is wgsl/tess/factor-rule.wgsl.
 *
 * BULGE TERM (bulgeFactor; wgsl/tess/factor-bulge.wgsl). The edge term sees only an edge's ends.
 * Inside a cage triangle whose edges are nearly straight the surface can still bulge (on the
 * talk's cages, the limit's bulge at the centroid of a triangle whose edges all ask for factor
 * < 1.5 is up to 3.6× what the ends predict), and the clamped pattern puts no interior vertex
 * there below a factor of about 3: the drawn triangles cut through the bulge. So each triangle
 * samples its surface (the exact limit for Catmull-Clark, before the flat-baseline blend) at
 * BULGE_WEIGHTS (the three points (2/3, 1/6, 1/6), then the centroid); a sample's bulge b is its
 * distance from the flat triangle of the corners at the same weights, and it asks for
 *     k = sqrt(BULGE_ALPHA·lodScale·b / (dist·pixelAngle)),
 * the edge term's law with the constant fitted: in the demo's first view at LOD 1
 * (tests/gpu/tess/limit-distance.node.test.ts: every drawn edge's midpoint and triangle's centroid against
 * the limit), α = 10 brings the largest distance to about 0.7–0.9 px on the creature, pawn,
 * bigguy and suzanne (the test logs them), from 2.56 / 3.02 / 2.58 / 4.70 px without the term.
 * That costs 7.4–8.6× the triangles of the edge term alone there (creature 3,958 → 31,720,
 * suzanne 4,608 → 38,694). The centroid alone needed α = 16 and about 1.6× the triangles of the
 * four samples for the same bound; α = 4 left 1.5 px. Each edge takes the larger k of its two
 * triangles, so the factor stays one per edge and continuous in the camera
 * (tests/gpu/cc/animate.gpu.test.ts's jump test).
 * Facing away does not lower a triangle's k. Skipping samples that face away (by more than
 * 0.5·|toEye|) saved about a fifth of the triangles, but a triangle facing away beside one
 * facing the eye then kept an edge at 1 beside edges at 14, and those strips fold: over
 * tests/gpu/tess/no-folds.test.ts's views the boxes went 10 → 106 folded triangles, the gear 3 → 24;
 * without the skip they are 0 and 0 (the creature 67 → 6).
 * A triangle whose sphere (round the flat centroid through the farthest corner, grown by the
 * largest bulge) is outside the view frustum is BULGE_OFF_SCREEN.
 * Edges whose bounding sphere (centre: the Phong midpoint, radius |d|/2 + |e|) is outside the
 * view frustum, or whose two ends both face away from the eye, drop to factor 1 unless a
 * triangle beside them is on screen.
 */
import { ONE } from '../../pattern/fixed.ts';
import { MAX_FACTOR, PHONG_ALPHA } from '../contract/constants.ts';
import type { FactorParams } from '../contract/tessellated-mesh.ts';

export { PHONG_ALPHA };

export type Vec3 = readonly [number, number, number];

const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];

/** Phong midpoint minus linear midpoint of an edge. */
export function phongMidpointOffset(p0: Vec3, p1: Vec3, n0: Vec3, n1: Vec3): Vec3 {
  const d = sub(p1, p0);
  const a = dot(d, n1),
    b = dot(d, n0);
  const s = PHONG_ALPHA / 4;
  return [s * (a * n1[0] - b * n0[0]), s * (a * n1[1] - b * n0[1]), s * (a * n1[2] - b * n0[2])];
}

export interface FactorRule {
  mode: 'fixed' | 'adaptive';
  fixedFactor: number;
  lodScale: number;
  /** Column-major view-projection, WebGPU clip space (z in 0..1). */
  viewProj: ArrayLike<number>;
  eye: Vec3;
  /** fovY / viewportHeight, radians per pixel. */
  pixelAngle: number;
  maxFactor: number;
}

/** The adaptive rule a tessellator applies for its FactorParams (camera, viewport, LOD scale). */
export function adaptiveRuleOf(p: FactorParams, maxFactor = MAX_FACTOR): FactorRule {
  return {
    mode: 'adaptive',
    fixedFactor: 1,
    lodScale: p.lodScale,
    viewProj: p.viewProj,
    eye: [p.eye[0], p.eye[1], p.eye[2]],
    pixelAngle: p.fovY / p.viewportHeight,
    maxFactor,
  };
}

/** Is a sphere entirely outside one of the six frustum planes of viewProj? */
export function sphereOutsideFrustum(m: ArrayLike<number>, c: Vec3, r: number): boolean {
  const row = (i: number) => [m[i], m[4 + i], m[8 + i], m[12 + i]];
  const r0 = row(0),
    r1 = row(1),
    r2 = row(2),
    r3 = row(3);
  const planes = [
    r3.map((v, i) => v + r0[i]),
    r3.map((v, i) => v - r0[i]),
    r3.map((v, i) => v + r1[i]),
    r3.map((v, i) => v - r1[i]),
    r2,
    r3.map((v, i) => v - r2[i]), // WebGPU: 0 ≤ z ≤ w
  ];
  for (const p of planes) {
    const len = Math.hypot(p[0], p[1], p[2]);
    if (p[0] * c[0] + p[1] * c[1] + p[2] * c[2] + p[3] < -r * len) return true;
  }
  return false;
}

/** The bulge term's constant (see the header; wgsl/tess/factor-bulge.wgsl holds the same). */
export const BULGE_ALPHA = 10;
/** A triangle's bulge term where it is off screen. */
export const BULGE_OFF_SCREEN = -1;
/** The bulge samples, 16.16 barycentrics exactly as the WGSL makes them: (2/3, 1/6, 1/6) at each
 * corner, then the centroid. */
export const BULGE_WEIGHTS: readonly Vec3[] = (() => {
  const sixth = Math.floor(ONE / 6),
    third = Math.floor(ONE / 3);
  const w: Vec3[] = [0, 1, 2].map((i) => [0, 1, 2].map((j) => (j === i ? ONE - 2 * sixth : sixth)) as unknown as Vec3);
  w.push([third, third, ONE - 2 * third]);
  return w;
})();

/**
 * The factor a cage triangle's bulge asks for (the header's bulge term): `corners` are its
 * corners' positions (the factor rule's: the limit's for Catmull-Clark), `surface` evaluates its
 * surface at 16.16 barycentrics. BULGE_OFF_SCREEN where the triangle is outside the frustum.
 */
export function bulgeFactor(
  corners: readonly [Vec3, Vec3, Vec3],
  surface: (w: Vec3) => { pos: ArrayLike<number> },
  rule: FactorRule,
): number {
  let k = 0;
  let most = 0;
  for (const w of BULGE_WEIGHTS) {
    const s = surface(w);
    const dist = Math.max(Math.hypot(rule.eye[0] - s.pos[0], rule.eye[1] - s.pos[1], rule.eye[2] - s.pos[2]), 1e-6);
    const b = Math.hypot(...[0, 1, 2].map((c) => s.pos[c] - (w[0] * corners[0][c] + w[1] * corners[1][c] + w[2] * corners[2][c]) / ONE));
    most = Math.max(most, b);
    k = Math.max(k, Math.sqrt((BULGE_ALPHA * rule.lodScale * b) / (dist * rule.pixelAngle)));
  }
  const c = [0, 1, 2].map((i) => (corners[0][i] + corners[1][i] + corners[2][i]) / 3) as unknown as Vec3;
  const r = Math.max(...corners.map((p) => Math.hypot(p[0] - c[0], p[1] - c[1], p[2] - c[2]))) + most;
  return sphereOutsideFrustum(rule.viewProj, c, r) ? BULGE_OFF_SCREEN : k;
}

/** The adaptive or fixed factor of edge p0–p1 (unit normals n0, n1); `bulge` is the larger
 * bulgeFactor of its two triangles (the default: both off screen, the edge term alone). */
export function edgeFactor(p0: Vec3, p1: Vec3, n0: Vec3, n1: Vec3, rule: FactorRule, bulge = BULGE_OFF_SCREEN): number {
  let f: number;
  if (rule.mode === 'fixed') {
    f = rule.fixedFactor;
  } else {
    const e = phongMidpointOffset(p0, p1, n0, n1);
    const el = Math.hypot(e[0], e[1], e[2]);
    const mid: Vec3 = [(p0[0] + p1[0]) / 2 + e[0], (p0[1] + p1[1]) / 2 + e[1], (p0[2] + p1[2]) / 2 + e[2]];
    const radius = Math.hypot(...sub(p1, p0)) / 2 + el;
    const toEye0 = sub(rule.eye, p0),
      toEye1 = sub(rule.eye, p1);
    const away = dot(n0, toEye0) < -0.1 * Math.hypot(...toEye0) && dot(n1, toEye1) < -0.1 * Math.hypot(...toEye1);
    if ((away || sphereOutsideFrustum(rule.viewProj, mid, radius)) && bulge === BULGE_OFF_SCREEN) {
      f = 1;
    } else {
      const dist = Math.max(Math.hypot(...sub(mid, rule.eye)), 1e-6);
      const ray: Vec3 = [(mid[0] - rule.eye[0]) / dist, (mid[1] - rule.eye[1]) / dist, (mid[2] - rule.eye[2]) / dist];
      const along = dot(e, ray);
      const errAcross = Math.hypot(e[0] - along * ray[0], e[1] - along * ray[1], e[2] - along * ray[2]);
      const facing = dot(n0, toEye0) > 0.1 * Math.hypot(...toEye0) && dot(n1, toEye1) > 0.1 * Math.hypot(...toEye1);
      const errSeen = facing ? Math.max(el, 2 * errAcross) : el;
      f = Math.max(Math.sqrt((rule.lodScale * errSeen) / (dist * rule.pixelAngle)), bulge);
    }
  }
  if (!(f >= 1)) return 1; // NaN, ≤ 1
  return Math.min(f, rule.maxFactor);
}

/**
 * The budget (wgsl/tess/scan.wgsl `budget`): a rebuild counts its output at every candidate scale
 * of the factors (contract/tess.ts BUDGET_SCALES, largest first; the last is factor 1 everywhere)
 * and takes the first whose vertices and triangles fit the buffers, or the last, which setMesh
 * checks always fits. `totals[c]` are candidate c's counts. Returns the candidate and whether it fits.
 */
export function budgetCandidate(
  totals: readonly { vertices: number; triangles: number }[],
  vertexCapacity: number,
  triangleCapacity: number,
): { candidate: number; fits: boolean } {
  for (let c = 0; c < totals.length; c++) {
    const fits = totals[c].vertices <= vertexCapacity && totals[c].triangles <= triangleCapacity;
    if (fits || c === totals.length - 1) return { candidate: c, fits };
  }
  throw new Error('no budget candidates');
}

/** Bytes of output per vertex and per triangle (positions, normals, bary, srcTri; indices). */
export const BYTES_PER_VERTEX = 12 + 12 + 4 + 4;
export const BYTES_PER_TRIANGLE = 12;

/**
 * Output capacities from the device limits: each output buffer must fit one storage binding
 * (positions and normals are the largest per vertex, indices per triangle), and a request can
 * only lower them.
 */
export function outputCapacity(
  limits: { maxStorageBufferBindingSize: number; maxBufferSize: number },
  request: { vertexCapacity?: number; triangleCapacity?: number } = {},
): { vertexCapacity: number; triangleCapacity: number } {
  const largest = Math.min(limits.maxStorageBufferBindingSize, limits.maxBufferSize);
  const byLimit = Math.floor(largest / 12);
  return {
    vertexCapacity: Math.max(0, Math.min(byLimit, request.vertexCapacity ?? 1 << 24)),
    triangleCapacity: Math.max(0, Math.min(byLimit, request.triangleCapacity ?? 1 << 24)),
  };
}
