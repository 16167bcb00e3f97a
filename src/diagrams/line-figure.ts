/**
 * The line figures: (parameters, time) → drawing. Two views:
 *  - `line`: one row per mode at the same factor, points from `line()` with its `moving` flags
 *    in red, optionally segments coloured by size and labelled with their weight (length × f);
 *  - `trace`: one panel per mode, position across and factor upwards, every point's track over
 *    the whole sweep, the current factor as a cursor, and optionally one tracked point in red.
 * Below 600 px of available width both views lay out again for a phone (`Layout.compact`): the
 * mode's name above its row instead of beside it, trace panels stacked, no type under 11 px.
 */
import { ONE } from '../pattern/fixed.ts';
import { line } from '../pattern/line.ts';
import type { LineMode, LinePattern } from '../pattern/types.ts';
import { LINE_MODE_LABEL, fmtFactor, fmtPos, plural } from './labels.ts';
import { compactWidth, MIN_TEXT_PX, type FigureFrame, type PanelCounts } from './model.ts';
import type { LineParams } from './params.ts';
import { SceneBuilder, type Role } from './scene.ts';
import { isAnimated, phaseAt, snapValue, trackValue } from './timeline.ts';

export const LINE_WIDTH = 760;

/** Where a frame is drawn: the scene's width, and whether it is the compact (phone) layout,
 * drawn at one scene unit per CSS px. */
interface Layout {
  W: number;
  compact: boolean;
  /** Size of the small labels (ticks, axis names, weights). */
  small: number;
}

/** The factor shown at time t. */
export function lineFactorAt(p: LineParams, t: number): number {
  const v = trackValue(p.factor, phaseAt(p.timing, t), p.ease);
  return p.snap ? snapValue(v) : v;
}

function linePattern(mode: LineMode, f: number, maxFactor: number): LinePattern {
  return line(mode, f, { maxFactor });
}

export function lineCounts(mode: LineMode, pat: LinePattern): PanelCounts {
  let zero = 0;
  for (let i = 1; i < pat.x.length; i++) if (pat.x[i] === pat.x[i - 1]) zero++;
  return { mode, label: LINE_MODE_LABEL[mode], vertices: pat.x.length, triangles: Math.max(0, pat.x.length - 1), degenerate: zero };
}

/** Segment class for `segments=1`: split (small), not yet split (big) or in between. */
function segmentRole(len: number, f: number): Role {
  let N = 1;
  while (N * 2 <= f + 1e-9) N *= 2;
  const unit = 1 / N;
  if (len >= unit * 0.999) return 'accent';
  if (len <= unit / 2 + 1e-6) return 'green';
  return 'muted';
}

function countsText(c: PanelCounts): string {
  const z = c.degenerate ? ` · ${c.degenerate} zero-length` : '';
  return `${plural(c.vertices, 'point')} · ${plural(c.triangles, 'segment')}${z}`;
}

function header(b: SceneBuilder, p: LineParams, f: number, lay: Layout): void {
  const x = lay.compact ? 14 : 24;
  b.text(x, 34, 'factor', 13, 'muted');
  b.text(x + 46, 34, fmtFactor(f), 20, 'ink', { weight: 600, mono: true });
  if (p.snap) b.text(x + 126, 34, 'whole factors only', 12, 'muted');
}

