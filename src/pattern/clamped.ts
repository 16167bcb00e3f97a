/**
 * Hable's clamped-parallelogram triangle pattern: three independent edge factors, no inside
 * factor, one triangle at (1,1,1), N² triangles at a uniform power of two N.
 *
 * CONVENTIONS (the checks rely on them)
 *   Corner i is the barycentric unit vector e_i. Edge i joins corner i to corner (i+1) mod 3;
 *   its parameter t is the weight of corner (i+1) mod 3. A forward edge places the line's
 *   points at t = x, a reversed edge (walked from corner i+1, as a mesh does when the edge's
 *   lower-index vertex is corner i+1) at t = 1 − x. Hable's line is not symmetric, so this flag
 *   is what makes two triangles agree on a shared edge.
 *
 *   Internally the pattern is built in a FRAME: an origin corner A, u along the BOTTOM edge
 *   A→B, v along the LEFT edge A→C, and the RIGHT edge B→C is the hypotenuse u + v = 1. The
 *   frame is chosen from the reverse flags alone (so both triangles of an edge still agree):
 *   the left edge must be one whose line STARTS at C, because a line's new points are born
 *   next to its start, and a row born at C collapses onto the left edge while a row born at A
 *   would put its clamp end (c, 0) where no vertex was (a pop). In a mesh the corner with the
 *   highest vertex index has both its edges pointing at it, so the first rotation tried there
 *   works; the frames tried are the rotations (A, B, C) = (o, o+1, o+2) for o = 0, 1, 2, then the
 *   reflections (o, o+2, o+1), which reverse the winding. With all edges forward the frame is
 *   A = corner 0, bottom = edge 0, left = edge 2.

 * CONSTRUCTION (all integer arithmetic over ONE = 2^16)
 *   1. Parallelogram: the bottom line gives columns u_0..u_nb, the left line rows v_0..v_nl.
 *   2. Gap: the clamp line is u + v = c with c = 1 − max(gap_u, gap_v). The talk takes a line's
 *      gap as 1 minus its last interior point; here it is the LARGER OF THE LAST TWO SEGMENTS
 *      (1 for a single segment). The two agree at powers of two, but only this one is
 *      continuous: a point born on the end point (a reversed edge, or the 1→2 ghost) makes
 *      "the last interior point" jump from its neighbour to 1, while the last two segments go
 *      from (a, b) to (b, 0) with a ≤ b (checked by the continuity test). It is never smaller
 *      than the last segment, so c ≤ u_{nb−1} and c ≤ v_{nl−1}, which step 4 needs.
 *   3. Clamp: row j ≥ 1 (v = v_j) keeps the columns with u_i < e_j = max(0, c − v_j) and ends at
 *      E_j = (e_j, v_j) on the clamp line (the talk's u = min(u, (1 − gap) − v)); columns that
 *      would pass the line collapse onto E_j and are merged into it. Row 0 is the bottom edge
 *      itself, never clamped, so no edge vertex ever moves: its grid part is u_0..u_{k_0}, with
 *      u_{k_0} the first point at or past the clamp line (k_0 ≤ nb − 1 since c ≤ u_{nb−1}); the
 *      points after it belong to the gap strip. (With a single right segment and a strip too
 *      large for step 4's exact triangulation, k_0 = nb − 1: the greedy could then only fan the
 *      strip from B and C; rowZeroKept.) Row nl is corner C.
 *      Between rows j and j+1, column i gives a "lower" triangle if i < k_j and an "upper"
 *      one if i < k_{j+1} (k_j = columns kept in row j), so a quad disappears exactly when it
 *      has collapsed.
 *   4. Gap strip: what is left, between the inner chain u_{nb−1}, …, u_{k_0} (the bottom's tail,
 *      walked back from B), E_1, …, E_nl = C and the right edge B = O_0, O_1, …, O_nr = C, is a
 *      convex polygon (the turn at u_{k_0} is u_{k_0} − c ≥ 0; the others are shown in the header
 *      comment of tests/pattern/clamped.test.ts), so any triangulation of it has no flip. It is cut to avoid
 *      CAPS: triangles whose three distinct vertices lie nearly on one line. In the domain they
 *      are harmless, but their vertices lie on a curve of the surface (an edge, the clamp line)
 *      and the flat triangle through them folds under it: the dark dotted lines of issue 13.
 *      A strip of at most STRIP_DP_VERTICES points (what adaptive factors near 1–3 make, where
 *      the folds were) gets the exact triangulation of least Σ 16^angleLevel
 *      (stripTriangulation), which may also join two points of one chain; a larger one a
 *      monotone merge of the two chains by a greedy walk from B on the current positions
 *      (gapMergeSteps, "gap matching"). Both are pure functions of the points, so of the three
 *      factors and the frame; the GPU's plan pass computes them once per cage triangle and
 *      stores them for the emit pass. (The merge before them compared the points' final
 *      places, which never changes while points slide, but fanned a point born at a corner to
 *      every point of the next edge.) At powers of two they reproduce the uniform grid.
 *
 * Hable adds a centre point while the left factor is below 2 because his parallelogram breaks
 * while the left edge's points slide in from both ends. Here every sliding left point simply
 * gets its own row (the rows may be in any position), so no centre point is needed: the
 * pattern is the single triangle at (1,1,1) and grows continuously from there.
 *
 * Vertex order (in the frame): row 0, row 1, …, row nl (= C), then B, then O_1..O_{nr−1}.
 */
