/**
 * Power-of-two patterns and the T-junction snap (src/pattern/pow2.ts), held in exact
 * integer arithmetic to: counts, coverage, orientation;
 * every (P, Le) snapped boundary equals {j/Le}; the two sides of an edge agree; no flipped
 * triangle; exactly P − Le collapsed boundary triangles per edge.
 */
import { describe, it, expect } from 'vitest';
import {
  POW2_LEVELS,
  pow2Pattern,
  snapEdgeParam,
  snapVertex,
  vertexEdges,
  packPatterns,
  patternVertexCount,
  patternTriangleCount,
  type PatchDomain,
  type Pow2Pattern,
} from '../../src/pattern/pow2.ts';

const DOMAINS: PatchDomain[] = ['quad', 'tri'];
const EDGES = { quad: 4, tri: 3 } as const;

/** Twice the signed area of triangle t over points xy (integers: exact). */
function area2(xy: ArrayLike<number>, idx: ArrayLike<number>, t: number): number {
  const [a, b, c] = [idx[3 * t], idx[3 * t + 1], idx[3 * t + 2]];
  return (xy[2 * b] - xy[2 * a]) * (xy[2 * c + 1] - xy[2 * a + 1]) - (xy[2 * b + 1] - xy[2 * a + 1]) * (xy[2 * c] - xy[2 * a]);
}

function snapped(p: Pow2Pattern, levels: number[], canonical: boolean[]): Int32Array {
  const xy = new Int32Array(p.ij.length);
  for (let v = 0; v < p.ij.length / 2; v++) xy.set(snapVertex(p.domain, p.level, p.ij[2 * v], p.ij[2 * v + 1], levels, canonical), 2 * v);
  return xy;
}

/** Edge membership of every pattern vertex (bit e: on edge e), cached per pattern. */
const membership = new Map<Pow2Pattern, Uint8Array>();
function edgeBits(p: Pow2Pattern): Uint8Array {
  let m = membership.get(p);
  if (!m) {
    m = new Uint8Array(p.ij.length / 2);
    for (let v = 0; v < m.length; v++)
      for (const { edge } of vertexEdges(p.domain, p.level, p.ij[2 * v], p.ij[2 * v + 1])) m[v] |= 1 << edge;
    membership.set(p, m);
  }
  return m;
}

/**
 * Run every snap check (edge sets, canonical agreement, orientation, degenerates) on one pattern under
 * one assignment of edge levels and directions.
 */
function checkSnap(p: Pow2Pattern, levels: number[], canonical: boolean[]): void {
  const P = p.level;
  const xy = snapped(p, levels, canonical);
  const bits = edgeBits(p);
  const nT = p.indices.length / 3;
  const collapsedBoundary = new Array<boolean>(nT).fill(false);
  for (let e = 0; e < levels.length; e++) {
    const Le = levels[e],
      R = P / Le;
    // The snapped boundary is exactly {jR}: as a set of edge parameters.
    const params = new Set<number>();
    for (let v = 0; v < bits.length; v++) {
      if (!(bits[v] & (1 << e))) continue;
      const after = vertexEdges(p.domain, P, xy[2 * v], xy[2 * v + 1]).find((x) => x.edge === e);
      if (!after) throw new Error(`vertex ${v} left edge ${e}`);
      params.add(after.t);
    }
    expect([...params].sort((a, b) => a - b)).toEqual(Array.from({ length: Le + 1 }, (_, j) => j * R));
    // Triangles with a side on edge e: P of them, P − Le collapsed to a point.
    let sides = 0,
      collapsed = 0;
    for (let t = 0; t < nT; t++) {
      for (let s = 0; s < 3; s++) {
        const a = p.indices[3 * t + s],
          b = p.indices[3 * t + ((s + 1) % 3)];
        if (!(bits[a] & bits[b] & (1 << e))) continue;
        sides++;
        if (xy[2 * a] === xy[2 * b] && xy[2 * a + 1] === xy[2 * b + 1]) {
          collapsed++;
          collapsedBoundary[t] = true;
        }
      }
    }
    expect(sides).toBe(P);
    expect(collapsed).toBe(P - Le);
  }
  for (let t = 0; t < nT; t++) {
    const a = area2(xy, p.indices, t);
    if (a < 0) throw new Error(`triangle ${t} flipped (P ${P}, levels ${levels}, canonical ${canonical})`);
    if (collapsedBoundary[t]) expect(a).toBe(0);
    // Nothing else degenerates, except a triangle whose three vertices all lie on the boundary
    // (the centre triangle of the level-2 triangle pattern, when two of them meet at a corner).
    else if (a === 0) expect([0, 1, 2].every((s) => bits[p.indices[3 * t + s]] !== 0)).toBe(true);
  }
}

