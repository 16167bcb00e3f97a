/**
 * Checks shared by the ACC tests and the error table (scripts/acc-errors.ts): small cages (prisms
 * after one Catmull-Clark step: every valence we ask for), across-edge continuity of an ACC surface,
 * and its error against the exact Catmull-Clark limit (src/subdiv Surface) at the same parameter.
 */
import { makeCage, type Cage, DEFAULT_OPTIONS } from '../../src/mesh/index.ts';
import { Surface, levelFromCage, refine } from '../../src/subdiv/index.ts';
import type { AccSurface } from '../../src/subdiv/acc-evaluate.ts';
import type { V3 } from '../../src/subdiv/acc-patches.ts';
import { faceParam } from '../../src/gpu/tess/face-params.ts';
import { prepareMesh, type PreparedMesh } from '../../src/gpu/tess/prepare.ts';
import { angleBetween } from './tess-checks.ts';

/** An n-gonal prism with wavy heights (so no accidental symmetry hides errors), n-gon caps. */
export function prism(n: number, wobble = 0.15): Cage {
  const p: number[] = [];
  for (const z of [-1, 1])
    for (let i = 0; i < n; i++) {
      const a = (2 * Math.PI * i) / n;
      p.push(Math.cos(a), Math.sin(a), z * (1 + wobble * Math.sin(3 * a + z)));
    }
  const f: number[][] = [[...Array(n).keys()].map((i) => n + i), [...Array(n).keys()].map((i) => n - 1 - i)];
  for (let i = 0; i < n; i++) f.push([i, (i + 1) % n, n + ((i + 1) % n), n + i]);
  return makeCage(p, f);
}

/** One Catmull-Clark step (the exact reference's refinement) as a new cage: all quads. */
export function ccStep(cage: Cage): Cage {
  const L = refine(levelFromCage(cage));
  const faces: number[][] = [];
  for (let f = 0; f < L.he.nFaces; f++) faces.push(Array.from(L.he.faceIndices.subarray(L.he.faceOffsets[f], L.he.faceOffsets[f + 1])));
  return makeCage(L.pos, faces);
}

/**
 * A cage with faces dropped (boundaries) and edges tagged infinitely sharp (creases), every vertex
 * a sharp edge ends at tagged as a corner when `cornerAt` says so. Unused vertices stay (no rings).
 */
export function openCreased(cage: Cage, drop: (f: number) => boolean, creases: [number, number][] = [], corners: number[] = []): Cage {
  const faces: number[][] = [];
  for (let f = 0; f < cage.faceOffsets.length - 1; f++)
    if (!drop(f)) faces.push(Array.from(cage.faceIndices.subarray(cage.faceOffsets[f], cage.faceOffsets[f + 1])));
  return makeCage(cage.positions, faces, {
    creases: creases.map(([a, b]) => [a, b, 10] as [number, number, number]),
    corners: corners.map((v) => [v, 10] as [number, number]),
  });
}

/**
 * Test cages with boundaries and creases: n-prisms after one CC step (valences 3 and n) with one
 * cap's faces dropped (a boundary through extraordinary vertices), an infinitely sharp loop
 * round the middle (crease vertices of valence 4) and a sharp corner; a triangular prism opened
 * the same way (triangles at the boundary); the octahedron with one face dropped.
 */
export function boundaryCages(): [string, Cage][] {
  const out: [string, Cage][] = [];
  for (const n of [5, 6, 8]) {
    const c = ccStep(prism(n));
    // The step's vertices: n-gon cap centres are face points; drop the faces round the top cap's centre.
    const P = c.positions;
    const zTop = (f: number) => {
      let z = 0;
      for (let i = c.faceOffsets[f]; i < c.faceOffsets[f + 1]; i++) z += P[3 * c.faceIndices[i] + 2];
      return z / (c.faceOffsets[f + 1] - c.faceOffsets[f]);
    };
    let zMax = -Infinity;
    for (let f = 0; f < c.faceOffsets.length - 1; f++) zMax = Math.max(zMax, zTop(f));
    // A sharp loop: the side edges at mid-height (the CC step's edge points of the prism's sides).
    const mid: [number, number][] = [];
    const seen = new Set<string>();
    for (let f = 0; f < c.faceOffsets.length - 1; f++) {
      const o = c.faceOffsets[f],
        m = c.faceOffsets[f + 1] - o;
      for (let k = 0; k < m; k++) {
        const a = c.faceIndices[o + k],
          b = c.faceIndices[o + ((k + 1) % m)];
        const key = `${Math.min(a, b)},${Math.max(a, b)}`;
        if (Math.abs(P[3 * a + 2]) < 0.2 && Math.abs(P[3 * b + 2]) < 0.2 && !seen.has(key)) {
          seen.add(key);
          mid.push([a, b]);
        }
      }
    }
    out.push([`prism ${n} (CC step), open top, sharp loop, one corner`, openCreased(c, (f) => zTop(f) > zMax - 0.3, mid, [mid[0][0]])]);
  }
  out.push(['triangular prism, one quad dropped', openCreased(triPrismCage(), (f) => f === 2)]);
  out.push(['octahedron, one face dropped', openCreased(octahedron(), (f) => f === 0)]);
  return out;
}