import { ONE } from './fixed.ts';
import { MAX_FACTOR } from './max-factor.ts';
import { HABLE_OPTIONS, cachedSlots, presentSlots, slotPosition, stableFactorFixed, type Slot } from './hable-line.ts';
import type { TriPattern } from './types.ts';

export type Reverse = readonly [boolean, boolean, boolean];
export const FORWARD: Reverse = [false, false, false];

/** One edge of the clamped pattern: its points in the internal frame, ascending. */
export interface FramedLine {
  x: number[];
}

/** The points of one edge line at F, already mapped to the frame coordinate:
 * `flip` = the frame runs against the line's own direction (coordinate = ONE − x). */
export function framedLine(slots: Slot[], present: number[], F: number, flip: boolean): FramedLine {
  const x = present.map((i) => slotPosition(slots[i], F));
  if (!flip) return { x };
  return { x: x.map((v) => ONE - v).reverse() };
}

/** The frame a triangle's pattern is built in (see the header). */
export interface PatternFrame {
  /** The corners playing A (origin), B and C. */
  a: number;
  b: number;
  c: number;
  /** Edge index of the bottom (A–B), left (A–C) and right (B–C) edges. */
  bottomEdge: number;
  leftEdge: number;
  rightEdge: number;
  /** Whether each frame coordinate runs against the edge's line (coordinate = ONE − x). */
  flipBottom: boolean;
  flipLeft: boolean;
  flipRight: boolean;
  /** A reflection: the triangles' winding must be reversed to stay positive. */
  mirrored: boolean;
}

/** Edge index joining corners p and q, and whether the frame coordinate that runs from p
 * (0) to q (ONE) is ONE − x for that edge's line. */
function edgeFrom(p: number, q: number, reverse: Reverse): { edge: number; flip: boolean } {
  const edge = q === (p + 1) % 3 ? p : q;
  // Edge e's t is the weight of corner e+1: forward t = x, reversed t = ONE − x.
  const towardsEnd = q === (edge + 1) % 3;
  return { edge, flip: towardsEnd === reverse[edge] };
}

function makeFrame(a: number, b: number, c: number, reverse: Reverse, mirrored: boolean): PatternFrame {
  const bottom = edgeFrom(a, b, reverse);
  const left = edgeFrom(a, c, reverse);
  const right = edgeFrom(b, c, reverse);
  return {
    a,
    b,
    c,
    bottomEdge: bottom.edge,
    leftEdge: left.edge,
    rightEdge: right.edge,
    flipBottom: bottom.flip,
    flipLeft: left.flip,
    flipRight: right.flip,
    mirrored,
  };
}