/** Factor axis under the rows: ticks, the swept range and the current factor. */
function ruler(b: SceneBuilder, p: LineParams, f: number, x0: number, x1: number, y: number, lay: Layout): void {
  const lo = Math.min(...p.factor);
  const hi = Math.max(...p.factor);
  if (!(hi > lo)) return;
  const log = p.ease === 'log';
  const map = (v: number) => x0 + (x1 - x0) * (log ? Math.log(v / lo) / Math.log(hi / lo) : (v - lo) / (hi - lo));
  b.line(x0, y, x1, y, 'faint', 1.5);
  const ticks: number[] = [];
  if (log) {
    for (let v = 1; v <= hi * 1.0001; v *= 2) if (v >= lo - 1e-9) ticks.push(v);
  } else {
    let step = hi - lo <= 16 ? 1 : hi - lo <= 40 ? 4 : 8;
    // A phone's ruler is short: at least 26 px between ticks, or their numbers run together.
    if (lay.compact) while (((x1 - x0) * step) / (hi - lo) < 26) step *= 2;
    for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-9; v += step) ticks.push(v);
  }
  for (const v of ticks) {
    const x = map(v);
    b.line(x, y - 4, x, y + 4, 'faint', 1);
    b.text(x, y + 17, String(v), lay.small, 'muted', { anchor: 'middle' });
  }
  // The compact layout has no margin to the left of the ruler: its name goes under the numbers.
  if (lay.compact) b.text((x0 + x1) / 2, y + 33, 'factor', lay.small, 'muted', { anchor: 'middle' });
  else b.text(x0 - 12, y + 4, 'factor', lay.small, 'muted', { anchor: 'end' });
  const xf = map(Math.min(hi, Math.max(lo, f)));
  b.line(x0, y, xf, y, 'ink', 2);
  b.dots([xf, y], 5, 'ink', 'bg', 2);
}

/** Display units: the whole edge, or the half-edge [0, ½] stretched to [0, 1]. */
const toDisplay = (p: LineParams, x: number) => (p.half ? 2 * x : x);

function drawRows(
  b: SceneBuilder,
  p: LineParams,
  f: number,
  top: number,
  x0: number,
  x1: number,
  counts: PanelCounts[],
  lay: Layout,
): number {
  // Compact: the name and counts above the line (there is no room beside it), the weights
  // between them and the line.
  const rowH = lay.compact ? (p.labels ? 72 : 60) : 66;
  const X = (d: number) => x0 + (x1 - x0) * d;
  p.modes.forEach((mode, r) => {
    const pat = linePattern(mode, f, p.maxFactor);
    const c = lineCounts(mode, pat);
    counts.push(c);
    const rowTop = top + r * rowH;
    const y = lay.compact ? rowTop + (p.labels ? 58 : 46) : rowTop + 30;
    if (lay.compact) {
      b.text(x0, rowTop + 16, LINE_MODE_LABEL[mode], 13.5, 'ink', { weight: 600 });
      b.text(x0, rowTop + 31, countsText(c), 11, 'muted');
    } else {
      b.text(24, y - 3, LINE_MODE_LABEL[mode], 13.5, 'ink', { weight: 600 });
      b.text(24, y + 14, countsText(c), 11, 'muted');
    }
    const xs = pat.x.map((v) => toDisplay(p, v / ONE));
    const n = xs.length;
    // Segments.
    if (n === 0) {
      b.text(X(0.5), y + 4, 'culled (no points)', 12, 'muted', { anchor: 'middle' });
      return;
    }
    if (!p.segments) b.line(X(0), y, X(Math.min(1, xs[n - 1])), y, 'faint', 2.5);
    for (let i = 1; i < n; i++) {
      const a = xs[i - 1];
      const e = xs[i];
      if (a >= 1 + 1e-9) break;
      const len = (pat.x[i] - pat.x[i - 1]) / ONE;
      if (p.segments) b.line(X(a), y, X(Math.min(1, e)), y, segmentRole(len, f), 3.5);
      const w = X(Math.min(1, e)) - X(a);
      // A weight only where it fits over its segment: at 11 px (compact) a monospaced digit is
      // about 6.6 px, so "1.0" needs 20 px and "1.00" 27.
      const [one, two] = lay.compact ? [24, 36] : [12, 34];
      if (p.labels && e <= 1 + 1e-9 && w >= one)
        b.text((X(a) + X(e)) / 2, y - 10, (len * f).toFixed(w >= two ? 2 : 1), lay.compact ? lay.small : 10, 'muted', {
          anchor: 'middle',
          mono: true,
        });
    }
    // Points: still ones in ink, moving (newest or sliding) ones in red, on top.
    const still: number[] = [];
    const moving: number[] = [];
    for (let i = 0; i < n; i++) {
      if (xs[i] > 1 + 1e-9) continue;
      (pat.moving[i] ? moving : still).push(X(xs[i]), y);
    }
    b.dots(still, 4.2, 'ink', 'bg', 1.5);
    b.dots(moving, 5, 'accent', 'bg', 1.5);
  });
  return top + p.modes.length * rowH;
}

