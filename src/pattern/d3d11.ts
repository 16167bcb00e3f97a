/**
 * The Direct3D 11 fixed-function tessellator's partitionings (integer, pow2, fractional_odd,
 * fractional_even) for the isoline and the triangle domain, bit-exact against the hardware
 * reference class `CHWTessellator` of Microsoft's "D3D11 Fixed Function Tessellator Reference"
 * (checked by `npm run check:golden` against the golden data in shared/golden).
 *
 * This is an independent implementation written from the algorithm as Microsoft's reference
 * and the D3D11.3 functional specification (§11.7, the tessellator) describe it; the structure and
 * names are ours.
 *
 * D3D11's conventions, kept as they are:
 * - Triangle domain: barycentric (u, v, w) with w = ONE − u − v. Edge factor 0 belongs to the
 *   U==0 edge (V corner → W corner), factor 1 to the V==0 edge (W → U), factor 2 to the W==0
 *   edge (U → V).
 * - Point order: the outer ring first, clockwise from the V corner (0, 1): the U==0 edge with V
 *   decreasing, the V==0 edge with U increasing, the W==0 edge with U decreasing; each side
 *   stops before its end point, which starts the next side. The interior rings follow in the
 *   same order, spiralling in; with even inside parity the last point is the centre
 *   (0x5555, 0x5555), so its w is 0x5556.
 * - Triangles in the reference's emission order (ring by ring, side by side) with its
 *   TRIANGLE_CW index order: with u as x and v as y every non-degenerate triangle has a positive
 *   signed area (but for the hairline quirks below).
 * - The isoline is `TessellateIsoLineDomain(density 1, detail f)`: the points of the v = 0 line.
 *
 * Arithmetic:
 * - Float32 first: every input factor is first rounded to the nearest float32
 *   (`Math.fround`), as the reference takes `float`s. Culling (`!(f > 0)`), clamping to the
 *   partitioning's range (NaN goes to the lower bound by D3D's min/max rules), `ceil` for
 *   integer/pow2, the fractional_odd "picture frame" test (an edge above 1 + 2⁻¹⁷) and the pow2
 *   round-up all happen on that float32 value (exact in a double).
 * - The clamped float32 is then converted to 16.16 fixed point, ties to even (`factorToFixed`).
 * - Everything after that is integer fixed-point arithmetic: 1/n comes from a 64-entry table of
 *   round(2^16 / n), the blend between the floor and ceiling distributions rounds half up, and
 *   points on the second half of an edge are exact mirrors ONE − x.
 *
 * Quirks of the reference that are reproduced, not fixed:
 * - New points are born on top of old ones, so just above an epoch two neighbours can be equal
 *   (zero-length segments, zero-area triangles).
 * - A fold in fractional_even: the reciprocal table rounds 1/6 and 1/30 up, so 3·(1/6) and
 *   15·(1/30) land past ½ (by 1 and 7 units). For 16.16 factors in (6, 6 + 6·2⁻¹⁶] and
 *   (30, 30 + 414·2⁻¹⁶] the point before the midpoint lies beyond it and the row is not
 *   monotone. A triangle edge with such a factor gets two hairline inverted triangles (doubled
 *   area up to ~2.4·2¹⁶ units², the domain's being 2³²); as the inside factor it folds every
 *   ring side. fractional_odd and integer never fold.
 * - Hairline slivers in both fractional modes: while a newborn pair is still within a few units
 *   of its twin (a factor up to ~0.02 above an epoch), projecting it onto an interior ring
 *   (⅔ of x_r and half of that as a shift, each rounded) can make a ring corner non-convex by
 *   a unit, and a transition or ring triangle comes out inverted, with a doubled area of at
 *   most ~1.4·2¹⁶ units² in our scans. Integer and pow2 were never seen to invert a triangle.
 * - The forced fractional_odd picture frame (inside ≤ 1 with some edge > 1) puts the first
 *   ring exactly on the three corners: duplicate positions and zero-area transition triangles.
 */