/** The frame for these reverse flags: the first whose left line starts at C. */
export function chooseFrame(reverse: Reverse): PatternFrame {
  for (const mirrored of [false, true]) {
    for (let o = 0; o < 3; o++) {
      const f = mirrored ? makeFrame(o, (o + 2) % 3, (o + 1) % 3, reverse, true) : makeFrame(o, (o + 1) % 3, (o + 2) % 3, reverse, false);
      if (f.flipLeft) return f;
    }
  }
  throw new Error('unreachable: every edge points at one of its corners');
}

/** A point of the frame, (u, v) in fixed point. */
export type FramePoint = readonly [number, number];

/** Twice-squared distance halved (|Δ|/2 per axis, squared): exact in u32 on the GPU. */
function halfDist2(p: FramePoint, q: FramePoint): number {
  const du = (q[0] - p[0]) >> 1,
    dv = (q[1] - p[1]) >> 1;
  return du * du + dv * dv;
}

/** A vector scaled down to at most 5 significant bits (|components| ≤ 32) by a power of two
 * (arithmetic shift, as WGSL's >> on i32): its direction to about 2°, in numbers small enough
 * that obtuseAt's products stay below 2^31. */
function coarse(du: number, dv: number): [number, number] {
  const shift = Math.max(0, 32 - Math.clz32(Math.max(Math.abs(du), Math.abs(dv))) - 5);
  return [du >> shift, dv >> shift];
}

/** How obtuse the angle at p is: 0 up to 150°, 1 above 150°, 2 above 165°, 3 above 175°
 * (cos² above 3/4, 14/15, 130/131). 0 for a zero-length side. */
function obtuseAt(p: FramePoint, q: FramePoint, r: FramePoint): number {
  const [au, av] = coarse(q[0] - p[0], q[1] - p[1]);
  const [bu, bv] = coarse(r[0] - p[0], r[1] - p[1]);
  const dot = au * bu + av * bv;
  if (dot >= 0) return 0;
  const d2 = dot * dot; // ≤ 2^22
  const n2 = (au * au + av * av) * (bu * bu + bv * bv); // ≤ 2^22, so 131·n2 < 2^31
  return (4 * d2 > 3 * n2 ? 1 : 0) + (15 * d2 > 14 * n2 ? 1 : 0) + (131 * d2 > 130 * n2 ? 1 : 0);
}

/**
 * How much triangle p q r is a CAP (0: not; 1-3: its largest angle is above 150°, 165°, 175°):
 * three distinct vertices nearly on one line. Flat in the domain, such a triangle is not flat
 * on a curved surface: its vertices lie on a curve (a cage edge, the clamp line) and the flat
 * triangle through them stands across the surface (a fin) or folds under it, whatever its side
 * lengths. A NEEDLE (a vertex close to another, as at a point's birth, off the line of the
 * third) is harmless and is not a cap. The angle is judged from each side's direction alone
 * (coarse), in integers that fit i32, so wgsl/tess/pattern.wgsl computes the same answer.
 */
export function capLevel(p: FramePoint, q: FramePoint, r: FramePoint): number {
  return Math.max(obtuseAt(p, q, r), obtuseAt(q, r, p), obtuseAt(r, p, q));
}

/**
 * The gap matching: triangulate the strip between the inner chain I_0..I_nI (the bottom's last
 * point, back along the bottom edge to the first point at or past the clamp line, then
 * E_1..E_nl = C) and the outer chain O_0..O_nO (B, the right edge, C), both ending at C. From
 * the front edge I_a–O_b each move cuts one triangle off what is left of the (convex) strip:
 *   inner  (I_a, O_b, I_{a+1}),  then a = a + 1
 *   outer  (I_a, O_b, O_{b+1}),  then b = b + 1
 * nI + nO moves; the last one closes at C and is not a triangle. Every triangle is three
 * consecutive vertices of what is left of a convex polygon, so none is flipped.
 *
 * The choice is greedy, on the CURRENT positions, with one move of look-ahead: the move whose
 * triangle, and the best triangle after it, are the least of a cap (capLevel); then the
 * shorter new diagonal; then outer before inner. A chain may not reach C while the other has
 * more than one step to go if that would leave a fan of caps from C (gapMoveOk). At a power of
 * two this is the uniform grid's strip. The merge changes with the factors only where two
 * candidates tie, which moves the rendered surface by less than the strip's chord error; the
 * vertex set itself stays continuous (tested).
 *
 * Returns the moves (true = inner).
 */
