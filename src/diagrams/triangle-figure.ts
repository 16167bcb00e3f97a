/**
 * The triangle figures: (parameters, time) → drawing. One panel per mode, side by side, every
 * pattern drawn in the clamped construction's FRAME (corner A bottom left, B bottom right, C at
 * the top; the bottom, left and right edges carry the factors of the frame's edges), so that a
 * factor sits on the same screen edge in every panel. D3D11's corner for its barycentric i is
 * our corner (i + 2) mod 3: D3D11's edge factor i (the edge where component i is 0) then lies on
 * our edge i, as the pattern CLI numbers them.
 *
 * The clamped panels can show the construction's stages (`stage`): the parallelogram, the clamp
 * without a gap (an illustration of the rejected step, drawn here from the two edge lines), the
 * clamp with the gap and the open strip, the gap matching, and the full pattern. Counts are of
 * what is drawn; at `full` (and `match`) they are the pattern's own, as the CLI prints them.
 *
 * Below 600 px of available width the panels are laid out again for a phone: one or two columns
 * at one scene unit per CSS px, each triangle as large as its cell allows with the edge labels
 * beside it (all of this figure's type is 11 px or more already; the wide layout shrinks it).
 */
import { chooseFrame, clampedConstruction, type PatternFrame } from '../pattern/clamped.ts';
import { d3d11Triangle } from '../pattern/d3d11.ts';
import { ONE } from '../pattern/fixed.ts';
import { line } from '../pattern/line.ts';
import type { D3D11Partitioning, TriMode } from '../pattern/types.ts';
import { TRI_MODE_LABEL, fmtFactor, plural } from './labels.ts';
import { compactWidth, type FactorValue, type FigureFrame, type PanelCounts } from './model.ts';
import type { Shape, TriParams } from './params.ts';
import { SceneBuilder, type Role } from './scene.ts';
import { isAnimated, phaseAt, snapValue, trackValue, type Track } from './timeline.ts';

export const TRI_WIDTH = 760;

/** A pattern in frame barycentrics (w_A, w_B, w_C), fixed point. */
export interface FramePattern {
  bary: number[];
  triangles: number[];
  vertexCount: number;
  triangleCount: number;
  /** Clamped only: triangles [0, gridTriangleCount) are the grid, the rest the gap strip. */
  gridTriangleCount?: number;
  /** Clamped only: the clamp line u + v = c. */
  c?: number;
}

export interface TriFactors {
  edges: [number, number, number];
  /** D3D11's inside factor (the mean of the edges unless given). */
  inside: number;
}

const valueAt = (tr: Track, p: TriParams, s: number) => {
  const v = trackValue(tr, s, p.ease);
  return p.snap ? snapValue(v) : v;
};

export function triFactorsAt(p: TriParams, t: number): TriFactors {
  const s = phaseAt(p.timing, t);
  const edges = p.factors.map((tr) => valueAt(tr, p, s)) as [number, number, number];
  const inside = p.inside ? valueAt(p.inside, p, s) : (edges[0] + edges[1] + edges[2]) / 3;
  return { edges, inside };
}

/** The pattern of one panel in frame coordinates (no copies of pattern logic: only relabelling). */
export function framePattern(
  mode: TriMode,
  fc: TriFactors,
  reverse: readonly [boolean, boolean, boolean],
  maxFactor: number,
): FramePattern {
  if (mode === 'clamped') {
    const { framed } = clampedConstruction(fc.edges, reverse, { maxFactor });
    return framed;
  }
  const frame = chooseFrame(reverse);
  const pat = d3d11Triangle(mode as D3D11Partitioning, [...fc.edges], fc.inside);
  // Our corner k holds D3D11 component (k + 1) mod 3.
  const comp = (corner: number) => (corner + 1) % 3;
  const bary = new Array<number>(pat.bary.length);
  for (let v = 0; v < pat.vertexCount; v++) {
    bary[3 * v] = pat.bary[3 * v + comp(frame.a)];
    bary[3 * v + 1] = pat.bary[3 * v + comp(frame.b)];
    bary[3 * v + 2] = pat.bary[3 * v + comp(frame.c)];
  }
  return { bary, triangles: pat.triangles, vertexCount: pat.vertexCount, triangleCount: pat.triangleCount };
}

