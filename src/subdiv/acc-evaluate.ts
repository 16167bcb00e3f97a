/**
 * Evaluation of the ACC patches built by src/subdiv/acc-patches.ts: bicubic, tangent patches,
 * Gregory blends, quartic triangles and the Pm sectors, per patch kind; and AccSurface, the
 * yardstick by (face, u, v) that the tests and scripts hold the GPU path and the exact surface
 * against (parameters as in the header of src/subdiv/acc.ts).
 */
import type { Cage, Topology } from '../mesh/index.ts';
import {
  ACC_DEGENERATE_SIN,
  ACC_DEGENERATE_STEP,
  type AccOptions,
  type AccScheme,
  type AccTopology,
  AccError,
  KIND_BEZIER,
  KIND_GREGORY_QUAD,
  KIND_GREGORY_TRI,
  KIND_PM_QUAD,
  KIND_PM_TRI,
  KIND_PM_TRI_LS,
  KIND_POINTS,
  KIND_REGULAR,
  buildAccTopology,
} from './acc.ts';
import { type V3, add, buildAccPoints, comb, cross3, mul, normalize3, subv } from './acc-patches.ts';

export interface AccPoint {
  P: V3;
  /** Unit shading normal (outward for counter-clockwise faces). */
  N: V3;
}

const bern3 = (t: number): number[] => {
  const s = 1 - t;
  return [s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t];
};
const bern3d = (t: number): number[] => {
  const s = 1 - t;
  return [-3 * s * s, 3 * s * s - 6 * s * t, 6 * s * t - 3 * t * t, 3 * t * t];
};
const bern2 = (t: number): number[] => {
  const s = 1 - t;
  return [s * s, 2 * s * t, t * t];
};

/** Bicubic b_ij (i + 4j): position and the two partial derivatives. */
export function evalBicubic(b: V3[], u: number, v: number): { P: V3; Pu: V3; Pv: V3 } {
  const bu = bern3(u),
    bv = bern3(v),
    du = bern3d(u),
    dv = bern3d(v);
  const P: V3 = [0, 0, 0],
    Pu: V3 = [0, 0, 0],
    Pv: V3 = [0, 0, 0];
  for (let j = 0; j < 4; j++)
    for (let i = 0; i < 4; i++) {
      const q = b[i + 4 * j];
      for (let c = 0; c < 3; c++) {
        P[c] += bu[i] * bv[j] * q[c];
        Pu[c] += du[i] * bv[j] * q[c];
        Pv[c] += bu[i] * dv[j] * q[c];
      }
    }
  return { P, Pu, Pv };
}

/** Tangent patches of a BEZIER patch (32 points): T_u and T_v at (u, v). */
export function evalTangentPatches(q: V3[], u: number, v: number): { Tu: V3; Tv: V3 } {
  const b = (i: number, j: number): V3 => q[i + 4 * j];
  const Ua = (a: number, c: number): V3 => (a === 1 ? mul(subv(b(2, c), b(1, c)), 3) : q[16 + 2 * a + c]);
  const Va = (c: number, a: number): V3 => (a === 1 ? mul(subv(b(c, 2), b(c, 1)), 3) : q[24 + 2 * a + c]);
  const b2u = bern2(u),
    b2v = bern2(v),
    b3u = bern3(u),
    b3v = bern3(v);
  const Tu: V3 = [0, 0, 0],
    Tv: V3 = [0, 0, 0];
  for (let a = 0; a < 3; a++)
    for (let c = 0; c < 4; c++) {
      const x = Ua(a, c),
        y = Va(c, a);
      for (let d = 0; d < 3; d++) {
        Tu[d] += b2u[a] * b3v[c] * x[d];
        Tv[d] += b3u[c] * b2v[a] * y[d];
      }
    }
  return { Tu, Tv };
}

