/**
 * The GPU's Catmull-Clark evaluation (wgsl/surface-cc.wgsl) line for line on the CPU in f64,
 * over the same tables (build.ts): for tests of the tables themselves, and as the documentation
 * of what the WGSL does.
 */
import { bsplineBasis } from '../../subdiv/bspline.ts';
import { ANCHOR, NODE_INTERNAL, NODE_PATCH, NO_NODE, type CatmullClarkData } from './build.ts';

type V3 = [number, number, number];

/** Control points from cage positions (the patch-build pass). */
export function controlPoints(cc: CatmullClarkData, positions: ArrayLike<number>): Float64Array {
  const out = new Float64Array(3 * cc.ctrlCount);
  for (let i = 0; i < cc.ctrlCount; i++) {
    for (let e = cc.rows[i]; e < cc.rows[i + 1]; e++) {
      const v = cc.entryVertex[e], w = cc.entryWeight[e];
      for (let c = 0; c < 3; c++) out[3 * i + c] += w * positions[3 * v + c];
    }
  }
  return out;
}

export interface CCPoint {
  P: V3;
  N: V3;
  /** Evaluated in the blended region round an irregular vertex (not the exact limit there). */
  blended: boolean;
  depth: number;
  /** Kind of the patch that gave the point (build.ts PatchKind). */
  kind: number;
  /** Blended round a smooth interior extraordinary vertex (the radial blend's exponent is exact there). */
  smoothEV: boolean;
}

const cross = (a: V3, b: V3): V3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a: V3): V3 => {
  const l = Math.hypot(a[0], a[1], a[2]);
  return l > 0 ? [a[0] / l, a[1] / l, a[2] / l] : [0, 0, 1];
};
const pt = (ctrl: Float64Array, i: number): V3 => [ctrl[3 * i], ctrl[3 * i + 1], ctrl[3 * i + 2]];

function evalPatch(ctrl: Float64Array, base: number, x: number, y: number): { P: V3; N: V3 } {
  const bu = [0, 0, 0, 0], du = [0, 0, 0, 0], bv = [0, 0, 0, 0], dv = [0, 0, 0, 0];
  bsplineBasis(x, bu, du);
  bsplineBasis(y, bv, dv);
  const P: V3 = [0, 0, 0], Pu: V3 = [0, 0, 0], Pv: V3 = [0, 0, 0];
  const A = pt(ctrl, base + ANCHOR);
  for (let r = 0; r < 4; r++) {
    for (let c = 0; c < 4; c++) {
      const i = 4 * r + c;
      if (i === ANCHOR) continue;
      const p = pt(ctrl, base + i); // offset from the anchor
      for (let q = 0; q < 3; q++) {
        P[q] += bu[c] * bv[r] * p[q];
        Pu[q] += du[c] * bv[r] * p[q];
        Pv[q] += bu[c] * dv[r] * p[q];
      }
    }
  }
  return { P: [A[0] + P[0], A[1] + P[1], A[2] + P[2]], N: norm(cross(Pu, Pv)) };
}

function descend(cc: CatmullClarkData, node: number, x: number, y: number): { node: number; x: number; y: number; depth: number } {
  let depth = 0;
  for (; depth < 40; depth++) {
    const w0 = cc.nodes[4 * node];
    if ((w0 & 3) !== NODE_INTERNAL) break;
    const i = x >= 0.5 ? 1 : 0, j = y >= 0.5 ? 1 : 0;
    x = 2 * x - i;
    y = 2 * y - j;
    node = cc.nodes[4 * node + 1] + i + 2 * j;
  }
  return { node, x, y, depth };
}

/** The surface at (x,y) of the quadtree rooted at `root`. */
export function evalRoot(cc: CatmullClarkData, ctrl: Float64Array, root: number, x: number, y: number): CCPoint {
  const d = descend(cc, root, x, y);
  const w0 = cc.nodes[4 * d.node];
  const kind = (w0 >> 4) & 7;
  if ((w0 & 3) === NODE_PATCH) return { ...evalPatch(ctrl, cc.nodes[4 * d.node + 1], d.x, d.y), blended: false, depth: d.depth, kind, smoothEV: false };
  // Unresolved: radial blend between the limit point and the neighbouring regular patch.
  const lim = cc.nodes[4 * d.node + 1];
  const P0 = pt(ctrl, lim);
  const N0 = norm(cross(pt(ctrl, lim + 1), pt(ctrl, lim + 2)));
  const rc = (w0 >> 2) & 3;
  const alpha = (w0 >>> 8) / 4096;
  const smoothEV = ((w0 >> 7) & 1) === 1;
  const cx = rc === 1 || rc === 2 ? 1 : 0, cy = rc >= 2 ? 1 : 0;
  const a = Math.abs(d.x - cx), b = Math.abs(d.y - cy);
  const t = Math.max(a, b);
  if (t === 0) return { P: P0, N: N0, blended: true, depth: d.depth, kind, smoothEV };
  let sib: number, sx: number, sy: number;
  if (a >= b) {
    sib = cc.nodes[4 * d.node + 2];
    sx = cx;
    sy = cy === 0 ? b / t : 1 - b / t;
  } else {
    sib = cc.nodes[4 * d.node + 3];
    sy = cy;
    sx = cx === 0 ? a / t : 1 - a / t;
  }
  if (sib === NO_NODE) return { P: P0, N: N0, blended: true, depth: d.depth, kind, smoothEV };
  const s = descend(cc, sib, sx, sy);
  if ((cc.nodes[4 * s.node] & 3) !== NODE_PATCH) return { P: P0, N: N0, blended: true, depth: d.depth, kind, smoothEV };
  const q = evalPatch(ctrl, cc.nodes[4 * s.node + 1], s.x, s.y);
  const f = Math.pow(t, alpha);
  const P: V3 = [0, 1, 2].map((c) => P0[c] + f * (q.P[c] - P0[c])) as V3;
  const N = norm([0, 1, 2].map((c) => N0[c] + f * (q.N[c] - N0[c])) as V3);
  return { P, N, blended: true, depth: d.depth, kind, smoothEV };
}

/** Root node and (x,y) of a point given as the CPU reference's face parameter. */
export function rootOf(cc: CatmullClarkData, t: number, k: number): number {
  return cc.triRoot[3 * t] + k;
}