/** Twice the signed area of triangle t in the (w_B, w_C) plane, exact. */
function area2(bary: number[], a: number, b: number, c: number): number {
  const ux = bary[3 * b + 1] - bary[3 * a + 1];
  const uy = bary[3 * b + 2] - bary[3 * a + 2];
  const vx = bary[3 * c + 1] - bary[3 * a + 1];
  const vy = bary[3 * c + 2] - bary[3 * a + 2];
  return ux * vy - uy * vx;
}

export function degenerateCount(p: { bary: number[]; triangles: number[] }, from = 0, to = p.triangles.length / 3): number {
  let n = 0;
  for (let t = from; t < to; t++) if (area2(p.bary, p.triangles[3 * t], p.triangles[3 * t + 1], p.triangles[3 * t + 2]) === 0) n++;
  return n;
}

// ---------------------------------------------------------------------------------------------
// Geometry on screen
// ---------------------------------------------------------------------------------------------

type V2 = [number, number];

/** Corners A, B, C of each shape in a unit box (y down). */
function shapeCorners(shape: Shape): [V2, V2, V2] {
  if (shape === 'right')
    return [
      [0, 1],
      [1, 1],
      [0, 0],
    ];
  if (shape === 'thin')
    return [
      [0, 1],
      [0.26, 1],
      [0.13, 0],
    ];
  const h = Math.sqrt(3) / 2;
  return [
    [0, h],
    [1, h],
    [0.5, 0],
  ];
}

class Mapper {
  constructor(
    readonly A: V2,
    readonly B: V2,
    readonly C: V2,
  ) {}
  /** Frame (u, v) in [0, 1] (u toward B, v toward C) to screen. */
  uv(u: number, v: number): V2 {
    return [
      this.A[0] + u * (this.B[0] - this.A[0]) + v * (this.C[0] - this.A[0]),
      this.A[1] + u * (this.B[1] - this.A[1]) + v * (this.C[1] - this.A[1]),
    ];
  }
  /** Fixed-point frame barycentrics of vertex i. */
  vert(bary: number[], i: number): V2 {
    return this.uv(bary[3 * i + 1] / ONE, bary[3 * i + 2] / ONE);
  }
}

const flat = (pts: V2[]) => pts.flat();

// ---------------------------------------------------------------------------------------------
// Which vertices move
// ---------------------------------------------------------------------------------------------

const EPS = 1 / 512;

/** Vertices whose position changes when the factors change a little (the factors this figure
 * animates, or its fractional ones if it is static): they are sliding or new. */
function movingVertices(mode: TriMode, p: TriParams, fc: TriFactors, pat: FramePattern): boolean[] {
  const anim = p.factors.map(isAnimated);
  const insideAnim = p.inside ? isAnimated(p.inside) : anim.some(Boolean);
  const any = anim.some(Boolean) || insideAnim;
  const bump = (v: number, animated: boolean) => (any ? (animated ? v + EPS : v) : Number.isInteger(v) ? v : v + EPS);
  const edges = fc.edges.map((v, i) => bump(v, anim[i])) as [number, number, number];
  const inside = p.inside ? bump(fc.inside, insideAnim) : (edges[0] + edges[1] + edges[2]) / 3;
  if (edges.every((v, i) => v === fc.edges[i]) && inside === fc.inside) return new Array(pat.vertexCount).fill(false);
  const other = framePattern(mode, { edges, inside }, p.reverse, p.maxFactor);
  const seen = new Set<string>();
  for (let v = 0; v < other.vertexCount; v++) seen.add(`${other.bary[3 * v + 1]},${other.bary[3 * v + 2]}`);
  const out: boolean[] = [];
  for (let v = 0; v < pat.vertexCount; v++) out.push(!seen.has(`${pat.bary[3 * v + 1]},${pat.bary[3 * v + 2]}`));
  return out;
}

// ---------------------------------------------------------------------------------------------
// Drawing one panel
// ---------------------------------------------------------------------------------------------

interface PanelBox {
  m: Mapper;
  /** Panel frame on screen: title baseline, centre x, bottom of the drawing. */
  x: number;
  y: number;
  w: number;
  h: number;
}

function countsLine(c: PanelCounts): string {
  return `${plural(c.triangles, 'triangle')} · ${plural(c.vertices, 'vertex', 'vertices')} · ${c.degenerate} degenerate`;
}