/** Blended 16-point Bézier of a GREGORY_QUAD (20 points) at (u, v) (Loop, Schaefer, Ni, Castaño 2009). */
export function gregoryQuadBezier(q: V3[], u: number, v: number): V3[] {
  const G = (k: number, i: number): V3 => q[5 * k + i]; // i: 0 P, 1 E⁺, 2 E⁻, 3 F⁺, 4 F⁻
  const blend = (F1: V3, w1: number, F2: V3, w2: number): V3 => (w1 + w2 > 0 ? mul(add(mul(F1, w1), mul(F2, w2)), 1 / (w1 + w2)) : F1);
  const b: V3[] = new Array(16);
  const set = (i: number, j: number, p: V3) => {
    b[i + 4 * j] = p;
  };
  set(0, 0, G(0, 0));
  set(1, 0, G(0, 1));
  set(0, 1, G(0, 2));
  set(3, 0, G(1, 0));
  set(2, 0, G(1, 2));
  set(3, 1, G(1, 1));
  set(3, 3, G(2, 0));
  set(2, 3, G(2, 1));
  set(3, 2, G(2, 2));
  set(0, 3, G(3, 0));
  set(0, 2, G(3, 1));
  set(1, 3, G(3, 2));
  set(1, 1, blend(G(0, 3), u, G(0, 4), v));
  set(2, 1, blend(G(1, 3), v, G(1, 4), 1 - u));
  set(2, 2, blend(G(2, 3), 1 - u, G(2, 4), 1 - v));
  set(1, 2, blend(G(3, 3), 1 - v, G(3, 4), u));
  return b;
}

/** Index of quartic triangle coefficient Q_{abc} (a + b + c = 4) in a 15-array: by c, then b. */
export const qi = (_a: number, b: number, c: number): number => c * 5 - (c * (c - 1)) / 2 + b;

/**
 * Quartic Bézier triangle by de Casteljau down to three points R_a, R_b, R_c: the position is
 * a·R_a + b·R_b + c·R_c and the homogeneous partials are ∂/∂a = 4R_a, ∂/∂b = 4R_b, ∂/∂c = 4R_c.
 */
export function evalQuartic(Q: V3[], a: number, b: number, c: number): { P: V3; Da: V3; Db: V3; Dc: V3 } {
  let cur = Q,
    deg = 4;
  while (deg > 1) {
    const next: V3[] = [];
    const d = deg - 1;
    const idx = (bb: number, cc: number, dd: number) => cc * (dd + 1) - (cc * (cc - 1)) / 2 + bb;
    for (let cc = 0; cc <= d; cc++)
      for (let bb = 0; bb + cc <= d; bb++) {
        next[idx(bb, cc, d)] = comb([a, cur[idx(bb, cc, deg)]], [b, cur[idx(bb + 1, cc, deg)]], [c, cur[idx(bb, cc + 1, deg)]]);
      }
    cur = next;
    deg = d;
  }
  // Degree 1: index (b=0,c=0) → R_a = 0, (1,0) → R_b = 1, (0,1) → R_c = 2.
  const Ra = cur[0],
    Rb = cur[1],
    Rc = cur[2];
  return { P: comb([a, Ra], [b, Rb], [c, Rc]), Da: mul(Ra, 4), Db: mul(Rb, 4), Dc: mul(Rc, 4) };
}

/** Quartic coefficients of a GREGORY_TRI (15 points) at barycentrics λ (Loop, Schaefer, Ni, Castaño 2009; our G1
 * blend, see src/subdiv/acc.ts). */