/** A triangular prism: two triangles, three quads (as tests/subdiv-fixtures triPrism). */
function triPrismCage(): Cage {
  return makeCage(
    [1, 0, -1, -0.5, 0.866, -1, -0.5, -0.866, -1, 1, 0, 1.2, -0.5, 0.866, 0.9, -0.5, -0.866, 1],
    [
      [0, 2, 1],
      [3, 4, 5],
      [0, 1, 4, 3],
      [1, 2, 5, 4],
      [2, 0, 3, 5],
    ],
  );
}

/** A cube whose face 0 is split by an interior vertex of valence 2 (two quads sharing two edges). */
export function valence2Cube(base: Cage): Cage {
  const faces: number[][] = [];
  for (let f = 0; f < base.faceOffsets.length - 1; f++)
    faces.push(Array.from(base.faceIndices.subarray(base.faceOffsets[f], base.faceOffsets[f + 1])));
  const [a, b, c, d] = faces[0];
  const m = base.positions.length / 3;
  faces.splice(0, 1, [a, b, c, m], [a, m, c, d]);
  const P = Array.from(base.positions);
  const cx = (P[3 * a] + P[3 * c]) / 2,
    cy = (P[3 * a + 1] + P[3 * c + 1]) / 2,
    cz = (P[3 * a + 2] + P[3 * c + 2]) / 2;
  P.push(cx + 0.1, cy - 0.2, cz + 0.3);
  return makeCage(P, faces);
}

/** Regular octahedron: all triangles, valence 4. */
export function octahedron(): Cage {
  return makeCage(
    [1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1],
    [
      [0, 2, 4],
      [2, 1, 4],
      [1, 3, 4],
      [3, 0, 4],
      [2, 0, 5],
      [1, 2, 5],
      [3, 1, 5],
      [0, 3, 5],
    ],
  );
}

export function bboxDiagonal(P: ArrayLike<number>): number {
  const lo = [Infinity, Infinity, Infinity],
    hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < P.length; i += 3)
    for (let c = 0; c < 3; c++) {
      lo[c] = Math.min(lo[c], P[i + c]);
      hi[c] = Math.max(hi[c], P[i + c]);
    }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

/** Parameter of point t ∈ [0,1] along corner k → k+1 of a face with m corners ((u,v) or (w1,w2)). */
export function edgeParam(m: number, k: number, t: number): [number, number] {
  if (m === 4) {
    const uv = [
      [0, 0],
      [1, 0],
      [1, 1],
      [0, 1],
    ];
    const a = uv[k],
      b = uv[(k + 1) % 4];
    return [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
  }
  const w = [0, 0, 0];
  w[k] = 1 - t;
  w[(k + 1) % 3] = t;
  return [w[1], w[2]];
}

export type NormalFn = (face: number, u: number, v: number) => V3;

export interface EdgeStats {
  maxGap: number;
  maxJumpDeg: number;
  edges: number;
  worst: string;
}

/**
 * Position gap (/ bbox diagonal) and normal jump (degrees) along every interior edge, sampled at
 * `samples` points, evaluated from both faces. `include(fa, fb)` selects which edges count.
 */
export function continuity(
  S: AccSurface,
  normal: NormalFn = (f, u, v) => S.evaluate(f, u, v).N,
  samples = 9,
  include: (fa: number, fb: number, a: number, b: number) => boolean = () => true,
): EdgeStats {
  const T = S.topology,
    cage = S.cage;
  const diag = bboxDiagonal(cage.positions);
  const stats: EdgeStats = { maxGap: 0, maxJumpDeg: 0, edges: 0, worst: '' };
  const corner = new Map<string, [number, number]>(); // "a,b" directed → (face, k)
  for (let f = 0; f < T.nPatches; f++) {
    const o = cage.faceOffsets[f],
      m = cage.faceOffsets[f + 1] - o;
    for (let k = 0; k < m; k++) corner.set(`${cage.faceIndices[o + k]},${cage.faceIndices[o + ((k + 1) % m)]}`, [f, k]);
  }
  for (const [key, [fa, ka]] of corner) {
    const [a, b] = key.split(',').map(Number);
    if (a > b) continue;
    const other = corner.get(`${b},${a}`);
    if (!other) continue;
    const [fb, kb] = other;
    if (!include(fa, fb, a, b)) continue;
    stats.edges++;
    const ma = T.faceSize[fa],
      mb = T.faceSize[fb];
    for (let i = 0; i <= samples; i++) {
      const t = i / samples;
      const [ua, va] = edgeParam(ma, ka, t),
        [ub, vb] = edgeParam(mb, kb, 1 - t);
      const pa = S.evaluate(fa, ua, va).P,
        pb = S.evaluate(fb, ub, vb).P;
      const gap = Math.hypot(pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]) / diag;
      const jump = (angleBetween(normal(fa, ua, va), normal(fb, ub, vb)) * 180) / Math.PI;
      if (gap > stats.maxGap) stats.maxGap = gap;
      if (jump > stats.maxJumpDeg) {
        stats.maxJumpDeg = jump;
        stats.worst = `faces ${fa}/${fb} edge ${a}-${b} t=${t.toFixed(2)}`;
      }
    }
  }
  return stats;
}

