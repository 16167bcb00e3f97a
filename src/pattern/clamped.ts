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
 *      itself, u_0..u_{nb−1}, never clamped, so no edge vertex ever moves; row nl is corner C.
 *      Between rows j and j+1, column i gives a "lower" triangle if i < k_j and an "upper"
 *      one if i < k_{j+1} (k_j = columns kept in row j), so a quad disappears exactly when it
 *      has collapsed: the pattern changes only through zero-area triangles.
 *   4. Gap strip: what is left, between the inner chain P = (u_{nb−1}, 0), E_1, …, E_nl = C and
 *      the right edge B = O_0, O_1, …, O_nr = C, is a convex polygon (shown in the notes of
 *      tests/clamped.test.ts), so any monotone merge of the two chains triangulates it without a
 *      flip. The merge ("gap matching") compares FINAL positions: every point of a line has a
 *      place on the power-of-two grid where its slide ends, and the chains are merged by that
 *      place (right edge first on a tie). The final places do not change while points slide,
 *      so the matching changes only when a point is born or dies, and then by a single
 *      zero-area triangle. At powers of two it reproduces the uniform grid.
 *
 * Hable adds a centre point while the left factor is below 2 because his parallelogram breaks
 * while the left edge's points slide in from both ends. Here every sliding left point simply
 * gets its own row (the rows may be in any position), so no centre point is needed: the
 * pattern is the single triangle at (1,1,1) and grows continuously from there.
 *
 * Vertex order (in the frame): row 0, row 1, …, row nl (= C), then B, then O_1..O_{nr−1}.
 */
import { ONE } from './fixed.ts';
import { HABLE_OPTIONS, cachedSlots, presentSlots, slotPosition, stableFactorFixed, type Slot } from './hable-line.ts';
import type { TriPattern } from './types.ts';

export type Reverse = readonly [boolean, boolean, boolean];
export const FORWARD: Reverse = [false, false, false];

/** One edge of the clamped pattern: points in the internal frame, ascending, plus the final
 * (end-of-slide) position of each point in the same frame: the key of the gap matching. */
export interface FramedLine {
  x: number[];
  key: number[];
}

/** The points of one edge line at F, already mapped to the frame coordinate:
 * `flip` = the frame runs against the line's own direction (coordinate = ONE − x). */
export function framedLine(slots: Slot[], present: number[], F: number, flip: boolean): FramedLine {
  const x = present.map((i) => slotPosition(slots[i], F));
  const key = present.map((i) => slots[i].x1);
  if (!flip) return { x, key };
  return { x: x.map((v) => ONE - v).reverse(), key: key.map((v) => ONE - v).reverse() };
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

/**
 * The gap matching: merge steps of the inner chain (P, E_1..E_nl) and the outer chain
 * (B, O_1..O_nr), true = advance the inner chain. `leftKey` and `rightKey` are the final
 * positions (in v) of the left and right lines, 0 first and ONE last.
 */
export function gapMergeSteps(leftKey: number[], rightKey: number[]): boolean[] {
  const nl = leftKey.length - 1;
  const nr = rightKey.length - 1;
  const steps: boolean[] = [];
  let a = 0;
  let b = 0;
  while (a < nl || b < nr) {
    const advanceOuter = b < nr && (a === nl || rightKey[b + 1] <= leftKey[a + 1]);
    steps.push(!advanceOuter);
    if (advanceOuter) b++;
    else a++;
  }
  return steps;
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

/** Build the pattern from the three framed lines and the merge steps. */
export function assembleClamped(bottom: number[], left: number[], right: number[], merge: boolean[]): ClampedAssembly {
  const nb = bottom.length - 1;
  const nl = left.length - 1;
  const nr = right.length - 1;
  const c = ONE - Math.max(endGap(bottom), endGap(left));

  // Rows: k[j] kept columns and the row's end u (E_j; for row 0 it is P = u_{nb−1}).
  const k = new Array<number>(nl + 1);
  const end = new Array<number>(nl + 1);
  k[0] = nb - 1;
  end[0] = bottom[nb - 1];
  for (let j = 1; j <= nl; j++) {
    const e = Math.max(0, c - left[j]);
    let kept = 0;
    while (kept < nb && bottom[kept] < e) kept++; // bottom is sorted
    k[j] = kept;
    end[j] = e;
  }
  const base = new Array<number>(nl + 2);
  base[0] = 0;
  for (let j = 0; j <= nl; j++) base[j + 1] = base[j] + k[j] + 1;

  const bary: number[] = [];
  for (let j = 0; j <= nl; j++) {
    const v = left[j];
    for (let col = 0; col <= k[j]; col++) {
      const u = col < k[j] ? bottom[col] : end[j];
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
  const inner = (a: number) => base[a] + k[a];
  const outer = (b: number) => (b === 0 ? B : b === nr ? C : B + b);
  let a = 0;
  let b = 0;
  for (const advanceInner of merge) {
    const t = advanceInner ? [inner(a), outer(b), inner(a + 1)] : [inner(a), outer(b), outer(b + 1)];
    if (advanceInner) a++;
    else b++;
    if (t[0] === t[1] || t[1] === t[2] || t[0] === t[2]) continue; // the one step that closes at C
    tris.push(t[0], t[1], t[2]);
  }
  if (a !== nl || b !== nr) throw new Error(`gap merge ended at (${a}, ${b}), expected (${nl}, ${nr})`);

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
  const maxFactor = opts.maxFactor ?? 64;
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
  const framed = assembleClamped(lines.bottom.x, lines.left.x, lines.right.x, gapMergeSteps(lines.left.key, lines.right.key));
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