export function gregoryTriQuartic(q: V3[], l: [number, number, number]): V3[] {
  const G = (k: number, i: number): V3 => q[5 * k + i];
  const Q: V3[] = new Array(15);
  const set = (a: number, b: number, c: number, p: V3) => {
    Q[qi(a, b, c)] = p;
  };
  // Quartic index (a, b, c) ↔ powers of λ0, λ1, λ2; corner k = 4 on slot k.
  const slot = (k: number, x: number, y: number): [number, number, number] => {
    // x on corner k, y on corner k+1, rest on corner k+2.
    const r: [number, number, number] = [0, 0, 0];
    r[k] = x;
    r[(k + 1) % 3] = y;
    r[(k + 2) % 3] = 4 - x - y;
    return r;
  };
  const blend = (F1: V3, w1: number, F2: V3, w2: number): V3 => (w1 + w2 > 0 ? mul(add(mul(F1, w1), mul(F2, w2)), 1 / (w1 + w2)) : F1);
  for (let k = 0; k < 3; k++) {
    const k1 = (k + 1) % 3,
      k2 = (k + 2) % 3;
    const Pk = G(k, 0),
      Ep = G(k, 1),
      Em1 = G(k1, 2);
    set(...slot(k, 4, 0), Pk);
    set(...slot(k, 3, 1), comb([0.25, Pk], [0.75, Ep]));
    set(...slot(k, 2, 2), comb([0.5, Ep], [0.5, Em1]));
    set(...slot(k, 1, 3), comb([0.75, Em1], [0.25, G(k1, 0)]));
    // Interior point next to corner k: F⁺ (edge toward k+1) weighted by λ_{k+1}, F⁻ by λ_{k−1}.
    set(...slot(k, 2, 1), blend(G(k, 3), l[k1], G(k, 4), l[k2]));
  }
  return Q;
}

/** Quartic coefficients of sector k of a Pm patch (m = 4 c-patch, m = 3 triangle): Myles, Ni, Peters 2008. */
export function pmSectorQuartic(q: V3[], m: number, k: number): V3[] {
  const S = (j: number, i: number): V3 => q[6 * (((j % m) + m) % m) + i]; // 0 c, 1 t⁺, 2 t⁻(next corner), 3 b211, 4 b121, 5 b112
  const Q: V3[] = new Array(15);
  const set = (a: number, b: number, c: number, p: V3) => {
    Q[qi(a, b, c)] = p;
  };
  const ck = S(k, 0),
    tk = S(k, 1),
    tk1 = S(k, 2),
    ck1 = S(k + 1, 0);
  set(4, 0, 0, ck);
  set(3, 1, 0, comb([0.25, ck], [0.75, tk]));
  set(2, 2, 0, comb([0.5, tk], [0.5, tk1]));
  set(1, 3, 0, comb([0.75, tk1], [0.25, ck1]));
  set(0, 4, 0, ck1);
  set(2, 1, 1, S(k, 3));
  set(1, 2, 1, S(k, 4));
  set(1, 1, 2, S(k, 5));
  // The neighbouring sectors' boundary points next to corners k and k+1.
  const prevNear = comb([0.25, ck], [0.75, S(k - 1, 2)]); // (c_k + 3 t_k⁻)/4
  const nextNear = comb([0.25, ck1], [0.75, S(k + 1, 1)]); // (c_{k+1} + 3 t_{k+1}⁺)/4
  if (m === 4) {
    set(3, 0, 1, mul(add(Q[qi(3, 1, 0)], prevNear), 0.5));
    set(0, 3, 1, mul(add(Q[qi(1, 3, 0)], nextNear), 0.5));
    set(2, 0, 2, mul(add(S(k, 3), S(k - 1, 4)), 0.5));
    set(0, 2, 2, mul(add(S(k, 4), S(k + 1, 3)), 0.5));
    set(1, 0, 3, mul(add(S(k, 5), S(k - 1, 5)), 0.5));
    set(0, 1, 3, mul(add(S(k, 5), S(k + 1, 5)), 0.5));
    set(0, 0, 4, mul(add(add(S(0, 5), S(1, 5)), add(S(2, 5), S(3, 5))), 0.25));
  } else {
    set(3, 0, 1, comb([1 / 3, ck], [1 / 3, Q[qi(3, 1, 0)]], [1 / 3, prevNear]));
    set(0, 3, 1, comb([1 / 3, ck1], [1 / 3, Q[qi(1, 3, 0)]], [1 / 3, nextNear]));
    set(2, 0, 2, comb([1 / 3, Q[qi(3, 0, 1)]], [1 / 3, S(k, 3)], [1 / 3, S(k - 1, 4)]));
    set(0, 2, 2, comb([1 / 3, Q[qi(0, 3, 1)]], [1 / 3, S(k, 4)], [1 / 3, S(k + 1, 3)]));
    set(1, 0, 3, comb([1 / 3, Q[qi(2, 0, 2)]], [1 / 3, S(k, 5)], [1 / 3, S(k - 1, 5)]));
    set(0, 1, 3, comb([1 / 3, Q[qi(0, 2, 2)]], [1 / 3, S(k, 5)], [1 / 3, S(k + 1, 5)]));
    set(0, 0, 4, q[18]);
  }
  return Q;
}