import { D3D11_MAX_FACTOR } from './max-factor.ts';
import { ONE, factorToFixed } from './fixed';
import type { D3D11Partitioning, LinePattern, TriPattern } from './types';

type Parity = 'even' | 'odd';

const HALF = ONE >> 1; // 0x8000
const ONE_THIRD = Math.floor(ONE / 3); // 0x5555
const TWO_THIRDS = Math.floor((2 * ONE) / 3); // 0xaaaa

/** Fixed-point reciprocals 1/n for n = 1…64, as round(2^16 / n) (no ties occur). */
const RECIPROCAL: readonly number[] = Array.from({ length: D3D11_MAX_FACTOR + 1 }, (_, n) => (n === 0 ? 0 : Math.round(ONE / n)));

/**
 * Ruler-function birth order of the 33 slots of a fully refined half-edge (32 segments):
 * slot 0 is the corner (born first); slot s ≥ 1, with s − 1 = 2^t · m (m odd), is born at
 * 2^(4−t) + (m − 1)/2; slot 1 (s − 1 = 0) is born last, as number 32. A row whose half-edge
 * holds h points contains exactly the slots born before h. Walking the slots in spatial order
 * and advancing whichever row owns the slot is how the transition band is stitched.
 */
export const RULER_BIRTH_ORDER: readonly number[] = Array.from({ length: 33 }, (_, s) => {
  if (s === 0) return 0;
  const j = s - 1;
  if (j === 0) return 32;
  let t = 0;
  let m = j;
  while (m % 2 === 0) {
    m /= 2;
    t++;
  }
  return (1 << (4 - t)) + (m - 1) / 2;
});

/** Clears the highest set bit (0 stays 0). */
function clearTopBit(x: number): number {
  if (x <= 0) return 0;
  return x - 2 ** Math.floor(Math.log2(x));
}

/** What a processed factor means for the placement of points along one edge. */
interface Spacing {
  parity: Parity;
  /** Points on the half-edge, not counting the even midpoint. */
  halfPoints: number;
  /** Fractional part of the half factor, 16.16 (0 at an exact epoch). */
  frac: number;
  /** Half-edge index after which the floor distribution lags one point behind. */
  split: number;
  invFloor: number;
  invCeil: number;
  /** Points on the whole edge, ends included. */
  points: number;
}

/** Splits the 16.16 factor into its floor/ceiling half-edge distributions. */
function makeSpacing(fixed: number, parity: Parity): Spacing {
  const odd = parity === 'odd';
  let half = Math.floor((fixed + 1) / 2);
  // An even factor of 1 (integer inside factor 1) is laid out as if it were odd.
  if (odd || half === HALF) half += HALF;
  const lo = half - (half % ONE);
  const hi = half % ONE === 0 ? half : lo + ONE;
  const loInt = lo / ONE;
  const hiInt = hi / ONE;
  let split: number;
  if (lo === hi)
    split = hiInt + 1; // never reached: no split in progress
  else if (odd) split = loInt === 1 ? 0 : 2 * clearTopBit(loInt - 1) + 1;
  else split = 2 * clearTopBit(loInt) + 1;
  const segLo = 2 * loInt - (odd ? 1 : 0);
  const segHi = 2 * hiInt - (odd ? 1 : 0);
  const halfFactor = Math.floor((fixed + 1) / 2);
  const points = odd ? 2 * Math.ceil((HALF + halfFactor) / ONE) : 2 * Math.ceil(halfFactor / ONE) + 1;
  return {
    parity,
    halfPoints: hiInt,
    frac: half - lo,
    split,
    invFloor: RECIPROCAL[segLo],
    invCeil: RECIPROCAL[segHi],
    points,
  };
}