function drawMesh(
  b: SceneBuilder,
  m: Mapper,
  pat: FramePattern,
  from: number,
  to: number,
  fill: Role,
  edges: boolean,
  loops: boolean,
): void {
  const tris: number[][] = [];
  for (let t = from; t < to; t++) {
    const [a, c, d] = [pat.triangles[3 * t], pat.triangles[3 * t + 1], pat.triangles[3 * t + 2]];
    tris.push(flat([m.vert(pat.bary, a), m.vert(pat.bary, c), m.vert(pat.bary, d)]));
  }
  b.path(tris, { fill, stroke: fill, width: 0.6 }, true);
  if (!edges) return;
  if (!loops) {
    b.path(tris, { stroke: 'ink', width: 0.75, opacity: 0.85 }, true);
    return;
  }
  // Edge loops: every edge coloured by its direction in the frame.
  const fam: Record<'row' | 'col' | 'diag' | 'other', number[][]> = { row: [], col: [], diag: [], other: [] };
  const done = new Set<string>();
  for (let t = from; t < to; t++) {
    for (let k = 0; k < 3; k++) {
      const i = pat.triangles[3 * t + k];
      const j = pat.triangles[3 * t + ((k + 1) % 3)];
      const key = i < j ? `${i},${j}` : `${j},${i}`;
      if (done.has(key)) continue;
      done.add(key);
      const du = pat.bary[3 * j + 1] - pat.bary[3 * i + 1];
      const dv = pat.bary[3 * j + 2] - pat.bary[3 * i + 2];
      if (du === 0 && dv === 0) continue;
      const seg = flat([m.vert(pat.bary, i), m.vert(pat.bary, j)]);
      (dv === 0 ? fam.row : du === 0 ? fam.col : du + dv === 0 ? fam.diag : fam.other).push(seg);
    }
  }
  b.path(fam.other, { stroke: 'faint', width: 0.7 });
  b.path(fam.row, { stroke: 'blue', width: 1.5 });
  b.path(fam.col, { stroke: 'orange', width: 1.5 });
  b.path(fam.diag, { stroke: 'green', width: 1.5 });
}

function drawVertices(b: SceneBuilder, m: Mapper, pat: FramePattern, moving: boolean[], r: number): void {
  const still: number[] = [];
  const mov: number[] = [];
  for (let v = 0; v < pat.vertexCount; v++) (moving[v] ? mov : still).push(...m.vert(pat.bary, v));
  b.dots(still, r, 'ink');
  b.dots(mov, r + 0.9, 'accent');
}

function outline(b: SceneBuilder, m: Mapper): void {
  b.path([flat([m.A, m.B, m.C])], { stroke: 'ink', width: 1.6 }, true);
}

const EDGE_LABEL_PX = 11;

interface LabelSpot {
  x: number;
  y: number;
  anchor: 'start' | 'middle' | 'end';
}

/** Where the edge factor labels go, outside each edge: bottom, left, right of the frame. */
function edgeLabelSpots(m: Mapper, shape: Shape): [LabelSpot, LabelSpot, LabelSpot] {
  const cx = (m.A[0] + m.B[0] + m.C[0]) / 3;
  const cy = (m.A[1] + m.B[1] + m.C[1]) / 3;
  const put = (P: V2, Q: V2, extra = 0): LabelSpot => {
    const mx = (P[0] + Q[0]) / 2;
    const my = (P[1] + Q[1]) / 2;
    let nx = mx - cx;
    let ny = my - cy;
    const len = Math.hypot(nx, ny) || 1;
    nx /= len;
    ny /= len;
    const d = 16 + extra + (Math.abs(nx) > 0.35 && Math.abs(ny) > 0.35 ? 6 : 0);
    const x = mx + nx * d;
    const y = my + ny * d + 4;
    const anchor = Math.abs(nx) < 0.35 ? 'middle' : nx < 0 ? 'end' : 'start';
    return { x, y, anchor };
  };
  return [put(m.A, m.B, 2), put(m.A, m.C, shape === 'thin' ? 4 : 0), put(m.B, m.C, shape === 'thin' ? 4 : 0)];
}