function axis(b: SceneBuilder, p: LineParams, x0: number, x1: number, y: number, marksTop: number, lay: Layout): void {
  const X = (d: number) => x0 + (x1 - x0) * d;
  for (const m of p.marks) {
    b.line(X(m), marksTop, X(m), y - 6, 'faint', 1, [3, 4]);
    b.text(X(m), marksTop - 4, fmtPos(m), lay.small, 'muted', { anchor: 'middle' });
  }
  for (const v of [0, 0.25, 0.5, 0.75, 1]) {
    b.line(X(v), y - 3, X(v), y + 3, 'faint', 1);
    b.text(X(v), y + 15, fmtPos(v), lay.small, 'muted', { anchor: 'middle' });
  }
  if (p.half) b.text(x1, y + 30, halfNote(lay), lay.small, 'muted', { anchor: 'end' });
}

/** The half-edge's note, shorter on a phone (the long one is 250 px at 11 px). */
const halfNote = (lay: Layout) =>
  lay.compact ? 'position on the half-edge (½ edge = 1)' : 'position on the half-edge (½ of the edge = 1)';

// ---------------------------------------------------------------------------------------------
// Trace view
// ---------------------------------------------------------------------------------------------

export interface Trace {
  /** Sampled factors, ascending. */
  f: number[];
  /** Polylines in (display x, factor) pairs, one per point index within runs of equal counts. */
  tracks: number[][];
  /** The followed point, as (display x, factor) pairs, or null. */
  followed: number[] | null;
}

const traceCache = new Map<string, Trace>();

/** Every point's track over [lo, hi] (samples uniform in the eased factor). Cached. */
export function computeTrace(
  mode: LineMode,
  lo: number,
  hi: number,
  log: boolean,
  maxFactor: number,
  half: boolean,
  follow: number | null,
  samples = 480,
): Trace {
  const key = [mode, lo, hi, log, maxFactor, half, follow, samples].join('|');
  const hit = traceCache.get(key);
  if (hit) return hit;
  const fs: number[] = [];
  const xs: number[][] = [];
  for (let i = 0; i <= samples; i++) {
    const s = i / samples;
    const f = log ? lo * (hi / lo) ** s : lo + (hi - lo) * s;
    fs.push(f);
    xs.push(linePattern(mode, f, maxFactor).x.map((v) => v / ONE));
  }
  const limit = half ? 0.5 + 1e-9 : 1 + 1e-9;
  const tracks: number[][] = [];
  let open: number[][] = [];
  for (let i = 0; i <= samples; i++) {
    const row = xs[i];
    if (i === 0 || row.length !== xs[i - 1].length) {
      // A new run: start fresh polylines, each joined to the nearest point of the sample before.
      tracks.push(...open);
      open = row.map((x) => {
        if (i === 0) return [];
        const prev = xs[i - 1];
        let best = prev[0] ?? x;
        for (const q of prev) if (Math.abs(q - x) < Math.abs(best - x)) best = q;
        return best <= limit ? [best, fs[i - 1]] : [];
      });
    }
    row.forEach((x, k) => {
      if (x <= limit) open[k].push(x, fs[i]);
      else if (open[k].length) {
        tracks.push(open[k]);
        open[k] = [];
      }
    });
  }
  tracks.push(...open);
  const disp = (poly: number[]) => poly.map((v, j) => (j % 2 === 0 && half ? 2 * v : v));
  let followed: number[] | null = null;
  if (follow !== null) {
    // Backwards from the top of the sweep: points only merge going down, so the nearest point
    // is always the same point.
    let cur = half ? follow / 2 : follow;
    const out: number[] = [];
    for (let i = samples; i >= 0; i--) {
      let best = xs[i][0] ?? cur;
      for (const q of xs[i]) if (Math.abs(q - cur) < Math.abs(best - cur)) best = q;
      cur = best;
      out.push(cur, fs[i]);
    }
    const pairs: number[] = [];
    for (let j = out.length - 2; j >= 0; j -= 2) pairs.push(out[j], out[j + 1]);
    followed = disp(pairs);
  }
  const trace = { f: fs, tracks: tracks.filter((t) => t.length >= 4).map(disp), followed };
  if (traceCache.size > 64) traceCache.clear();
  traceCache.set(key, trace);
  return trace;
}