/** Where point q (0 … points−1) of the edge lies: its half-edge index and whether it is mirrored. */
function halfEdgeIndex(sp: Spacing, q: number): { k: number; mirrored: boolean } {
  if (q < sp.halfPoints) return { k: q, mirrored: false };
  return { k: 2 * sp.halfPoints - q - (sp.parity === 'odd' ? 1 : 0), mirrored: true };
}

/** 16.16 position of point q on the edge. */
function placePoint(sp: Spacing, q: number): number {
  const { k, mirrored } = halfEdgeIndex(sp, q);
  if (k === sp.halfPoints) return HALF; // the even midpoint, exact
  const kLo = k > sp.split ? k - 1 : k;
  const onLo = kLo * sp.invFloor;
  const onHi = k * sp.invCeil;
  // Products stay below 2^32, so doubles are exact; round half up, then drop 16 bits.
  const x = Math.floor((onLo * (ONE - sp.frac) + onHi * sp.frac + HALF) / ONE);
  return mirrored ? ONE - x : x;
}

// ---------------------------------------------------------------------------------------------
// Factor processing (float32 stage)
// ---------------------------------------------------------------------------------------------

function bounds(p: D3D11Partitioning): [number, number] {
  if (p === 'fractional_odd') return [1, 63];
  if (p === 'fractional_even') return [2, 64];
  return [1, 64];
}

const isIntegerLike = (p: D3D11Partitioning) => p === 'integer' || p === 'pow2';

/** D3D clamp: NaN and −∞ go to the lower bound, +∞ to the upper. Inputs are float32 values. */
function clampFactor(f: number, lo: number, hi: number): number {
  if (Number.isNaN(f)) return lo;
  return Math.min(hi, Math.max(lo, f));
}

/**
 * The HLSL-side pow2 rule: clean to [1, ∞) (NaN → 1), then round up to a power of two (a float
 * with a non-zero mantissa moves to the next exponent), then clamp to 64.
 */
function pow2RoundUp(f: number): number {
  const x = Number.isNaN(f) || f < 1 ? 1 : Math.min(f, D3D11_MAX_FACTOR);
  let p = 1;
  while (p < x) p *= 2;
  return p;
}

const isCulled = (f32: number) => !(f32 > 0);

interface EdgeFactor {
  fixed: number;
  parity: Parity;
}

/** An edge factor after culling (null), pow2 rounding, clamping and ceil; float32 in, 16.16 out. */
function processEdge(p: D3D11Partitioning, factor: number): (EdgeFactor & { f32: number }) | null {
  let f = Math.fround(factor);
  if (isCulled(f)) return null;
  if (p === 'pow2') f = pow2RoundUp(f);
  const [lo, hi] = bounds(p);
  f = clampFactor(f, lo, hi);
  let parity: Parity;
  if (isIntegerLike(p)) {
    f = Math.ceil(f);
    parity = f % 2 === 0 ? 'even' : 'odd';
  } else {
    parity = p === 'fractional_odd' ? 'odd' : 'even';
  }
  return { fixed: factorToFixed(f), parity, f32: f };
}

interface TriFactors {
  edges: [EdgeFactor, EdgeFactor, EdgeFactor];
  inside: EdgeFactor;
  /** Integer/pow2 or fractional_odd with every factor exactly 1: the single original triangle. */
  single: boolean;
}