export function gapMergeSteps(inner: readonly FramePoint[], outer: readonly FramePoint[]): boolean[] {
  const moves: boolean[] = [];
  let a = 0;
  let b = 0;
  for (let k = 0; k < inner.length + outer.length - 2; k++) {
    const inn = gapStepInner(inner, outer, a, b);
    moves.push(inn);
    if (inn) a++;
    else b++;
  }
  return moves;
}

/** May the gap matching advance the inner (or outer) chain from front edge I_a–O_b? */
export function gapMoveOk(
  inner: readonly FramePoint[],
  outer: readonly FramePoint[],
  a: number,
  b: number,
  advanceInner: boolean,
): boolean {
  const nI = inner.length - 1;
  const nO = outer.length - 1;
  if (advanceInner) {
    if (a === nI) return false;
    // Onto C with more than one outer step to go: the rest is a fan from C along the right
    // edge, caps unless its points coincide.
    return b === nO || !(a + 1 === nI && b + 1 < nO && capLevel(outer[nO - 2], outer[nO - 1], outer[nO]) > 0);
  }
  if (b === nO) return false;
  // Outer onto C with more than one inner step to go: the rest is a fan from C along the
  // inner chain's end, caps if that end is in line with C (a left edge).
  return a === nI || !(b + 1 === nO && a + 1 < nI && capLevel(inner[nI - 2], inner[nI - 1], inner[nI]) > 0);
}

/** The cap level of a move's triangle (0 for a move not allowed: callers check first). */
function moveLevel(inner: readonly FramePoint[], outer: readonly FramePoint[], a: number, b: number, advanceInner: boolean): number {
  return advanceInner ? capLevel(inner[a], outer[b], inner[a + 1]) : capLevel(inner[a], outer[b], outer[b + 1]);
}

/** The least cap level of the moves allowed at (a, b) (0 where none is: the end). */
function bestLevel(inner: readonly FramePoint[], outer: readonly FramePoint[], a: number, b: number): number {
  let best = 4;
  if (gapMoveOk(inner, outer, a, b, true)) best = Math.min(best, moveLevel(inner, outer, a, b, true));
  if (gapMoveOk(inner, outer, a, b, false)) best = Math.min(best, moveLevel(inner, outer, a, b, false));
  return best === 4 ? 0 : best;
}

/** One decision of the gap matching at front edge I_a–O_b: advance the inner chain? */
export function gapStepInner(inner: readonly FramePoint[], outer: readonly FramePoint[], a: number, b: number): boolean {
  const okInner = gapMoveOk(inner, outer, a, b, true);
  const okOuter = gapMoveOk(inner, outer, a, b, false);
  if (!okInner) return false;
  if (!okOuter) return true;
  const li = moveLevel(inner, outer, a, b, true);
  const lo = moveLevel(inner, outer, a, b, false);
  const si = Math.max(li, bestLevel(inner, outer, a + 1, b));
  const so = Math.max(lo, bestLevel(inner, outer, a, b + 1));
  if (si !== so) return si < so;
  if (li !== lo) return li < lo;
  return halfDist2(outer[b], inner[a + 1]) < halfDist2(inner[a], outer[b + 1]);
}

/**
 * Columns row 0 keeps in the grid: the bottom points before the clamp line and the first one at
 * or past it (k_0 = #{u_i < c} ≤ nb − 1, since c ≤ u_{nb−1}); the rest are the gap strip's. A
 * strip too large for the exact triangulation with a single right segment can only be fanned
 * from B and C by the greedy, and a bottom tail there would be a fan of caps from B: then the
 * bottom stays in the grid (k_0 = nb − 1, fanned from E_1).
 */
