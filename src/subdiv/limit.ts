// Limit positions and tangents at vertices (OpenSubdiv's limit masks), made exact:
// semi-sharpness is refined away first, and where a mask is not exact (darts,
// interior valence 2) the vertex's ring is refined until the mask converges.
import { type HalfEdges, vertexRing } from '../mesh/index.ts';
import { isInf, isSemi } from '../mesh/index.ts';
import { type Level, extractFaces, refine, vertexFaces } from './level.ts';

export interface VertexLimit {
  /** Limit position. */
  P: [number, number, number];
  /** Tangent along the sector face's leading edge (towards the next corner) and trailing edge. Magnitudes are arbitrary. */
  lead: [number, number, number];
  trail: [number, number, number];
  /** false where the surface has no tangent plane (cone points, interior valence 2, degenerate crease spans). */
  normalDefined: boolean;
  /** Number of local refinement levels used. */
  levels: number;
}

type V3 = [number, number, number];
const sub = (P: Float64Array, a: number, b: number): V3 => [P[3 * a] - P[3 * b], P[3 * a + 1] - P[3 * b + 1], P[3 * a + 2] - P[3 * b + 2]];

const crossTangentCache = new Map<number, Float64Array>();

/**
 * Cross-tangent mask for a crease span of k >= 3 faces under the standard crease
 * rule (the Biermann-Levin-Zorin mask OpenSubdiv uses is for modified rules and is
 * off by degrees). Coefficients over [v, e_0..e_k, d_0..d_{k-1}], found by iterating
 * the span's subdivision on coefficient vectors until mean(d)-v is the dominant
 * cross eigenvector (components outside the tangent plane vanish).
 */
export function creaseCrossMask(k: number): Float64Array {
  const hit = crossTangentCache.get(k);
  if (hit) return hit;
  const np = 2 * k + 2;
  const iv = 0,
    ie = (i: number): number => 1 + i,
    id = (i: number): number => k + 2 + i;
  let rows: Float64Array[] = [];
  for (let p = 0; p < np; p++) {
    const r = new Float64Array(np);
    r[p] = 1;
    rows.push(r);
  }
  const comb = (terms: [number, Float64Array][]): Float64Array => {
    const r = new Float64Array(np);
    for (const [w, x] of terms) for (let i = 0; i < np; i++) r[i] += w * x[i];
    return r;
  };
  for (let it = 0; it < 600; it++) {
    const v = rows[iv];
    const e = (i: number): Float64Array => rows[ie(i)];
    const d = (i: number): Float64Array => rows[id(i)];
    const Fc: Float64Array[] = [];
    for (let i = 0; i < k; i++)
      Fc.push(
        comb([
          [0.25, v],
          [0.25, e(i)],
          [0.25, d(i)],
          [0.25, e(i + 1)],
        ]),
      );
    const next: Float64Array[] = new Array(np);
    next[iv] = comb([
      [0.75, v],
      [0.125, e(0)],
      [0.125, e(k)],
    ]);
    next[ie(0)] = comb([
      [0.5, v],
      [0.5, e(0)],
    ]);
    next[ie(k)] = comb([
      [0.5, v],
      [0.5, e(k)],
    ]);
    for (let i = 1; i < k; i++)
      next[ie(i)] = comb([
        [0.25, v],
        [0.25, e(i)],
        [0.25, Fc[i - 1]],
        [0.25, Fc[i]],
      ]);
    for (let i = 0; i < k; i++) next[id(i)] = Fc[i];
    // Translate so the centre is the origin and rescale (subdivision is affine-invariant).
    const c = next[iv];
    let mx = 0;
    for (let p = 0; p < np; p++) {
      if (p === iv) continue;
      const r = next[p];
      for (let i = 0; i < np; i++) {
        r[i] -= c[i];
        mx = Math.max(mx, Math.abs(r[i]));
      }
    }
    next[iv] = new Float64Array(np);
    for (let p = 0; p < np; p++) if (p !== iv) for (let i = 0; i < np; i++) next[p][i] /= mx;
    rows = next;
  }
  // mean(d) - v, where the current v row is 0 (points are relative to the centre).
  const t = new Float64Array(np);
  for (let i = 0; i < k; i++) for (let q = 0; q < np; q++) t[q] += rows[id(i)][q] / k;
  crossTangentCache.set(k, t);
  return t;
}