/** Hardware factor processing for the triangle domain (null when culled). */
function processTri(p: D3D11Partitioning, factors: readonly [number, number, number], inside: number): TriFactors | null {
  const e0 = processEdge(p, factors[0]);
  const e1 = processEdge(p, factors[1]);
  const e2 = processEdge(p, factors[2]);
  if (!e0 || !e1 || !e2) return null;
  let [lo, hi] = bounds(p);
  let f = Math.fround(inside);
  if (p === 'pow2') f = pow2RoundUp(f);
  if (p === 'fractional_odd') {
    // Any edge that stays above 1 after fixed-point conversion forces a picture frame.
    const threshold = 1 + 2 ** -17;
    if (e0.f32 > threshold || e1.f32 > threshold || e2.f32 > threshold) lo = 1 + 2 ** -16;
  }
  f = clampFactor(f, lo, hi);
  let parity: Parity;
  if (isIntegerLike(p)) {
    f = Math.ceil(f);
    parity = f % 2 === 0 || f === 1 ? 'even' : 'odd';
  } else {
    parity = p === 'fractional_odd' ? 'odd' : 'even';
  }
  const insideFactor: EdgeFactor = { fixed: factorToFixed(f), parity };
  const edges: [EdgeFactor, EdgeFactor, EdgeFactor] = [e0, e1, e2];
  const single = p !== 'fractional_even' && insideFactor.fixed === ONE && edges.every((e) => e.fixed === ONE);
  return { edges, inside: insideFactor, single };
}

// ---------------------------------------------------------------------------------------------
// Closed forms (fitted for this project to the reference's counts; checked against it by
// tests/pattern/d3d11.test.ts), on the processed 16.16 values
// ---------------------------------------------------------------------------------------------

/** Segments for a processed factor: ⌈F⌉ (integer), 2⌈(F+1)/2⌉−1 (odd), 2⌈F/2⌉ (even). */
function segmentsOf(e: EdgeFactor): number {
  const f = e.fixed / ONE; // exact
  return e.parity === 'odd' ? 2 * Math.ceil((f + 1) / 2) - 1 : 2 * Math.ceil(f / 2);
}

/** Segments on an edge after clamping and rounding (0 if the factor culls). */
export function d3d11SegmentCount(partitioning: D3D11Partitioning, factor: number): number {
  const e = processEdge(partitioning, factor);
  return e ? segmentsOf(e) : 0;
}

/** Vertex and triangle counts of `d3d11Triangle`, in closed form. */
export function d3d11TriCounts(
  partitioning: D3D11Partitioning,
  factors: [number, number, number],
  inside: number,
): { vertexCount: number; triangleCount: number } {
  const tri = processTri(partitioning, factors, inside);
  if (!tri) return { vertexCount: 0, triangleCount: 0 };
  if (tri.single) return { vertexCount: 3, triangleCount: 1 };
  const outer = tri.edges.reduce((sum, e) => sum + segmentsOf(e), 0);
  // The inside needs at least one ring: 2 segments (even) or 3 (odd).
  const S = Math.max(segmentsOf(tri.inside), tri.inside.parity === 'odd' ? 3 : 2);
  const k = S - 2;
  const innerVertices = k % 2 === 0 ? 3 * (k / 2) * (k / 2 + 1) + 1 : 3 * ((k + 1) / 2) ** 2;
  const innerTriangles = Math.floor((3 * k * k) / 2);
  return { vertexCount: outer + innerVertices, triangleCount: outer + 3 * S - 6 + innerTriangles };
}

// ---------------------------------------------------------------------------------------------
// Isoline
// ---------------------------------------------------------------------------------------------

/**
 * The 1D distribution of `TessellateIsoLineDomain(1, f)`: 16.16 points in the reference's
 * order, empty if the factor culls (≤ 0 or NaN). That order is ascending (non-decreasing: a
 * newborn pair can coincide) except in the fractional_even fold windows just above 6 and 30
 * (see the file header), where it is kept as the reference emits it so that it stays identical
 * to the triangle edges. `moving` marks, for the fractional modes between epochs (a
 * non-zero fractional half factor), the pair being split apart at the ruler split point and
 * its mirror, i.e. half-edge points σ and σ+1 except the ones that never move (a corner, the
 * even midpoint). Integer and pow2 never move. pow2 first rounds the factor up to a power of
 * two (the HLSL-side rule) and is then integer.
 */