describe('power-of-two patterns', () => {
  for (const domain of DOMAINS) {
    it(`${domain}: counts, indices in range, counter-clockwise, covering the domain`, () => {
      for (const L of POW2_LEVELS) {
        const p = pow2Pattern(domain, L);
        const nV = p.ij.length / 2,
          nT = p.indices.length / 3;
        expect(nV).toBe(domain === 'quad' ? (L + 1) ** 2 : ((L + 1) * (L + 2)) / 2);
        expect(nT).toBe(domain === 'quad' ? 2 * L * L : L * L);
        expect(nV).toBe(patternVertexCount(domain, L));
        expect(nT).toBe(patternTriangleCount(domain, L));
        let total = 0;
        for (let t = 0; t < nT; t++) {
          const a = area2(p.ij, p.indices, t);
          expect(a).toBe(1); // every cell triangle has area 1/2 in (i, j) units
          total += a;
        }
        expect(total).toBe(domain === 'quad' ? 2 * L * L : L * L);
        for (const x of p.indices) expect(x).toBeLessThan(nV);
        // Distinct vertices, uv = ij / L.
        expect(new Set(Array.from({ length: nV }, (_, v) => p.ij[2 * v] * 1000 + p.ij[2 * v + 1])).size).toBe(nV);
        for (let k = 0; k < p.ij.length; k++) expect(p.uv[k]).toBe(p.ij[k] / L);
      }
    });
  }

  it('packs all 14 patterns with their bases; a draw record is 5 u32 (20 bytes)', () => {
    const packed = packPatterns();
    expect(packed.entries.length).toBe(14);
    let v = 0,
      i = 0;
    for (const [k, e] of packed.entries.entries()) {
      expect(e.domain).toBe(k < 7 ? 'quad' : 'tri');
      expect(e.level).toBe(POW2_LEVELS[k % 7]);
      expect(e.baseVertex).toBe(v);
      expect(e.firstIndex).toBe(i);
      expect(e.indexCount).toBe(3 * patternTriangleCount(e.domain, e.level));
      const p = pow2Pattern(e.domain, e.level);
      for (let x = 0; x < e.vertexCount; x++) expect(packed.ij[v + x]).toBe(p.ij[2 * x] | (p.ij[2 * x + 1] << 16));
      expect(Array.from(packed.indices.subarray(i, i + e.indexCount))).toEqual(Array.from(p.indices));
      v += e.vertexCount;
      i += e.indexCount;
    }
    expect(packed.ij.length).toBe(v);
  });
});

describe('snap function', () => {
  it('every (P, Le): the snapped edge is {j/Le}, monotone, ends fixed', () => {
    for (const P of POW2_LEVELS) {
      for (const Le of POW2_LEVELS.filter((l) => l <= P)) {
        for (const canonical of [true, false]) {
          const seq = Array.from({ length: P + 1 }, (_, t) => snapEdgeParam(t, P, Le, canonical));
          expect(new Set(seq)).toEqual(new Set(Array.from({ length: Le + 1 }, (_, j) => (j * P) / Le)));
          for (let t = 1; t <= P; t++) expect(seq[t]).toBeGreaterThanOrEqual(seq[t - 1]);
          expect(seq[0]).toBe(0);
          expect(seq[P]).toBe(P);
        }
      }
    }
  });

  it('both sides of an edge, walking it in opposite directions at any pattern levels, give the same points', () => {
    for (const PA of POW2_LEVELS) {
      for (const PB of POW2_LEVELS) {
        for (const Le of POW2_LEVELS.filter((l) => l <= Math.min(PA, PB))) {
          // Side A walks canonically; side B from the other end. Both in canonical edge
          // parameter (fractions of the edge), per fine vertex.
          const a = Array.from({ length: PA + 1 }, (_, t) => snapEdgeParam(t, PA, Le, true) / PA);
          const b = Array.from({ length: PB + 1 }, (_, t) => 1 - snapEdgeParam(PB - t, PB, Le, false) / PB);
          // Distinct points, in order: identical sequences ({j/Le}), so they pair one to one.
          const dedup = (s: number[]) => s.filter((x, k) => k === 0 || x !== s[k - 1]);
          expect(dedup(b)).toEqual(dedup(a));
          // At equal pattern levels the fine vertices themselves coincide one by one.
          if (PA === PB) expect(b).toEqual(a);
        }
      }
    }
  });

  for (const domain of DOMAINS) {
    it(`${domain}: every level assignment up to P = 8 (both directions): no flip, P − Le collapsed per edge`, () => {
      const n = EDGES[domain];
      for (const P of [1, 2, 4, 8]) {
        const p = pow2Pattern(domain, P);
        const choices = POW2_LEVELS.filter((l) => l <= P);
        const combos = choices.length ** n;
        for (let c = 0; c < combos; c++) {
          const levels = Array.from({ length: n }, (_, e) => choices[Math.floor(c / choices.length ** e) % choices.length]);
          for (let d = 0; d < 1 << n; d++)
            checkSnap(
              p,
              levels,
              Array.from({ length: n }, (_, e) => ((d >> e) & 1) === 1),
            );
        }
      }
    });

    it(`${domain}: random level assignments at P = 16, 32, 64`, () => {
      let seed = 12345;
      const rand = () => (seed = (Math.imul(seed, 1103515245) + 12345) >>> 0) / 2 ** 32;
      const n = EDGES[domain];
      for (const P of [16, 32, 64]) {
        const p = pow2Pattern(domain, P);
        const choices = POW2_LEVELS.filter((l) => l <= P);
        for (let k = 0; k < (P === 64 ? 6 : 20); k++) {
          const levels = Array.from({ length: n }, () => choices[Math.floor(rand() * choices.length)]);
          checkSnap(
            p,
            levels,
            Array.from({ length: n }, () => rand() < 0.5),
          );
        }
      }
    });
  }
});