/** Smooth-rule limit position mask: (n^2 v + 4 sum e + sum d) / (n (n+5)). */
function smoothLimit(m: HalfEdges, P: Float64Array, v: number, ring: number[]): V3 {
  const n = ring.length;
  const out: V3 = [n * n * P[3 * v], n * n * P[3 * v + 1], n * n * P[3 * v + 2]];
  for (const h of ring) {
    const e = m.faceIndices[m.heNext[h]],
      d = m.faceIndices[m.heNext[m.heNext[h]]];
    for (let c = 0; c < 3; c++) out[c] += 4 * P[3 * e + c] + P[3 * d + c];
  }
  const s = n * (n + 5);
  return [out[0] / s, out[1] / s, out[2] / s];
}

/** Smooth-rule tangent masks (T1 ~ leading edge of ring face 0, T2 ~ its trailing edge). */
function smoothTangents(m: HalfEdges, P: Float64Array, ring: number[]): [V3, V3] {
  const n = ring.length;
  const th = (2 * Math.PI) / n;
  const lam = (5 + Math.cos(th) + Math.cos(th / 2) * Math.sqrt(2 * (9 + Math.cos(th)))) / 16;
  const T1: V3 = [0, 0, 0],
    T2: V3 = [0, 0, 0];
  for (let i = 0; i < n; i++) {
    const h = ring[i];
    const e = m.faceIndices[m.heNext[h]],
      d = m.faceIndices[m.heNext[m.heNext[h]]];
    const we1 = 4 * Math.cos(i * th),
      wd1 = (Math.cos(i * th) + Math.cos((i + 1) * th)) / (4 * lam - 1);
    const we2 = 4 * Math.cos((i - 1) * th),
      wd2 = (Math.cos((i - 1) * th) + Math.cos(i * th)) / (4 * lam - 1);
    for (let c = 0; c < 3; c++) {
      T1[c] += we1 * P[3 * e + c] + wd1 * P[3 * d + c];
      T2[c] += we2 * P[3 * e + c] + wd2 * P[3 * d + c];
    }
  }
  return [T1, T2];
}

const MAX_LIMIT_LEVELS = 120;
/** Levels of a crease sector of one face's ring before its diagonal gives the normal: the GPU
 * fans' depth from the cage (src/gpu/cc/fans.ts TOTAL_DEPTH), so that the two conventions agree. */
const K1_LEVELS = 8;

/**
 * Limit position and tangents of vertex v of level L, for the sector of face
 * `sector` (which must contain v). v must have a complete ring in L.
 */