export function d3d11Line(partitioning: D3D11Partitioning, factor: number): LinePattern {
  const e = processEdge(partitioning, factor);
  if (!e) return { x: [], moving: [] };
  const sp = makeSpacing(e.fixed, e.parity);
  const fractional = !isIntegerLike(partitioning);
  const x: number[] = [];
  const moving: boolean[] = [];
  for (let q = 0; q < sp.points; q++) {
    x.push(placePoint(sp, q));
    const { k } = halfEdgeIndex(sp, q);
    const fixedPoint = k === 0 || (sp.parity === 'even' && k === sp.halfPoints);
    moving.push(fractional && sp.frac !== 0 && !fixedPoint && (k === sp.split || k === sp.split + 1));
  }
  return { x, moving };
}

// ---------------------------------------------------------------------------------------------
// Triangle domain
// ---------------------------------------------------------------------------------------------

/**
 * A closed ring of points stored consecutively from `start`, walked as three sides of `len[s]`
 * points each, consecutive sides sharing their end points; the last side ends on the ring's
 * first point. A ring of three one-point sides is the single centre point.
 */
class Ring {
  readonly start: number;
  readonly len: readonly [number, number, number];
  readonly size: number;
  constructor(start: number, len: readonly [number, number, number]) {
    this.start = start;
    this.len = len;
    this.size = len[0] + len[1] + len[2] - 3;
  }
  /** Global index of point j on side s. */
  at(s: number, j: number): number {
    let offset = j;
    for (let i = 0; i < s; i++) offset += this.len[i] - 1;
    return this.size === 0 ? this.start : this.start + (offset % this.size);
  }
}

/**
 * The band between an outer row (the patch edge) and the first ring's side: the rows are walked
 * together over the 33 ruler slots of a half-edge, each row advancing on the slots it owns, then
 * a middle piece set by the two parities, then the same walk mirrored.
 */
function stitchTransition(
  emit: (a: number, b: number, c: number) => void,
  out: (j: number) => number,
  outer: Spacing,
  inn: (j: number) => number,
  inner: Spacing,
): void {
  const hOut = outer.halfPoints - (outer.parity === 'odd' ? 1 : 0);
  const hIn = inner.halfPoints - (inner.parity === 'odd' ? 1 : 0);
  let o = 0;
  let i = 0;
  const advanceOut = () => {
    emit(out(o), out(o + 1), inn(i));
    o++;
  };
  const advanceIn = () => {
    emit(inn(i), out(o), inn(i + 1));
    i++;
  };
  const last = RULER_BIRTH_ORDER.length - 1;
  if (RULER_BIRTH_ORDER[0] < hOut) advanceOut();
  for (let s = 1; s <= last; s++) {
    if (RULER_BIRTH_ORDER[s] < hIn) advanceIn();
    if (RULER_BIRTH_ORDER[s] < hOut) advanceOut();
  }
  const outOdd = outer.parity === 'odd';
  const inOdd = inner.parity === 'odd';
  if (inOdd) advanceIn(); // both odd: a quad; inside odd only: a triangle pointing out
  if (outOdd) {
    // outside odd: the (second) triangle of the middle piece, starting from the inner row
    emit(inn(i), out(o), out(o + 1));
    o++;
  }
  for (let s = last; s >= 1; s--) {
    if (RULER_BIRTH_ORDER[s] < hOut) advanceOut();
    if (RULER_BIRTH_ORDER[s] < hIn) advanceIn();
  }
  if (RULER_BIRTH_ORDER[0] < hOut) advanceOut();
}

/**
 * The band between two regular rings: the outer side has k + 2 points, the inner side k. One
 * triangle at each end and a row of quads whose diagonals mirror at the middle.
 */
function stitchRegular(
  emit: (a: number, b: number, c: number) => void,
  out: (j: number) => number,
  inn: (j: number) => number,
  k: number,
): void {
  let o = 0;
  let i = 0;
  emit(out(o), out(o + 1), inn(i));
  o++;
  const halfway = Math.floor(k / 2);
  for (let p = 0; p < k - 1; p++, o++, i++) {
    if (p < halfway) {
      emit(out(o), inn(i + 1), inn(i));
      emit(out(o), out(o + 1), inn(i + 1));
    } else {
      emit(inn(i), out(o), out(o + 1));
      emit(inn(i), out(o + 1), inn(i + 1));
    }
  }
  emit(out(o), out(o + 1), inn(i));
}