function edgeLabels(b: SceneBuilder, m: Mapper, frame: PatternFrame, fc: TriFactors, shape: Shape): void {
  const spots = edgeLabelSpots(m, shape);
  [frame.bottomEdge, frame.leftEdge, frame.rightEdge].forEach((edge, k) => {
    const { x, y, anchor } = spots[k];
    b.text(x, y, `f${edge} ${fmtFactor(fc.edges[edge])}`, EDGE_LABEL_PX, 'muted', { anchor, mono: true });
  });
}

/**
 * The horizontal extent of a triangle drawn at scale S with its edge labels, relative to the
 * left of the triangle's box. A label is taken as 8 monospaced characters ("f0 12.00"), 0.6 em
 * each, the advance of the usual monospaced fonts.
 */
function extentWithLabels(corners: [V2, V2, V2], S: number, shape: Shape, ticks: boolean): [number, number] {
  const minX = Math.min(...corners.map((c) => c[0]));
  const minY = Math.min(...corners.map((c) => c[1]));
  const at = (c: V2): V2 => [(c[0] - minX) * S, (c[1] - minY) * S];
  const m = new Mapper(at(corners[0]), at(corners[1]), at(corners[2]));
  const w = 8 * 0.6 * EDGE_LABEL_PX;
  let lo = 0;
  let hi = Math.max(...corners.map((c) => (c[0] - minX) * S));
  if (ticks) {
    // The clamp stage's ticks stand 13 units outside the third edge (drawClampNoGap).
    const mid = m.uv(0.5, 0.5);
    const cx = (m.A[0] + m.B[0] + m.C[0]) / 3;
    const cy = (m.A[1] + m.B[1] + m.C[1]) / 3;
    const nx = (mid[0] - cx) / (Math.hypot(mid[0] - cx, mid[1] - cy) || 1);
    for (const P of [m.B, m.C]) {
      lo = Math.min(lo, P[0] + nx * 13);
      hi = Math.max(hi, P[0] + nx * 13);
    }
  }
  for (const { x, anchor } of edgeLabelSpots(m, shape)) {
    const left = anchor === 'start' ? x : anchor === 'end' ? x - w : x - w / 2;
    lo = Math.min(lo, left);
    hi = Math.max(hi, left + w);
  }
  return [lo, hi];
}

/** Frame lines and their moving flags (for the parallelogram and clamp stages). */
function framedLines(p: TriParams, fc: TriFactors) {
  const con = clampedConstruction(fc.edges, p.reverse, { maxFactor: p.maxFactor });
  const flags = (edge: number, flip: boolean) => {
    const mv = line('hable', fc.edges[edge], { maxFactor: p.maxFactor }).moving;
    return flip ? [...mv].reverse() : mv;
  };
  return {
    con,
    u: con.bottom.x.map((v) => v / ONE),
    v: con.left.x.map((v) => v / ONE),
    r: con.right.x.map((v) => v / ONE),
    uMoving: flags(con.frame.bottomEdge, con.frame.flipBottom),
    vMoving: flags(con.frame.leftEdge, con.frame.flipLeft),
  };
}

function drawParallelogram(b: SceneBuilder, box: PanelBox, p: TriParams, fc: TriFactors): PanelCounts {
  const { m } = box;
  const L = framedLines(p, fc);
  const D = m.uv(1, 1);
  b.path([flat([m.A, m.B, D, m.C])], { fill: 'fillOut', stroke: 'faint', width: 1, dash: [4, 4] }, true);
  b.path([flat([m.A, m.B, m.C])], { fill: 'fill' }, true);
  const rows = L.v.map((v) => flat([m.uv(0, v), m.uv(1, v)]));
  const cols = L.u.map((u) => flat([m.uv(u, 0), m.uv(u, 1)]));
  b.path([...rows, ...cols], { stroke: 'ink', width: 0.8, opacity: 0.8 });
  // Quad diagonals, as the grid's triangles.
  const diag: number[][] = [];
  for (let i = 0; i + 1 < L.u.length; i++)
    for (let j = 0; j + 1 < L.v.length; j++) diag.push(flat([m.uv(L.u[i], L.v[j]), m.uv(L.u[i + 1], L.v[j + 1])]));
  b.path(diag, { stroke: 'ink', width: 0.5, opacity: 0.35 });
  outline(b, m);
  const still: number[] = [];
  const mov: number[] = [];
  L.u.forEach((u, i) => L.v.forEach((v, j) => (L.uMoving[i] || L.vMoving[j] ? mov : still).push(...m.uv(u, v))));
  if (p.points) {
    b.dots(still, 2.2, 'ink');
    b.dots(mov, 3, 'accent');
  }
  const nb = L.u.length - 1;
  const nl = L.v.length - 1;
  let zero = 0;
  for (let i = 0; i < nb; i++) for (let j = 0; j < nl; j++) if (L.u[i] === L.u[i + 1] || L.v[j] === L.v[j + 1]) zero += 2;
  return { mode: 'clamped', label: 'parallelogram grid', vertices: (nb + 1) * (nl + 1), triangles: 2 * nb * nl, degenerate: zero };
}