/**
 * Edges that are not infinitely sharp (as the exact reference sees them: tags, boundary mode): the
 * edges across which the schemes must be G1. `continuity(S, n, s, smoothEdges(cage))`. `sharpFrom`:
 * the sharpness from which an edge counts as sharp (1: as the ACC default builds semi-sharp tags).
 */
export function smoothEdges(cage: Cage, sharpFrom = 10): (fa: number, fb: number, a: number, b: number) => boolean {
  const L = levelFromCage(cage, undefined, { ...DEFAULT_OPTIONS, ...cage.fileOptions });
  const sharp = new Set<string>();
  for (let e = 0; e < L.he.nEdges; e++)
    if (L.edgeSharp[e] >= sharpFrom) {
      const a = L.he.edgeVerts[2 * e],
        b = L.he.edgeVerts[2 * e + 1];
      sharp.add(`${Math.min(a, b)},${Math.max(a, b)}`);
    }
  return (_fa, _fb, a, b) => !sharp.has(`${Math.min(a, b)},${Math.max(a, b)}`);
}

/** The exact limit at an ACC parameter (face, u, v) (triangles: (u, v) = (w1, w2)). */
export class ExactAt {
  readonly S: Surface;
  readonly mesh: PreparedMesh;
  private readonly triOfFace = new Map<number, number>();
  constructor(readonly cage: Cage) {
    this.S = new Surface(cage, undefined, { ...DEFAULT_OPTIONS, ...cage.fileOptions });
    this.mesh = prepareMesh(cage);
    for (let t = 0; t < this.mesh.triangleCount; t++)
      if (!this.triOfFace.has(this.mesh.triFace[t])) this.triOfFace.set(this.mesh.triFace[t], t);
  }
  at(face: number, u: number, v: number) {
    const m = this.cage.faceOffsets[face + 1] - this.cage.faceOffsets[face];
    if (m === 4) return this.S.evaluate(face, u, v);
    const fp = faceParam(this.mesh, this.cage, this.triOfFace.get(face)!, [1 - u - v, u, v]);
    if (!('k' in fp)) throw new Error('expected a sub-face parameter');
    return this.S.evaluateSubFace(face, fp.k, fp.s, fp.t);
  }
}

export interface ErrorRow {
  samples: number;
  maxP: number;
  rmsP: number;
  maxN: number;
  rmsN: number;
  nan: number;
}

/** Deterministic random (face, u, v): quads uniform in the square, triangles in the simplex. */
export function randomFaceParams(cage: Cage, n: number, seed = 7): [number, number, number][] {
  let s = seed;
  const rnd = () => (s = (s * 16807) % 2147483647) / 2147483647;
  const nF = cage.faceOffsets.length - 1;
  const out: [number, number, number][] = [];
  for (let i = 0; i < n; i++) {
    const f = Math.min(nF - 1, Math.floor(rnd() * nF));
    let u = rnd(),
      v = rnd();
    if (cage.faceOffsets[f + 1] - cage.faceOffsets[f] === 3 && u + v > 1) {
      u = 1 - u;
      v = 1 - v;
    }
    out.push([f, u, v]);
  }
  return out;
}

/** Position (/ bbox diagonal) and normal (degrees) errors of an ACC surface against exact CC. */
export function accErrors(S: AccSurface, exact: ExactAt | ReturnType<ExactAt['at']>[], params: [number, number, number][]): ErrorRow {
  const diag = bboxDiagonal(S.cage.positions);
  let maxP = 0,
    sp = 0,
    maxN = 0,
    sn = 0,
    nn = 0,
    nan = 0;
  params.forEach(([f, u, v], i) => {
    const a = S.evaluate(f, u, v),
      r = Array.isArray(exact) ? exact[i] : exact.at(f, u, v);
    if (![...a.P, ...a.N].every(Number.isFinite)) {
      nan++;
      return;
    }
    const dp = Math.hypot(a.P[0] - r.P[0], a.P[1] - r.P[1], a.P[2] - r.P[2]) / diag;
    maxP = Math.max(maxP, dp);
    sp += dp * dp;
    if (r.normalDefined) {
      const dn = (angleBetween(a.N, r.N) * 180) / Math.PI;
      maxN = Math.max(maxN, dn);
      sn += dn * dn;
      nn++;
    }
  });
  return {
    samples: params.length,
    maxP,
    rmsP: Math.sqrt(sp / Math.max(1, params.length)),
    maxN,
    rmsN: Math.sqrt(sn / Math.max(1, nn)),
    nan,
  };
}