/**
 * Sector of a Pm quad at (u, v), its local (s, t, w) and their derivatives with respect to u and v
 * (the c-patch of Myles, Ni, Peters 2008), so the normal is ∂P/∂u × ∂P/∂v in every sector.
 */
export function pmQuadSector(u: number, v: number): { k: number; stw: V3; du: V3; dv: V3 } {
  if (v <= u) {
    if (u + v <= 1) return { k: 0, stw: [1 - u - v, u - v, 2 * v], du: [-1, 1, 0], dv: [-1, -1, 2] };
    return { k: 1, stw: [u - v, u + v - 1, 2 - 2 * u], du: [1, 1, -2], dv: [-1, 1, 0] };
  }
  if (u + v > 1) return { k: 2, stw: [u + v - 1, v - u, 2 - 2 * v], du: [1, -1, 0], dv: [1, 1, -2] };
  return { k: 3, stw: [v - u, 1 - u - v, 2 * u], du: [-1, -1, 2], dv: [1, -1, 0] };
}

/** Sector of a Pm triangle at (u, v) = (λ1, λ2) and derivatives of (s, t, w) (Myles, Ni, Peters 2008). */
export function pmTriSector(u: number, v: number): { k: number; stw: V3; du: V3; dv: V3 } {
  const l0 = 1 - u - v,
    l1 = u,
    l2 = v;
  if (l0 >= l2 && l1 >= l2) return { k: 0, stw: [l0 - l2, l1 - l2, 3 * l2], du: [-1, 1, 0], dv: [-2, -1, 3] };
  if (l2 > l0 && l1 >= l0) return { k: 1, stw: [l1 - l0, l2 - l0, 3 * l0], du: [2, 1, -3], dv: [1, 2, -3] };
  return { k: 2, stw: [l2 - l1, l0 - l1, 3 * l1], du: [-1, -2, 3], dv: [1, -1, 0] };
}

const dirDeriv = (e: { Da: V3; Db: V3; Dc: V3 }, d: V3): V3 => comb([d[0], e.Da], [d[1], e.Db], [d[2], e.Dc]);