export function vertexLimit(L: Level, v: number, sector: number): VertexLimit {
  // Work on the vertex's ring only, anchored at v.
  const faces = vertexFaces(L.he, v, sector);
  const ex = extractFaces(L, faces);
  let cur = ex.level;
  let lv = 0;
  while (ex.vmap[lv] !== v) lv++;
  let sec = 0; // sector face is local face 0
  const anchor: V3 = [L.pos[3 * v], L.pos[3 * v + 1], L.pos[3 * v + 2]];
  for (let i = 0; i < cur.pos.length; i += 3) {
    cur.pos[i] -= anchor[0];
    cur.pos[i + 1] -= anchor[1];
    cur.pos[i + 2] -= anchor[2];
  }
  const done = (p: V3, lead: V3, trail: V3, nd: boolean, levels: number): VertexLimit => ({
    P: [p[0] + anchor[0], p[1] + anchor[1], p[2] + anchor[2]],
    lead,
    trail,
    normalDefined: nd,
    levels,
  });
  let prev: V3 | null = null;
  let scale0 = 0;
  for (let i = 0; i < cur.pos.length; i++) scale0 = Math.max(scale0, Math.abs(cur.pos[i]));
  let k1Lead: V3 | null = null;
  for (let level = 0; ; level++) {
    let refineMore = false;
    const m = cur.he,
      P = cur.pos;
    let secHe = -1;
    for (let h = m.faceOffsets[sec]; h < m.faceOffsets[sec + 1]; h++) if (m.faceIndices[h] === lv) secHe = h;
    const ring = vertexRing(m, lv, secHe);
    let allQuads = true;
    for (let f = 0; f < m.nFaces; f++) if (m.faceOffsets[f + 1] - m.faceOffsets[f] !== 4) allQuads = false;
    const vs = cur.vertSharp[lv];
    let semi = isSemi(vs);
    const sharpEdgeIdx: number[] = [];
    let nInf = 0;
    for (let k = m.vertEdgeOffsets[lv]; k < m.vertEdgeOffsets[lv + 1]; k++) {
      const s = cur.edgeSharp[m.vertEdges[k]];
      if (isSemi(s)) semi = true;
      if (isInf(s)) nInf++;
    }
    const last = level >= MAX_LIMIT_LEVELS;
    if (ring && ((allQuads && !semi) || last)) {
      const R = ring.he;
      const nE = m.vertEdgeOffsets[lv + 1] - m.vertEdgeOffsets[lv];
      const leadE = m.faceIndices[m.heNext[secHe]],
        trailE = m.faceIndices[m.hePrev[secHe]];
      if (isInf(vs) || nInf > 2) {
        // Corner: the vertex itself; tangents along the sector face's edges.
        return done(
          [P[3 * lv], P[3 * lv + 1], P[3 * lv + 2]],
          sub(P, leadE, lv),
          sub(P, trailE, lv),
          isInf(cur.edgeSharp[m.heEdge[secHe]]) && isInf(cur.edgeSharp[m.heEdge[m.hePrev[secHe]]]),
          level,
        );
      }
      if (nInf === 2) {
        // Crease: edges of the ring (boundary ring has one more edge than faces).
        const edgeFar: number[] = [],
          edgeSharp: boolean[] = [];
        for (const h of R) {
          edgeFar.push(m.faceIndices[m.heNext[h]]);
          edgeSharp.push(isInf(cur.edgeSharp[m.heEdge[h]]));
        }
        if (ring.boundary) {
          const h = m.hePrev[R[R.length - 1]];
          edgeFar.push(m.faceIndices[h]);
          edgeSharp.push(isInf(cur.edgeSharp[m.heEdge[h]]));
        }
        const sharpIdx = edgeSharp.map((s, i) => (s ? i : -1)).filter((i) => i >= 0);
        sharpEdgeIdx.push(...sharpIdx);
        const ea = edgeFar[sharpIdx[0]],
          eb = edgeFar[sharpIdx[1]];
        const p: V3 = [0, 0, 0];
        for (let c = 0; c < 3; c++) p[c] = (4 * P[3 * lv + c] + P[3 * ea + c] + P[3 * eb + c]) / 6;
        // Span containing the sector face (ring face r, between edges r and r+1).
        const nF = R.length;
        const r = R.indexOf(secHe);
        let a: number, b: number;
        if (ring.boundary) {
          a = r;
          while (!edgeSharp[a]) a--;
          b = r + 1;
          while (!edgeSharp[b]) b++;
        } else {
          a = r;
          while (!edgeSharp[((a % nF) + nF) % nF]) a--;
          b = r + 1;
          while (!edgeSharp[b % nF]) b++;
        }
        const k = b - a;
        const E = (i: number): number => edgeFar[ring.boundary ? i : ((i % nF) + nF) % nF];
        const D = (i: number): number => {
          const h = R[ring.boundary ? i : ((i % nF) + nF) % nF];
          return m.faceIndices[m.heNext[m.heNext[h]]];
        };
        const T1: V3 = [0, 0, 0],
          T2: V3 = [0, 0, 0];
        for (let c = 0; c < 3; c++) T1[c] = 0.5 * (P[3 * E(a) + c] - P[3 * E(b) + c]);
        const nd = true;
        if (k === 1) {
          // A crease sector of one face: its two sharp edges leave the vertex in opposite
          // directions (θ = π), so the face's derivatives there are parallel and its normal
          // depends on the direction of approach; OpenSubdiv's single-face mask (3(e_a + e_b) −
          // 6v, along the crease curve's own curvature) gives it either sign (a concave rim: turned
          // over). Convention, as the GPU's fans (wgsl/cc/build.wgsl creaseTangents): the normal
          // approached along the face's diagonal, T2 = its opposite vertex − the limit point after
          // K1_LEVELS levels of the ring (refined on below until then).
          // T1 stays the input level's (tangents are per the level the call was given); T2 is
          // scaled back to it as well.
          if (level === 0) k1Lead = [T1[0], T1[1], T1[2]];
          if (level < K1_LEVELS) {
            refineMore = true;
          } else {
            if (k1Lead) for (let c = 0; c < 3; c++) T1[c] = k1Lead[c];
            for (let c = 0; c < 3; c++) T2[c] = 2 ** level * (P[3 * D(a) + c] - p[c]);
          }
        } else if (k === 2) {
          for (let c = 0; c < 3; c++) {
            T2[c] =
              (-4 * P[3 * lv + c] - P[3 * E(a) + c] - P[3 * E(b) + c] + 4 * P[3 * E(a + 1) + c] + P[3 * D(a) + c] + P[3 * D(a + 1) + c]) /
              6;
          }
        } else {
          const w = creaseCrossMask(k);
          for (let c = 0; c < 3; c++) {
            let s = w[0] * P[3 * lv + c];
            for (let i = 0; i <= k; i++) s += w[1 + i] * P[3 * E(a + i) + c];
            for (let i = 0; i < k; i++) s += w[k + 2 + i] * P[3 * D(a + i) + c];
            T2[c] = s;
          }
        }
        void nE;
        if (!refineMore) return done(p, T1, T2, nd, level);
      }
      if (refineMore) {
        // (a crease sector of one face, below K1_LEVELS: refine on)
      } else if (!ring.boundary && R.length >= 3 && nInf === 0) {
        const p = smoothLimit(m, P, lv, R);
        const [T1, T2] = smoothTangents(m, P, R);
        return done(p, T1, T2, true, level);
      }
      // Dart (one infinitely sharp edge) or interior valence 2: the smooth mask is
      // not exact; refine until it converges.
      else if (!ring.boundary && R.length >= 2) {
        const p = smoothLimit(m, P, lv, R);
        if (prev && (Math.hypot(p[0] - prev[0], p[1] - prev[1], p[2] - prev[2]) <= 2.3e-16 * scale0 || last)) {
          if (R.length >= 3) {
            const [T1, T2] = smoothTangents(m, P, R);
            return done(p, T1, T2, true, level);
          }
          return done(p, sub(P, leadE, lv), sub(P, trailE, lv), false, level);
        }
        prev = p;
      } else if (last) {
        return done([P[3 * lv], P[3 * lv + 1], P[3 * lv + 2]], sub(P, leadE, lv), sub(P, trailE, lv), false, level);
      }
    }
    // Refine the ring once and re-extract the ring of the vertex's child (same id).
    const child = refine(cur);
    const nextSec = secHe; // child face of corner secHe is face secHe
    const faces2 = vertexFaces(child.he, lv, nextSec);
    const ex2 = extractFaces(child, faces2);
    let nlv = 0;
    while (ex2.vmap[nlv] !== lv) nlv++;
    cur = ex2.level;
    lv = nlv;
    sec = 0;
  }
}

/** Limit positions (and normals, for each vertex's first face) of all vertices of a level. */
export function limitPositions(L: Level): { P: Float64Array; N: Float64Array } {
  const m = L.he;
  const P = new Float64Array(3 * m.nVerts);
  const N = new Float64Array(3 * m.nVerts).fill(NaN);
  for (let v = 0; v < m.nVerts; v++) {
    if (m.vertHeOffsets[v + 1] === m.vertHeOffsets[v]) {
      P.set(L.pos.subarray(3 * v, 3 * v + 3), 3 * v);
      continue;
    }
    const f = m.heFace[m.vertHe[m.vertHeOffsets[v]]];
    const r = vertexLimit(L, v, f);
    P[3 * v] = r.P[0];
    P[3 * v + 1] = r.P[1];
    P[3 * v + 2] = r.P[2];
    const n = cross(r.lead, r.trail);
    const l = Math.hypot(n[0], n[1], n[2]);
    if (l > 0) {
      N[3 * v] = n[0] / l;
      N[3 * v + 1] = n[1] / l;
      N[3 * v + 2] = n[2] / l;
    }
  }
  return { P, N };
}

export function cross(a: ArrayLike<number>, b: ArrayLike<number>): V3 {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}