function drawClampNoGap(b: SceneBuilder, box: PanelBox, p: TriParams, fc: TriFactors): PanelCounts {
  const { m } = box;
  const L = framedLines(p, fc);
  b.path([flat([m.A, m.B, m.C])], { fill: 'fill' }, true);
  // The grid clamped at u ≤ 1 − v: vertex (i, j) at (min(u_i, 1 − v_j), v_j).
  const q = (i: number, j: number): [number, number] => [Math.min(L.u[i], 1 - L.v[j]), L.v[j]];
  const tris: number[][] = [];
  let degenerate = 0;
  let count = 0;
  const nb = L.u.length - 1;
  const nl = L.v.length - 1;
  const area = (a: [number, number], c: [number, number], d: [number, number]) =>
    (c[0] - a[0]) * (d[1] - a[1]) - (c[1] - a[1]) * (d[0] - a[0]);
  for (let j = 0; j < nl; j++) {
    for (let i = 0; i < nb; i++) {
      if (L.u[i] >= 1 - L.v[j] && i > 0) continue; // both corners already on the hypotenuse: nothing left
      for (const t of [
        [q(i, j), q(i + 1, j), q(i + 1, j + 1)],
        [q(i, j), q(i + 1, j + 1), q(i, j + 1)],
      ] as [number, number][][]) {
        count++;
        if (Math.abs(area(t[0], t[1], t[2])) < 1e-12) {
          degenerate++;
          continue;
        }
        tris.push(flat(t.map(([u, v]) => m.uv(u, v))));
      }
    }
  }
  b.path(tris, { stroke: 'ink', width: 0.75, opacity: 0.85 }, true);
  outline(b, m);
  // Points: grid points inside, and the ones the clamp pushed onto the hypotenuse (hollow).
  const inside: number[] = [];
  const movingPts: number[] = [];
  const collapsed: number[] = [];
  const seen = new Set<string>();
  L.u.forEach((u, i) =>
    L.v.forEach((v, j) => {
      const [cu, cv] = q(i, j);
      const key = `${cu},${cv}`;
      if (seen.has(key)) return;
      seen.add(key);
      const pt = m.uv(cu, cv);
      if (u > 1 - v) collapsed.push(...pt);
      else (L.uMoving[i] || L.vMoving[j] ? movingPts : inside).push(...pt);
    }),
  );
  if (p.points) {
    b.dots(inside, 2.2, 'ink');
    b.dots(movingPts, 3, 'accent');
    b.dots(collapsed, 3.6, 'bg', 'accent', 1.4);
  }
  // The third edge's own line, ticked outside the hypotenuse: it does not match.
  const cx = (m.A[0] + m.B[0] + m.C[0]) / 3;
  const cy = (m.A[1] + m.B[1] + m.C[1]) / 3;
  const mid = m.uv(0.5, 0.5);
  let nx = mid[0] - cx;
  let ny = mid[1] - cy;
  const len = Math.hypot(nx, ny);
  nx /= len;
  ny /= len;
  const ticks = L.r.map((x) => {
    const P = m.uv(1 - x, x);
    return [P[0] + nx * 5, P[1] + ny * 5, P[0] + nx * 13, P[1] + ny * 13];
  });
  b.path(ticks, { stroke: 'blue', width: 2 });
  return { mode: 'clamped', label: 'clamped grid, no gap', vertices: seen.size, triangles: count, degenerate };
}