const dot3 = (a: V3, b: V3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** Position, ∂/∂u, ∂/∂v and the shading-normal direction of one patch (q = its control points), and
 * the two tangents whose cross product it is (∂/∂u, ∂/∂v but for Bezier ACC's tangent patches). */
export function evalPatchPoints(kind: number, q: V3[], u: number, v: number): { P: V3; Pu: V3; Pv: V3; n: V3; tangents: [V3, V3] } {
  switch (kind) {
    case KIND_REGULAR: {
      const r = evalBicubic(q, u, v);
      return { ...r, n: cross3(r.Pu, r.Pv), tangents: [r.Pu, r.Pv] };
    }
    case KIND_BEZIER: {
      const r = evalBicubic(q, u, v);
      const t = evalTangentPatches(q, u, v);
      return { ...r, n: cross3(t.Tu, t.Tv), tangents: [t.Tu, t.Tv] };
    }
    case KIND_GREGORY_QUAD: {
      // Derivatives of the frozen Bézier (blend weights' derivatives ignored, as the sample and OpenSubdiv).
      const r = evalBicubic(gregoryQuadBezier(q, u, v), u, v);
      return { ...r, n: cross3(r.Pu, r.Pv), tangents: [r.Pu, r.Pv] };
    }
    case KIND_GREGORY_TRI: {
      const l: V3 = [1 - u - v, u, v];
      const e = evalQuartic(gregoryTriQuartic(q, l), l[0], l[1], l[2]);
      const Pu = subv(e.Db, e.Da),
        Pv = subv(e.Dc, e.Da);
      return { P: e.P, Pu, Pv, n: cross3(Pu, Pv), tangents: [Pu, Pv] };
    }
    case KIND_PM_QUAD:
    case KIND_PM_TRI:
    case KIND_PM_TRI_LS: {
      const m = kind === KIND_PM_QUAD ? 4 : 3;
      const s = m === 4 ? pmQuadSector(u, v) : pmTriSector(u, v);
      const e = evalQuartic(pmSectorQuartic(q, m, s.k), s.stw[0], s.stw[1], s.stw[2]);
      const Pu = dirDeriv(e, s.du),
        Pv = dirDeriv(e, s.dv);
      return { P: e.P, Pu, Pv, n: cross3(Pu, Pv), tangents: [Pu, Pv] };
    }
    default:
      throw new AccError(`unknown patch kind ${kind}`);
  }
}

/** An ACC surface of a cage: topology, control points (f64) and evaluation by (face, u, v). */
export class AccSurface {
  readonly topology: AccTopology;
  points: Float64Array;
  constructor(
    readonly cage: Cage,
    readonly scheme: AccScheme,
    topology?: Topology,
    options: AccOptions = {},
  ) {
    this.topology = buildAccTopology(cage, scheme, topology, options);
    this.points = buildAccPoints(this.topology, cage.positions);
  }

  /** Rebuild the control points for new cage positions (same connectivity). */
  update(positions: ArrayLike<number>): void {
    this.points = buildAccPoints(this.topology, positions);
  }

  kind(face: number): number {
    return this.topology.patches[2 * face];
  }

  /** The control points of a patch. */
  patch(face: number): V3[] {
    const kind = this.topology.patches[2 * face],
      o = this.topology.patches[2 * face + 1];
    const out: V3[] = [];
    for (let i = 0; i < KIND_POINTS[kind]; i++)
      out.push([this.points[3 * (o + i)], this.points[3 * (o + i) + 1], this.points[3 * (o + i) + 2]]);
    return out;
  }

  /** Position, derivatives and unit shading normal at (face, u, v) (triangles: (u, v) = (w1, w2)).
   * Where the two tangents whose cross product is the normal are parallel (the corner of a crease
   * sector of one face, θ = π; a corner sector's degenerate corner) the normal is the patch's
   * own approached from inside, as wgsl/acc/surface.wgsl evalAccPatch says why: evaluated
   * ACC_DEGENERATE_STEP of the way toward the centroid of (corner, next corner, centre). */
  evaluate(face: number, u: number, v: number): AccPoint & { Pu: V3; Pv: V3 } {
    const kind = this.kind(face),
      q = this.patch(face);
    const r = evalPatchPoints(kind, q, u, v);
    let n = r.n;
    const [a, b] = r.tangents;
    if (dot3(n, n) <= ACC_DEGENERATE_SIN ** 2 * dot3(a, a) * dot3(b, b)) {
      // Toward the centroid of (corner, next corner counter-clockwise, centre): off the diagonal,
      // where a Pm patch's sectors meet.
      const tri = this.topology.faceSize[face] === 3;
      const c = tri ? 1 / 3 : 0.5;
      const [nu, nv] = tri ? [1 - u - v, u] : [1 - v, u];
      const du = (u + nu + c) / 3 - u,
        dv = (v + nv + c) / 3 - v;
      n = evalPatchPoints(kind, q, u + ACC_DEGENERATE_STEP * du, v + ACC_DEGENERATE_STEP * dv).n;
    }
    return { P: r.P, Pu: r.Pu, Pv: r.Pv, N: normalize3(n) };
  }
}
