/** Shared checks for the pattern tests: exact geometry in fixed point, no floating point. */
import { ONE } from '../../src/pattern/fixed.ts';
import type { TriPattern } from '../../src/pattern/types.ts';

/** Hausdorff distance between two 1D point sets (fixed point units). */
export function hausdorffSorted(a: number[], b: number[]): number {
  const sa = isSorted(a) ? a : [...a].sort((p, q) => p - q);
  const sb = isSorted(b) ? b : [...b].sort((p, q) => p - q);
  return Math.max(directed(sa, sb), directed(sb, sa));
}
function isSorted(a: number[]): boolean {
  for (let i = 1; i < a.length; i++) if (a[i] < a[i - 1]) return false;
  return true;
}
function directed(a: number[], b: number[]): number {
  let worst = 0;
  let j = 0;
  for (const x of a) {
    while (j + 1 < b.length && b[j + 1] <= x) j++;
    let d = Math.abs(b[j] - x);
    if (j + 1 < b.length) d = Math.min(d, Math.abs(b[j + 1] - x));
    worst = Math.max(worst, d);
  }
  return worst;
}

/** Twice the signed area of triangle t in the (w1, w2) plane, exact (integers < 2^34). */
export function area2(p: TriPattern, t: number): number {
  const [a, b, c] = [p.triangles[3 * t], p.triangles[3 * t + 1], p.triangles[3 * t + 2]];
  const ux = p.bary[3 * b + 1] - p.bary[3 * a + 1];
  const uy = p.bary[3 * b + 2] - p.bary[3 * a + 2];
  const vx = p.bary[3 * c + 1] - p.bary[3 * a + 1];
  const vy = p.bary[3 * c + 2] - p.bary[3 * a + 2];
  return ux * vy - uy * vx;
}

export interface MeshReport {
  negative: number;
  degenerate: number;
  areaSumExact: boolean;
  badBary: number;
  /** Undirected edges used other than once (boundary) or twice (interior), or a directed edge twice. */
  badEdges: string[];
  unreferenced: number;
}

/** Which domain edge (0, 1, 2) a vertex lies on, or -1: edge i is where the weight of corner i+2 is 0. */
export function onEdge(p: TriPattern, v: number, i: number): boolean {
  return p.bary[3 * v + ((i + 2) % 3)] === 0;
}

/**
 * Check a triangle pattern as a tiling of the domain, exactly:
 * barycentrics non-negative and summing to ONE; no negative area; areas sum to the domain's;
 * every directed edge used at most once; every undirected edge once (and then on the domain
 * boundary) or twice.
 */
export function checkTiling(p: TriPattern, areaSign = 1): MeshReport {
  let badBary = 0;
  for (let v = 0; v < p.vertexCount; v++) {
    const a = p.bary[3 * v],
      b = p.bary[3 * v + 1],
      c = p.bary[3 * v + 2];
    if (a < 0 || b < 0 || c < 0 || a + b + c !== ONE || !Number.isInteger(a + b + c)) badBary++;
  }
  let negative = 0,
    degenerate = 0,
    sum = 0;
  const used = new Uint8Array(p.vertexCount);
  const directed = new Map<number, number>();
  const undirected = new Map<number, number>();
  const key = (a: number, b: number) => a * 1_000_003 + b;
  for (let t = 0; t < p.triangleCount; t++) {
    const s = areaSign * area2(p, t);
    if (s < 0) negative++;
    if (s === 0) degenerate++;
    sum += s;
    for (let e = 0; e < 3; e++) {
      const a = p.triangles[3 * t + e],
        b = p.triangles[3 * t + ((e + 1) % 3)];
      used[a] = 1;
      directed.set(key(a, b), (directed.get(key(a, b)) ?? 0) + 1);
      const k = key(Math.min(a, b), Math.max(a, b));
      undirected.set(k, (undirected.get(k) ?? 0) + 1);
    }
  }
  const badEdges: string[] = [];
  for (const [k, n] of directed) if (n > 1) badEdges.push(`directed ${k} x${n}`);
  for (const [k, n] of undirected) {
    const a = Math.floor(k / 1_000_003),
      b = k % 1_000_003;
    if (n > 2) badEdges.push(`edge ${a}-${b} x${n}`);
    if (n === 1 && ![0, 1, 2].some((i) => onEdge(p, a, i) && onEdge(p, b, i))) badEdges.push(`open interior edge ${a}-${b}`);
  }
  let unreferenced = 0;
  for (let v = 0; v < p.vertexCount; v++) if (!used[v]) unreferenced++;
  return { negative, degenerate, areaSumExact: sum === ONE * ONE, badBary, badEdges, unreferenced };
}

/** The parameters t (weight of corner i+1) of the vertices on domain edge i, sorted. */
export function edgeParams(p: TriPattern, i: number): number[] {
  const out: number[] = [];
  for (let v = 0; v < p.vertexCount; v++) if (onEdge(p, v, i)) out.push(p.bary[3 * v + ((i + 1) % 3)]);
  return out.sort((a, b) => a - b);
}