/** The followed point's display position at factor f (linear between samples). */
function followedAt(tr: Trace, f: number): number | null {
  const fl = tr.followed;
  if (!fl) return null;
  for (let j = 2; j < fl.length; j += 2) {
    if (fl[j + 1] >= f) {
      const f0 = fl[j - 1];
      const f1 = fl[j + 1];
      const w = f1 > f0 ? (f - f0) / (f1 - f0) : 0;
      return fl[j - 2] + (fl[j] - fl[j - 2]) * Math.min(1, Math.max(0, w));
    }
  }
  return fl[fl.length - 2];
}

function drawTrace(b: SceneBuilder, p: LineParams, f: number, lay: Layout, counts: PanelCounts[]): number {
  const lo = Math.min(...p.factor);
  const hi = Math.max(...p.factor);
  const n = p.modes.length;
  const width = lay.W;
  // Wide: the panels side by side under one factor axis. Compact: one panel per row, full width,
  // each with its own factor axis, and shorter, so that two panels fit on a phone's screen.
  const gap = 28;
  const left = lay.compact ? 46 : 56;
  const right = lay.compact ? 14 : 20;
  const pw = lay.compact ? width - left - right : (width - left - right - gap * (n - 1)) / n;
  const ph = lay.compact ? 260 : 360;
  const stride = ph + 96; // compact: the next panel's top (room for its labels and title)
  const log = p.ease === 'log';
  const span = hi > lo ? hi : lo + 1;
  const Yin = (top: number, v: number) => top + ph - ph * (log ? Math.log(v / lo) / Math.log(span / lo) : (v - lo) / (span - lo));
  // Factor ticks (a left axis, shared by the panels of a row).
  const ticks: number[] = [];
  if (log) for (let v = 1; v <= span * 1.0001; v *= 2) v >= lo - 1e-9 && ticks.push(v);
  else {
    const step = span - lo <= 16 ? (span - lo <= 8 ? 1 : 2) : 4;
    for (let v = Math.ceil(lo / step) * step; v <= span + 1e-9; v += step) ticks.push(v);
  }
  const factorAxis = (top: number) => {
    b.text(left - 10, top - 10, 'factor', lay.small, 'muted', { anchor: 'end' });
    for (const v of ticks) b.text(left - 10, Yin(top, v) + 4, String(v), lay.small, 'muted', { anchor: 'end' });
  };
  if (!lay.compact) factorAxis(112);
  let bottom = 112 + ph;
  p.modes.forEach((mode, k) => {
    const top = lay.compact ? 112 + k * stride : 112;
    bottom = top + ph;
    if (lay.compact) factorAxis(top);
    const Y = (v: number) => Yin(top, v);
    const x0 = lay.compact ? left : left + k * (pw + gap);
    const x1 = x0 + pw;
    const X = (d: number) => x0 + (x1 - x0) * d;
    for (const v of ticks) b.line(x0, Y(v), x1, Y(v), 'grid', 1);
    for (const m of p.marks) b.line(X(m), top, X(m), top + ph, 'faint', 1, [3, 4]);
    const tr = computeTrace(mode, lo, span, log, p.maxFactor, p.half, p.track);
    const toXY = (poly: number[]) => poly.map((v, j) => (j % 2 === 0 ? X(v) : Y(v)));
    b.path(tr.tracks.map(toXY), { stroke: 'muted', width: 1, opacity: 0.7 });
    if (tr.followed) b.path([toXY(tr.followed)], { stroke: 'accent', width: 2.2 });
    // Cursor and current points.
    const pat = linePattern(mode, f, p.maxFactor);
    counts.push(lineCounts(mode, pat));
    const yc = Y(Math.min(span, Math.max(lo, f)));
    b.line(x0, yc, x1, yc, 'ink', 1, [2, 3]);
    const still: number[] = [];
    const moving: number[] = [];
    pat.x.forEach((v, i) => {
      const d = toDisplay(p, v / ONE);
      if (d <= 1 + 1e-9) (pat.moving[i] ? moving : still).push(X(d), yc);
    });
    b.dots(still, 3.4, 'ink', 'bg', 1.2);
    b.dots(moving, 4.2, 'accent', 'bg', 1.2);
    const fx = followedAt(tr, Math.min(span, Math.max(lo, f)));
    if (fx !== null) {
      b.dots([X(fx), yc], 6.5, 'bg', 'accent', 2);
      // On a phone the panel is narrow: near its right end the position goes on the left.
      const flip = lay.compact && X(fx) + 50 > x1;
      b.text(X(fx) + (flip ? -10 : 10), yc - 8, fmtPos(fx), 12, 'accent', { weight: 600, mono: true, anchor: flip ? 'end' : 'start' });
    }
    b.text(x0, top - 46, LINE_MODE_LABEL[mode], 13.5, 'ink', { weight: 600 });
    b.text(x0, top - 30, countsText(counts[counts.length - 1]), 11, 'muted');
    for (const v of [0, 0.5, 1])
      b.text(X(v), top + ph + 16, fmtPos(v), lay.small, 'muted', { anchor: v === 0 ? 'start' : v === 1 ? 'end' : 'middle' });
    for (const m of p.marks)
      if (m !== 0.5 && m !== 0 && m !== 1) b.text(X(m), top + ph + 16, fmtPos(m), lay.small, 'muted', { anchor: 'middle' });
  });
  if (p.half) b.text(width - right, bottom + 34, halfNote(lay), lay.small, 'muted', { anchor: 'end' });
  return bottom + (p.half ? 44 : 28);
}

