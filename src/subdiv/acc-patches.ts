/**
 * Construction of the ACC patches (the same steps as wgsl/acc/build.wgsl, one patch at a time): each
 * corner's data (cornerInfo), one assembly per scheme (Bezier, Gregory, Pm), and every patch's
 * control points in the layout of src/subdiv/acc.ts, whose header states the constructions. Beside
 * src/subdiv/acc.ts (schemes, constants, topology) and src/subdiv/acc-evaluate.ts (evaluation) as
 * acc-*.ts files, flat like the rest of src/subdiv; the f64 vector helpers of both live here.
 */
import {
  type AccTopology,
  type ValenceConstants,
  AccError,
  KIND_BEZIER,
  KIND_GREGORY_QUAD,
  KIND_GREGORY_TRI,
  KIND_PM_QUAD,
  KIND_PM_TRI,
  KIND_PM_TRI_LS,
  KIND_REGULAR,
  SECTOR_CONE,
  unpackSector,
  SECTOR_CORNER,
  SECTOR_CREASE,
  TRI_FACE,
  sectorConstants,
  valenceConstants,
} from './acc.ts';

export type V3 = [number, number, number];
export const add = (a: V3, b: V3): V3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
export const subv = (a: V3, b: V3): V3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const mul = (a: V3, s: number): V3 => [a[0] * s, a[1] * s, a[2] * s];
/** Σ w_i·p_i. */
export const comb = (...terms: [number, V3][]): V3 => {
  const r: V3 = [0, 0, 0];
  for (const [w, p] of terms) {
    r[0] += w * p[0];
    r[1] += w * p[1];
    r[2] += w * p[2];
  }
  return r;
};
export const cross3 = (a: V3, b: V3): V3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
/** As the GPU's accNormal: a zero vector stays zero (AccSurface.evaluate gives a patch corner
 * without a normal of its own the normal just inside first). */
export const normalize3 = (a: V3): V3 => {
  const l = Math.hypot(a[0], a[1], a[2]);
  return l > 0 ? mul(a, 1 / l) : [0, 0, 0];
};

/** Everything a patch needs from one of its corners (Loop & Schaefer 2008; Loop, Schaefer, Ni,
 * Castaño 2009; Myles, Ni, Peters 2008). */
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
  const type = unpackSector(sector).kind;
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
  const { kind: type, k, a } = unpackSector(sector);
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
 * Tangent-patch edge rows (Loop & Schaefer 2008): the cross-derivative coefficients x1, x2 pointing into the
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
  // ∂u, ∂v at the corners (Loop & Schaefer 2008).
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

/** Gregory quad (m = 4, denominators 3) or triangle (m = 3, denominators 4): Loop, Schaefer, Ni, Castaño 2009. */
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
 * Pm patch, quad c-patch (m = 4) or triangle (m = 3): Myles, Ni, Peters 2008, as nvmesh builds it.
 * `loopSchaefer`: corner and tangent points are the Loop–Schaefer limit and edge points (Bezier-ACC triangles).
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