export function rowZeroKept(bottom: readonly number[], nl: number, nr: number, c: number): number {
  const nb = bottom.length - 1;
  let k0 = 0;
  while (bottom[k0] < c) k0++;
  if (nr === 1 && nb - 1 - k0 + nl + nr + 1 > STRIP_DP_VERTICES) k0 = nb - 1;
  return k0;
}

/** Strips of at most this many vertices are triangulated exactly (stripTriangulation); larger
 * ones by the greedy gap matching. At most 16: the GPU stores a polygon index in 4 bits (the
 * WGSL reads the number from src/gpu/contract/tess.ts TESS_CONSTANTS). 8, not 16: on the cameras of
 * tests/gpu/tess/no-folds.test.ts 16 folds no fewer triangles (on 12 other seeded cameras it took the
 * creased box from 5 to 0), and the plan pass's O(n³) search cost about twice as much on
 * SwiftShader. */
export const STRIP_DP_VERTICES = 8;

/** 1024·tan φ for φ = 30°, 15°, 8°, 4°, 2°, 1° (rounded): angleLevel's thresholds 180° − φ. */
const TAN_1024 = [591, 274, 144, 72, 36, 18];

/** A vector scaled down to at most 8 significant bits (|components| ≤ 255) by a power of two. */
function coarse8(du: number, dv: number): [number, number] {
  const shift = Math.max(0, 32 - Math.clz32(Math.max(Math.abs(du), Math.abs(dv))) - 8);
  return [du >> shift, dv >> shift];
}

/**
 * How close to 180° the largest angle of triangle p q r is: the number of the thresholds 150°,
 * 165°, 172°, 176°, 178°, 179° it passes (0..6; 0 for a zero-length side, which is a degenerate
 * triangle, not a cap). At a vertex with sides a, b it tests |a × b|·1024 < 1024·tan φ·(−a·b) on
 * the sides' directions to 8 bits: every product is below 2^27, so the WGSL gets the same in i32.
 */
export function angleLevel(p: FramePoint, q: FramePoint, r: FramePoint): number {
  return Math.max(angleLevelAt(p, q, r), angleLevelAt(q, r, p), angleLevelAt(r, p, q));
}

function angleLevelAt(o: FramePoint, x: FramePoint, y: FramePoint): number {
  const [au, av] = coarse8(x[0] - o[0], x[1] - o[1]);
  const [bu, bv] = coarse8(y[0] - o[0], y[1] - o[1]);
  const dot = au * bu + av * bv;
  if (dot >= 0 || (au === 0 && av === 0) || (bu === 0 && bv === 0)) return 0;
  const cross = Math.abs(au * bv - av * bu) * 1024;
  let level = 0;
  for (const t of TAN_1024) if (cross < t * -dot) level++;
  return level;
}

/**
 * The exact triangulation of a small gap strip: the polygon's points in order around it (the
 * strip is convex, walked clockwise in the frame), triangulated to the least Σ 16^angleLevel
 * over its triangles (so the flattest cap counts most: almost the least largest angle) by the
 * usual interval recursion, the first best split on ties. Unlike the greedy it may join two
 * points of one chain, which is what a strip with few right points and a corner-born point needs
 * (a cap whichever way a chain merge goes). The triangles (i, j, m), polygon indices with
 * i < m < j (positive in the frame), in the order of a depth-first walk from (0, n − 1), lower
 * half first: the order wgsl/tess/plan.wgsl stores them in.
 */
export function stripTriangulation(pts: readonly FramePoint[]): [number, number, number][] {
  const n = pts.length;
  const cost = new Array<number>(n * n).fill(0);
  const split = new Array<number>(n * n).fill(0);
  for (let len = 2; len < n; len++) {
    for (let i = 0; i + len < n; i++) {
      const j = i + len;
      let best = Number.POSITIVE_INFINITY;
      for (let m = i + 1; m < j; m++) {
        const cst = cost[i * n + m] + cost[m * n + j] + 2 ** (4 * angleLevel(pts[i], pts[j], pts[m]));
        if (cst < best) {
          best = cst;
          split[i * n + j] = m;
        }
      }
      cost[i * n + j] = best;
    }
  }
  const out: [number, number, number][] = [];
  const stack: [number, number][] = [[0, n - 1]];
  while (stack.length) {
    const [i, j] = stack.pop() as [number, number];
    if (j - i < 2) continue;
    const m = split[i * n + j];
    out.push([i, j, m]);
    stack.push([m, j], [i, m]);
  }
  return out;
}