// ---------------------------------------------------------------------------------------------

/**
 * The frame at time t, laid out for `width` CSS px of available width: the wide layout (760 px,
 * scaled to fit) unless that is under 600 px, then the compact one at exactly that width.
 */
export function lineFigure(p: LineParams, t: number, title = 'Line patterns', width?: number): FigureFrame {
  const f = lineFactorAt(p, t);
  const b = new SceneBuilder();
  const counts: PanelCounts[] = [];
  const narrow = compactWidth(width);
  const wideW = p.view === 'trace' ? Math.max(LINE_WIDTH, 56 + 20 + p.modes.length * 250) : LINE_WIDTH;
  const lay: Layout = narrow === null ? { W: wideW, compact: false, small: 10.5 } : { W: narrow, compact: true, small: MIN_TEXT_PX };
  const W = lay.W;
  let H: number;
  header(b, p, f, lay);
  if (p.view === 'trace') {
    H = drawTrace(b, p, f, lay, counts) + 8;
  } else {
    const x0 = lay.compact ? 16 : 214;
    const x1 = W - (lay.compact ? 16 : 28);
    const marksTop = 62;
    const bottom = drawRows(b, p, f, p.marks.length ? 62 : 46, x0, x1, counts, lay);
    axis(b, p, x0, x1, bottom + 4, marksTop, lay);
    H = bottom + (p.half ? 44 : 30);
    if (isAnimated(p.factor)) {
      ruler(b, p, f, x0, x1, H + 10, lay);
      H += lay.compact ? 56 : 40;
    }
  }
  const desc = `factor ${fmtFactor(f)}: ${counts.map((c) => `${c.label} ${countsText(c)}`).join('; ')}`;
  return { scene: b.build(W, H, title, desc), counts, factors: [{ name: 'factor', value: f, animated: isAnimated(p.factor) }] };
}