/**
 * `CHWTessellator::TessellateTriDomain(e0, e1, e2, inside)` with TRIANGLE_CW output: the
 * reference's points (as u, v, w fixed-point triples) and triangles, in its order. pow2 rounds
 * the edges and the inside factor up to powers of two first and is then integer.
 */
export function d3d11Triangle(partitioning: D3D11Partitioning, factors: [number, number, number], inside: number): TriPattern {
  const tri = processTri(partitioning, factors, inside);
  if (!tri) return { bary: [], triangles: [], vertexCount: 0, triangleCount: 0 };
  const bary: number[] = [];
  const triangles: number[] = [];
  const addPoint = (u: number, v: number) => bary.push(u, v, ONE - u - v);
  const emit = (a: number, b: number, c: number) => triangles.push(a, b, c);

  if (tri.single) {
    addPoint(0, ONE); // V corner
    addPoint(0, 0); // W corner
    addPoint(ONE, 0); // U corner
    emit(0, 1, 2);
    return { bary, triangles, vertexCount: 3, triangleCount: 1 };
  }

  const edgeSp = tri.edges.map((e) => makeSpacing(e.fixed, e.parity));
  const inSp = makeSpacing(tri.inside.fixed, tri.inside.parity);
  const odd = inSp.parity === 'odd';
  // Points per side of the inside factor's full row; at least one ring is always made.
  const m = Math.max(inSp.points, odd ? 4 : 3);

  // Outer ring: each side without its end point.
  for (let s = 0; s < 3; s++) {
    const n = edgeSp[s].points;
    for (let p = 0; p < n - 1; p++) {
      const x = placePoint(edgeSp[s], s === 1 ? p : n - 1 - p);
      if (s === 0) addPoint(0, x);
      else if (s === 1) addPoint(x, 0);
      else addPoint(x, ONE - x);
    }
  }
  // Interior rings: ring r samples inside positions r … m−1−r, pushed in by 2/3 of x_r.
  for (let r = 1; r < m >> 1; r++) {
    const first = r;
    const lastQ = m - 1 - r;
    const perp = Math.floor((placePoint(inSp, r) * TWO_THIRDS + HALF) / ONE);
    const shift = Math.floor((perp + 1) / 2);
    for (let s = 0; s < 3; s++) {
      for (let p = 0; p < lastQ - first; p++) {
        const along = placePoint(inSp, s === 1 ? first + p : lastQ - p) - shift;
        if (s === 0) addPoint(perp, along);
        else if (s === 1) addPoint(along, perp);
        else addPoint(along, ONE - along - perp);
      }
    }
  }
  if (!odd) addPoint(ONE_THIRD, ONE_THIRD);

  // Connectivity, ring band by ring band.
  let outerRing = new Ring(0, [edgeSp[0].points, edgeSp[1].points, edgeSp[2].points]);
  for (let r = 1; r < (m + 1) >> 1; r++) {
    const k = m - 2 * r;
    const innerRing = new Ring(outerRing.start + outerRing.size, [k, k, k]);
    for (let s = 0; s < 3; s++) {
      const out = (j: number) => outerRing.at(s, j);
      const inn = (j: number) => innerRing.at(s, j);
      if (r === 1) stitchTransition(emit, out, edgeSp[s], inn, inSp);
      else stitchRegular(emit, out, inn, k);
    }
    outerRing = innerRing;
  }
  if (odd) emit(outerRing.start, outerRing.start + 1, outerRing.start + 2);

  return { bary, triangles, vertexCount: bary.length / 3, triangleCount: triangles.length / 3 };
}