/** A line's gap at its far end: the larger of its last two segments (ONE for one segment). */
export function endGap(x: number[]): number {
  const n = x.length - 1;
  if (n < 2) return ONE;
  return Math.max(x[n] - x[n - 1], x[n - 1] - x[n - 2]);
}

/** A pattern in its frame, with what the diagrams draw of the construction. */
export interface ClampedAssembly extends TriPattern {
  /** The clamp line u + v = c (fixed point). */
  c: number;
  /** Triangles [0, gridTriangleCount) are the clamped grid, the rest the gap strip. */
  gridTriangleCount: number;
}

/** Build the pattern from the three framed lines (positions in the frame, ascending). */
export function assembleClamped(bottom: number[], left: number[], right: number[]): ClampedAssembly {
  const nb = bottom.length - 1;
  const nl = left.length - 1;
  const nr = right.length - 1;
  const c = ONE - Math.max(endGap(bottom), endGap(left));

  // Rows: k[j] kept columns and the row's end u (E_j; for row 0 the first bottom point at or
  // past the clamp line, u_{k_0}).
  const k = new Array<number>(nl + 1);
  const end = new Array<number>(nl + 1);
  k[0] = rowZeroKept(bottom, nl, nr, c);
  end[0] = bottom[k[0]];
  for (let j = 1; j <= nl; j++) {
    const e = Math.max(0, c - left[j]);
    let kept = 0;
    while (kept < nb && bottom[kept] < e) kept++; // bottom is sorted
    k[j] = kept;
    end[j] = e;
  }
  // Row 0 holds every bottom point but B (u_0..u_{nb−1}); the ones past u_{k_0} are the
  // inner chain's tail. Rows j ≥ 1 hold their k_j kept columns and their end.
  const base = new Array<number>(nl + 2);
  base[0] = 0;
  base[1] = nb;
  for (let j = 1; j <= nl; j++) base[j + 1] = base[j] + k[j] + 1;

  const bary: number[] = [];
  for (let j = 0; j <= nl; j++) {
    const v = left[j];
    const cols = j === 0 ? nb - 1 : k[j];
    for (let col = 0; col <= cols; col++) {
      const u = j === 0 || col < k[j] ? bottom[col] : end[j];
      bary.push(ONE - u - v, u, v);
    }
  }
  const B = base[nl + 1];
  bary.push(0, ONE, 0);
  for (let q = 1; q < nr; q++) bary.push(0, ONE - right[q], right[q]);

  const tris: number[] = [];
  const at = (j: number, col: number) => base[j] + Math.min(col, k[j]);
  for (let j = 0; j < nl; j++) {
    for (let i = 0; i < nb - 1; i++) {
      if (i < k[j]) tris.push(at(j, i), at(j, i + 1), at(j + 1, i + 1));
      if (i < k[j + 1]) tris.push(at(j, i), at(j + 1, i + 1), at(j + 1, i));
    }
  }

  const gridTriangleCount = tris.length / 3;
  const C = base[nl]; // row nl is the single vertex C
  // Inner chain: u_{nb−1} back to u_{k_0} (tail = nb − 1 − k_0 points before u_{k_0}), then E_1..E_nl.
  const tail = nb - 1 - k[0];
  const inner = (a: number) => (a <= tail ? base[0] + nb - 1 - a : base[a - tail] + k[a - tail]);
  const outer = (b: number) => (b === 0 ? B : b === nr ? C : B + b);
  const nI = tail + nl;
  const at2 = (v: number): FramePoint => [bary[3 * v + 1], bary[3 * v + 2]];
  const innerPts = Array.from({ length: nI + 1 }, (_, a) => at2(inner(a)));
  const outerPts = Array.from({ length: nr + 1 }, (_, b) => at2(outer(b)));
  if (nI + nr + 1 <= STRIP_DP_VERTICES) {
    // A small strip: the best triangulation of the whole polygon (I_0..I_nI = C, then O_{nr−1}..O_1, B).
    const poly = (p: number) => (p <= nI ? inner(p) : outer(nr - (p - nI)));
    const pts = Array.from({ length: nI + nr + 1 }, (_, p) => at2(poly(p)));
    for (const [i, j, m] of stripTriangulation(pts)) tris.push(poly(i), poly(j), poly(m));
  } else {
    let a = 0;
    let b = 0;
    for (const advanceInner of gapMergeSteps(innerPts, outerPts)) {
      const t = advanceInner ? [inner(a), outer(b), inner(++a)] : [inner(a), outer(b), outer(++b)];
      if (t[0] === t[1] || t[1] === t[2] || t[0] === t[2]) continue; // the last move, closing at C
      tris.push(t[0], t[1], t[2]);
    }
  }

  return { bary, triangles: tris, vertexCount: bary.length / 3, triangleCount: tris.length / 3, c, gridTriangleCount };
}