function drawClamped(b: SceneBuilder, box: PanelBox, p: TriParams, pat: FramePattern): void {
  const { m } = box;
  const grid = pat.gridTriangleCount ?? pat.triangleCount;
  const strip = p.stage === 'match' ? 'fillAlt' : 'fill';
  if (p.stage === 'gap') {
    drawMesh(b, m, pat, grid, pat.triangleCount, 'fillAlt', false, false);
    drawMesh(b, m, pat, 0, grid, 'fill', true, p.loops);
  } else {
    drawMesh(b, m, pat, 0, grid, 'fill', true, p.loops);
    drawMesh(b, m, pat, grid, pat.triangleCount, strip, true, p.loops);
  }
  if ((p.stage === 'gap' || p.stage === 'match') && pat.c !== undefined) {
    const c = pat.c / ONE;
    const P = m.uv(c, 0);
    const Q = m.uv(0, c);
    b.line(P[0], P[1], Q[0], Q[1], 'orange', 1.8, [5, 4]);
  }
  outline(b, m);
}

interface TriLayout {
  W: number;
  cols: number;
  rows: number;
  /** Scene units per unit of the shape's box. */
  S: number;
  bw: number;
  bh: number;
  corners: [V2, V2, V2];
  /** Where the triangle's box starts, from the left of its cell (centred: the box, or on a
   * phone the box with its edge labels). */
  inset: number;
}

function layout(n: number, shape: Shape, stage: TriParams['stage'], modes: TriMode[], width: number | undefined): TriLayout {
  const corners = shapeCorners(shape);
  const withD = stage === 'parallelogram' && modes.includes('clamped');
  const xs = corners.map((c) => c[0]);
  const ys = corners.map((c) => c[1]);
  if (withD) {
    xs.push(corners[1][0] + corners[2][0] - corners[0][0]);
    ys.push(corners[1][1] + corners[2][1] - corners[0][1]);
  }
  const bw = Math.max(...xs) - Math.min(...xs);
  const bh = Math.max(...ys) - Math.min(...ys);
  const narrow = compactWidth(width);
  if (narrow === null) {
    const cols = n <= 3 ? n : Math.ceil(n / 2);
    const rows = Math.ceil(n / cols);
    const avail = (TRI_WIDTH - 40 - (cols - 1) * 56) / cols;
    const maxH = shape === 'thin' ? 440 : n === 1 ? 380 : rows > 1 ? 250 : 300;
    const S = Math.min(maxH / bh, (avail - 24) / bw);
    return { W: TRI_WIDTH, cols, rows, S, bw, bh, corners, inset: (TRI_WIDTH / cols - bw * S) / 2 };
  }
  // A phone: a column per 290 px (one on a phone, two in a wider column), each triangle as large
  // as its cell allows with its edge labels beside it, but no taller than 300 px (360 for the
  // thin shape), so that a panel and its counts fit on the screen at once.
  const cols = Math.max(1, Math.min(n, Math.floor(narrow / 290)));
  const rows = Math.ceil(n / cols);
  const cellW = narrow / cols;
  const room = cellW - 12;
  const maxH = shape === 'thin' ? 360 : 300;
  let lo = 0;
  let hi = maxH / bh;
  const fits = (S: number) => {
    const [l, r] = extentWithLabels(corners, S, shape, stage === 'clamp');
    return r - l <= room && (withD ? bw * S <= room : true);
  };
  if (fits(hi)) lo = hi;
  else for (let i = 0; i < 40; i++) fits((lo + hi) / 2) ? (lo = (lo + hi) / 2) : (hi = (lo + hi) / 2);
  const S = lo;
  const [l, r] = extentWithLabels(corners, S, shape, stage === 'clamp');
  // The parallelogram stage draws past the triangle (its fourth corner D) but has no labels there.
  const [el, er] = withD ? [Math.min(l, 0), Math.max(r, bw * S)] : [l, r];
  return { W: narrow, cols, rows, S, bw, bh, corners, inset: (cellW - (er - el)) / 2 - el };
}

/**
 * The frame at time t, laid out for `width` CSS px of available width: the wide layout (760 px,
 * scaled to fit) unless that is under 600 px, then the compact one at exactly that width.
 */