export interface ClampedOptions {
  /** Largest factor (a power of two, 2..256). Default 64. */
  maxFactor?: number;
}

/** The three framed lines of a triangle at the given factors (the pattern's only inputs). */
export function clampedLines(
  factors: readonly [number, number, number],
  frame: PatternFrame,
  opts: ClampedOptions = {},
): { bottom: FramedLine; left: FramedLine; right: FramedLine } {
  const maxFactor = opts.maxFactor ?? MAX_FACTOR;
  const slots = cachedSlots(maxFactor, HABLE_OPTIONS);
  const edge = (i: number, flip: boolean) => {
    const F = stableFactorFixed(factors[i], maxFactor);
    return framedLine(slots, presentSlots(slots, F), F, flip);
  };
  return {
    bottom: edge(frame.bottomEdge, frame.flipBottom),
    left: edge(frame.leftEdge, frame.flipLeft),
    right: edge(frame.rightEdge, frame.flipRight),
  };
}

/** Move a pattern built in a frame to the triangle's corners: (w_A, w_B, w_C) → corners
 * (a, b, c), and reverse the winding of a mirrored frame. */
export function fromFrame(p: TriPattern, frame: PatternFrame): TriPattern {
  const bary = new Array<number>(p.bary.length);
  for (let v = 0; v < p.vertexCount; v++) {
    bary[3 * v + frame.a] = p.bary[3 * v];
    bary[3 * v + frame.b] = p.bary[3 * v + 1];
    bary[3 * v + frame.c] = p.bary[3 * v + 2];
  }
  const triangles = p.triangles.slice();
  if (frame.mirrored) {
    for (let t = 0; t < triangles.length; t += 3) [triangles[t + 1], triangles[t + 2]] = [triangles[t + 2], triangles[t + 1]];
  }
  return { bary, triangles, vertexCount: p.vertexCount, triangleCount: p.triangleCount };
}

/** Every stage of the construction, for the diagrams: the frame, the three framed lines, and
 * the pattern in frame coordinates (w_A, w_B, w_C) with its clamp line and grid/gap split. */
export function clampedConstruction(
  factors: readonly [number, number, number],
  reverse: Reverse = FORWARD,
  opts: ClampedOptions = {},
): { frame: PatternFrame; bottom: FramedLine; left: FramedLine; right: FramedLine; framed: ClampedAssembly } {
  const frame = chooseFrame(reverse);
  const lines = clampedLines(factors, frame, opts);
  const framed = assembleClamped(lines.bottom.x, lines.left.x, lines.right.x);
  return { frame, ...lines, framed };
}

/** The clamped-parallelogram pattern for edge factors (f0, f1, f2), factor i on edge i. */
export function clampedTriangle(
  factors: readonly [number, number, number],
  reverse: Reverse = FORWARD,
  opts: ClampedOptions = {},
): TriPattern {
  const { frame, framed } = clampedConstruction(factors, reverse, opts);
  return fromFrame(framed, frame);
}