export function triangleFigure(p: TriParams, t: number, title = 'Triangle patterns', width?: number): FigureFrame {
  const fc = triFactorsAt(p, t);
  const b = new SceneBuilder();
  const counts: PanelCounts[] = [];
  const n = p.modes.length;
  const L = layout(n, p.shape, p.stage, p.modes, width);
  const frame = chooseFrame(p.reverse);
  const minX = Math.min(...L.corners.map((c) => c[0]));
  const minY = Math.min(...L.corners.map((c) => c[1]));
  const headH = 56;
  const footH = 52;
  const cellW = L.W / L.cols;
  const cellH = headH + L.bh * L.S + footH;
  const hasD3D = p.modes.some((m) => m !== 'clamped');
  p.modes.forEach((mode, k) => {
    const col = k % L.cols;
    const row = Math.floor(k / L.cols);
    const itemsInRow = Math.min(L.cols, n - row * L.cols);
    const offset = ((L.cols - itemsInRow) * cellW) / 2;
    const cx = offset + col * cellW + cellW / 2;
    const top = row * cellH + headH;
    const x0 = offset + col * cellW + L.inset;
    const tr = (c: V2): V2 => [x0 + (c[0] - minX) * L.S, top + (c[1] - minY) * L.S];
    const m = new Mapper(tr(L.corners[0]), tr(L.corners[1]), tr(L.corners[2]));
    const box: PanelBox = { m, x: cx, y: top, w: L.bw * L.S, h: L.bh * L.S };
    let c: PanelCounts;
    if (mode === 'clamped' && p.stage === 'parallelogram') c = drawParallelogram(b, box, p, fc);
    else if (mode === 'clamped' && p.stage === 'clamp') c = drawClampNoGap(b, box, p, fc);
    else {
      const pat = framePattern(mode, fc, p.reverse, p.maxFactor);
      if (mode === 'clamped') {
        drawClamped(b, box, p, pat);
        const grid = pat.gridTriangleCount ?? pat.triangleCount;
        c =
          p.stage === 'gap'
            ? {
                mode,
                label: 'clamped grid (gap open)',
                vertices: pat.vertexCount,
                triangles: grid,
                degenerate: degenerateCount(pat, 0, grid),
              }
            : {
                mode,
                label: TRI_MODE_LABEL[mode],
                vertices: pat.vertexCount,
                triangles: pat.triangleCount,
                degenerate: degenerateCount(pat),
              };
      } else {
        drawMesh(b, m, pat, 0, pat.triangleCount, 'fill', true, p.loops);
        outline(b, m);
        c = {
          mode,
          label: TRI_MODE_LABEL[mode],
          vertices: pat.vertexCount,
          triangles: pat.triangleCount,
          degenerate: degenerateCount(pat),
        };
      }
      if (p.points) drawVertices(b, m, pat, movingVertices(mode, p, fc, pat), pat.vertexCount > 400 ? 1.4 : 2);
    }
    counts.push(c);
    edgeLabels(b, m, frame, fc, p.shape);
    const titleY = row * cellH + 22;
    b.text(cx, titleY, mode === 'clamped' ? c.label : TRI_MODE_LABEL[mode], 13.5, 'ink', { weight: 600, anchor: 'middle' });
    const sub = mode !== 'clamped' && hasD3D ? `inside ${fmtFactor(fc.inside)}` : mode === 'clamped' && hasD3D ? 'no inside factor' : '';
    if (sub) b.text(cx, titleY + 16, sub, 11, 'muted', { anchor: 'middle', mono: mode !== 'clamped' });
    const bottom = top + L.bh * L.S;
    b.text(cx, bottom + 44, countsLine(c), 11.5, 'ink', { anchor: 'middle' });
  });
  const H = L.rows * cellH + 4;
  const factors: FactorValue[] = [...fc.edges.map((value, i) => ({ name: `f${i}`, value, animated: isAnimated(p.factors[i]) }))];
  if (hasD3D) factors.push({ name: 'inside', value: fc.inside, animated: p.inside ? isAnimated(p.inside) : p.factors.some(isAnimated) });
  const desc = `factors ${fc.edges.map(fmtFactor).join(', ')}${hasD3D ? `, inside ${fmtFactor(fc.inside)}` : ''}: ${counts.map((c) => `${c.label} ${countsLine(c)}`).join('; ')}`;
  return { scene: b.build(L.W, H, title, desc), counts, factors };
}
