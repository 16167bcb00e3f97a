/**
 * The stats panel's text: what the cage is, what the GPU built from it, how full the output
 * buffers are, and where the GPU time goes. A pure function from numbers to HTML (escaped).
 */
import type { LoadedModel } from './models.ts';
import { formatIssue } from '../mesh/errors.ts';
import type { MeshCounts } from './counts.ts';
import type { GpuMemoryCounts } from '../gpu/device/tracked-device.ts';
import type { InstancedCounts } from './instanced-view.ts';
import type { HeatTotals } from '../gpu/acc/heat.ts';
import { isExact, SURFACE_NAMES } from './surfaces.ts';

/** One ACC surface's error against the exact Catmull-Clark limit over its output vertices (the
 * GPU error pass: src/gpu/acc/heat.ts), or why there is none. */
export interface ErrorStats {
  /** The surface measured ('bezier-acc', …) and where it is drawn (the comparison's halves). */
  surface: SurfaceStats['shown'];
  side?: 'left' | 'right';
  /** Null while the first pass is read back. */
  totals: HeatTotals | null;
  /** Why it cannot be measured (no exact reference for this cage). */
  unavailable?: string | null;
}

/** The surface drawn, and what the Catmull-Clark tables are (or why there are none). */
export interface SurfaceStats {
  /** What is drawn now. */
  shown: 'catmull-clark' | 'phong' | 'cage' | 'bezier-acc' | 'gregory-acc' | 'pm-acc';
  /** The surface asked for (what `fallback` says is unavailable). */
  asked?: 'catmull-clark' | 'phong' | 'cage' | 'bezier-acc' | 'gregory-acc' | 'pm-acc';
  /** Catmull-Clark was asked for but the build refused the model: the reason. */
  fallback?: string | null;
  /** The tables are being built (the previous picture stays meanwhile). */
  building?: boolean;
  /** Triangles per patch kind (regular, irregular quad, triangle region, crease). */
  kinds?: [number, number, number, number];
  /** Wall-clock ms of the CPU preparation (topology only). */
  tablesMs?: number;
  /** Why the surface tessellates another cage than the model's (an ACC scheme refines a cage with
   * n-gons once: src/subdiv/acc.ts accCage), or null. */
  note?: string | null;
}

/** The other factor mode's output, counted by an occasional extra build. */
export interface OtherModeCounts {
  mode: 'adaptive' | 'fixed';
  /** Its setting: "factor 8" or "LOD 1". */
  setting: string;
  counts: MeshCounts;
}

export interface StatsInput {
  model: LoadedModel | null;
  counts: MeshCounts | null;
  surface?: SurfaceStats;
  other?: OtherModeCounts | null;
  vertexCapacity: number;
  triangleCapacity: number;
  source: 'cage' | 'tessellator';
  mode: 'adaptive' | 'fixed';
  tessTimes: Record<string, number>;
  /** The tessellation times are an older build's: the drawn one is still on the GPU or being read. */
  tessTimesStale?: boolean;
  /** The counts are an older build's, likewise ("building…" beside them). */
  countsStale?: boolean;
  drawTimes: Record<string, number>;
  timestamps: boolean;
  /** The device has timestamp queries but their readback never settled: timing stopped. */
  timingStalled?: boolean;
  frameMs: number;
  jsMs: number;
  rebuilds: number;
  adapter: string;
  /** The page's live GPU buffers and textures (src/gpu/device/tracked-device.ts). */
  memory?: GpuMemoryCounts;
  /** The ACC error views' max / RMS (the main surface, and the comparison's right half). */
  errors?: ErrorStats[];
  /** The comparison view's right half (`compare=`), and why it is not drawn if refused. */
  compare?: { surface: SurfaceStats['shown']; refused?: string | null } | null;
  /** What the device's limits clamped (output buffers, budget), said once per device. */
  clamps?: string[];
  /** The instanced tessellator draws (`tessellator=instanced`): its draws' counts (null until
   * read back) and its setting ("static level 8", "dynamic LOD 1"). */
  instanced?: {
    counts: InstancedCounts | null;
    setting: string;
    split?: boolean;
    /** Its surface (Phong, Catmull-Clark or an ACC scheme), the one asked for, and why not that
     * one, if refused. */
    surface?: string;
    asked?: string;
    fallback?: string | null;
  } | null;
}

const int = new Intl.NumberFormat('en-US');

function esc(s: string): string {
  return s.replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);
}

function percent(n: number, of: number): string {
  if (!of) return '–';
  const p = (100 * n) / of;
  return p < 0.1 && n > 0 ? '<0.1%' : `${p.toFixed(p < 10 ? 1 : 0)}%`;
}

function mib(bytes: number): string {
  return `${(bytes / 2 ** 20).toFixed(bytes < 10 * 2 ** 20 ? 2 : 1)} MiB`;
}

/** A ratio with two significant digits (0.0085×, 0.42×, 3.1×, 12×). */
export function ratio(x: number): string {
  return `${x >= 10 ? Math.round(x) : x.toPrecision(2)}×`;
}

function ms(x: number): string {
  return x < 0.01 ? '<0.01' : x.toFixed(2);
}

/** Timing stages of the Catmull-Clark patch build; every other stage is tessellation. */
const SUBDIVISION_STAGES = new Set(['subdivision']);

/** The rows the compact view shows (the rest show when the panel is expanded); a row that warns
 * shows either way (see `warns`). */
const COMPACT_ROWS = new Set(['surface', 'output', 'output (left)', 'output (right)', 'tessellation ms', 'frame', 'compare', 'limits']);

function row(label: string, value: string, testid?: string): string {
  const compact = COMPACT_ROWS.has(label) || label.startsWith('error') || value.includes('class="warn"');
  const cls = compact ? '' : ' class="more"';
  return `<dt${cls}>${label}</dt><dd${cls}${testid ? ` data-testid="${testid}"` : ''}>${value}</dd>`;
}

/** The button that expands the compact view to every row, and back (the page toggles the panel's
 * `expanded` class: src/app/tessellation-demo.ts). */
const TOGGLE =
  '<button type="button" class="stats-toggle" data-testid="stats-toggle"><span class="when-compact">all ▸</span><span class="when-expanded">fewer ▴</span></button>';

/** A fraction of the diagonal as a percentage with 3 significant digits (0 stays 0). */
export function percentOfDiagonal(x: number): string {
  return x === 0 ? '0%' : `${x * 100 < 0.001 ? (x * 100).toExponential(2) : (x * 100).toPrecision(3)}%`;
}

/** Degrees with 3 significant digits. */
export function degrees(x: number): string {
  return x === 0 ? '0°' : `${x < 0.001 ? x.toExponential(2) : x.toPrecision(3)}°`;
}

function errorText(e: ErrorStats): string {
  const name = `<b>${SURFACE_NAMES[e.surface]}</b>`;
  if (e.unavailable) return `${name} <span class="warn">no error view: ${esc(e.unavailable)}</span>`;
  const t = e.totals;
  if (!t) return `${name} <span class="muted">measuring…</span>`;
  return (
    `${name} geometry max <span data-testid="err-max-geometry">${percentOfDiagonal(t.maxDistance)}</span> · RMS ${percentOfDiagonal(t.rmsDistance)}` +
    ` <span class="muted">of the diagonal</span>` +
    ` · normal max <span data-testid="err-max-normal">${degrees(t.maxAngle)}</span> · RMS ${degrees(t.rmsAngle)}` +
    ` <span class="muted">· ${int.format(t.vertices)} verts</span>`
  );
}

export function renderStats(s: StatsInput): string {
  const rows: string[] = [];
  if (s.model) {
    const nv = s.model.cage.positions.length / 3;
    const nf = s.model.cage.faceOffsets.length - 1;
    // What the loader changed or ignored (non-manifold vertices and edges split apart, unused
    // vertices, …): the first said here, all of them on hover.
    const w = s.model.warnings;
    const said = w.length
      ? ` <span class="warn" title="${esc(w.map(formatIssue).join('\n'))}">· ${w.length === 1 ? '' : `${int.format(w.length)} notes, the first: `}${esc(formatIssue(w[0]))}</span>`
      : '';
    rows.push(row('cage', `<b>${esc(s.model.title)}</b> · ${int.format(nv)} verts · ${int.format(nf)} faces${said}`, 'stats-cage'));
  }
  if (s.surface) {
    const sf = s.surface;
    let text = `<b>${SURFACE_NAMES[sf.shown]}</b>`;
    if (sf.building) text += ' <span class="muted">preparing subdivision data…</span>';
    if (sf.fallback) text += ` <span class="warn">${SURFACE_NAMES[sf.asked ?? 'catmull-clark']} unavailable: ${esc(sf.fallback)}</span>`;
    else if (sf.note) text += ` <span class="muted">· ${esc(sf.note)}</span>`;
    if (isExact(sf.shown) && sf.kinds) {
      const [reg, irr, tri, crease] = sf.kinds;
      text += ` <span class="muted detail">· tris: ${int.format(reg)} regular, ${int.format(irr)} irregular, ${int.format(tri)} triangle, ${int.format(crease)} crease`;
      if (sf.tablesMs !== undefined) text += ` · prepared in ${sf.tablesMs < 10 ? sf.tablesMs.toFixed(1) : Math.round(sf.tablesMs)} ms`;
      text += '</span>';
    }
    // The instanced tessellator's surface by its name (any the compute one has but the flat cage).
    const named = (k: string | undefined) => esc(k && k in SURFACE_NAMES ? SURFACE_NAMES[k as keyof typeof SURFACE_NAMES] : (k ?? 'Phong'));
    const instName = named(s.instanced?.surface ?? 'phong');
    const refused = s.instanced?.fallback
      ? ` <span class="warn">${named(s.instanced.asked)} unavailable: ${esc(s.instanced.fallback)}</span>`
      : '';
    if (s.instanced?.split && sf.shown !== 'cage') text += ` <span class="muted">· instanced (right): ${instName}</span>${refused}`;
    else if (s.instanced && sf.shown !== 'cage') text = `<b>${instName}</b> <span class="muted">instanced tessellator</span>${refused}`;
    rows.push(row('surface', text, 'stats-surface'));
  }
  if (s.compare) {
    const cmp = s.compare;
    rows.push(
      row(
        'compare',
        `${s.surface ? SURFACE_NAMES[s.surface.shown] : '?'} (left) | <b>${SURFACE_NAMES[cmp.surface]}</b> (right)${cmp.refused ? ` <span class="warn">unavailable: ${esc(cmp.refused)}</span>` : ''}`,
        'stats-compare',
      ),
    );
  }
  for (const e of s.errors ?? [])
    rows.push(row(e.side ? `error (${e.side})` : 'error', errorText(e), e.side === 'right' ? 'stats-error-right' : 'stats-error'));
  const inst = s.instanced;
  const split = inst?.split ?? false;
  // The instanced tessellator stores no mesh: its counts are its draws', per pass. The split
  // view shows both: compute's stored mesh (left) and the instanced draws (right).
  const c = inst && !split ? null : s.counts;
  if (split)
    rows.push(
      row(
        'output (left)',
        c ? `${int.format(c.vertexCount)} verts · ${int.format(c.triangleCount)} tris <span class="muted">compute, ${s.mode}</span>` : '…',
        'stats-output-compute',
      ),
    );
  const what = s.source === 'cage' ? 'cage (flat)' : s.mode;
  const size = (m: MeshCounts) => `${int.format(m.vertexCount)} verts · ${int.format(m.triangleCount)} tris`;
  if (inst) {
    const ic = inst.counts;
    rows.push(
      row(
        split ? 'output (right)' : 'output',
        ic
          ? `${int.format(ic.vertices)} verts evaluated · ${int.format(ic.triangles)} tris <span class="muted">per pass · instanced, ${esc(inst.setting)}</span>`
          : '…',
        'stats-output',
      ),
    );
    if (ic)
      rows.push(
        row(
          'buckets',
          `${int.format(ic.patches)} patches <span class="muted">${ic.levels.map(([l, n]) => `L${l}: ${int.format(n)}`).join(' · ')}</span>`,
          'stats-buckets',
        ),
      );
  } else {
    const building = s.countsStale ? ' <span class="muted" data-testid="stats-building">· building…</span>' : '';
    rows.push(row('output', c ? `${size(c)} <span class="muted detail">${what}</span>${building}` : '…', 'stats-output'));
  }
  if (split && s.timestamps) {
    // Both tessellators' draw passes, from their timing slots (src/gpu/render/renderer.ts DrawOptions.region).
    const t = s.drawTimes;
    const pair = (sh?: number, lit?: number) => (sh === undefined || lit === undefined ? '…' : `shadow ${ms(sh)} · lit ${ms(lit)}`);
    rows.push(row('draw ms (left)', `${pair(t.shadow, t.lit)} <span class="muted">stored mesh</span>`, 'stats-gpu-compute'));
    rows.push(row('draw ms (right)', `${pair(t['shadow 2'], t['lit 2'])} <span class="muted">evaluates</span>`, 'stats-gpu'));
  }
  // The other factor mode, for the talk's fixed-vs-adaptive comparison: counted by one extra
  // build (then the drawn one again) when its settings, the model or the surface change.
  const o = s.source === 'cage' || inst ? null : s.other;
  if (o && o.mode !== s.mode) {
    let text = `${size(o.counts)} <span class="muted">${o.mode}, ${esc(o.setting)}`;
    if (c && c.triangleCount > 0) text += ` · ${ratio(o.counts.triangleCount / c.triangleCount)} the drawn tris`;
    text += '</span>';
    if (o.counts.budgetScale < 1) text += ` <span class="warn">over budget</span>`;
    rows.push(row(`vs ${o.mode}`, text, 'stats-other'));
  }
  if (c) {
    let buffers = `verts ${percent(c.vertexCount, s.vertexCapacity)} · tris ${percent(c.triangleCount, s.triangleCapacity)}`;
    if (c.budgetScale < 1) buffers += ` · <span class="warn">over budget: factors ×${c.budgetScale.toFixed(2)}</span>`;
    rows.push(row('buffers', buffers, 'stats-buffers'));
  }
  if (s.timestamps) {
    // The build runs only when the camera, factors or model change; the draw passes every frame.
    // Subdivision (the Catmull-Clark patch build) and tessellation are shown apart.
    const all = s.instanced && !s.instanced.split ? [] : Object.entries(s.tessTimes);
    const subdiv = all.filter(([k]) => SUBDIVISION_STAGES.has(k));
    const tess = all.filter(([k]) => !SUBDIVISION_STAGES.has(k));
    if (all.length && isExact(s.surface?.shown)) {
      const total = subdiv.reduce((a, [, v]) => a + v, 0);
      rows.push(row('subdivision ms', subdiv.length ? `<b>${ms(total)}</b> <span class="muted">patch build</span>` : '–', 'stats-subdiv'));
    }
    if (tess.length) {
      const total = tess.reduce((a, [, v]) => a + v, 0);
      const detail = tess.map(([k, v]) => `${esc(k)} ${ms(v)}`).join(' · ');
      const stale = s.tessTimesStale
        ? ' <span class="muted" data-testid="stats-build-stale">(the previous build; timing the new one…)</span>'
        : '';
      rows.push(row('tessellation ms', `<b>${ms(total)}</b> <span class="muted detail">${detail}</span>${stale}`, 'stats-build'));
    }
    let draw = Object.entries(s.drawTimes)
      .map(([k, v]) => `${esc(k)} ${ms(v)}`)
      .join(' · ');
    // Nothing drawn now: the figures are the frame on screen's, said so.
    if (draw && !s.frameMs) draw += ' <span class="muted">last frame</span>';
    const none = s.timingStalled ? '<span class="muted">timestamps did not come back: timing stopped</span>' : '…';
    if (!split) rows.push(row(inst ? 'draw ms (evaluates)' : 'draw ms', draw || none, 'stats-gpu'));
  } else {
    rows.push(row('GPU ms', '<span class="muted">no timestamp-query on this device</span>', 'stats-gpu'));
  }
  rows.push(
    row(
      'frame',
      `${s.frameMs ? `${s.frameMs.toFixed(1)} ms` : 'idle'} · JS ${s.jsMs.toFixed(2)} ms · ${int.format(s.rebuilds)} builds`,
      'stats-frame',
    ),
  );
  if (s.memory) {
    const m = s.memory;
    rows.push(
      row(
        'GPU memory',
        `<b>${mib(m.bytes)}</b> <span class="muted">${int.format(m.buffers)} buffers ${mib(m.bufferBytes)} · ${int.format(m.textures)} textures ${mib(m.textureBytes)}</span>`,
        'stats-memory',
      ),
    );
  }
  if (s.clamps?.length) rows.push(row('limits', s.clamps.map((c) => `<span class="warn">${esc(c)}</span>`).join('<br>'), 'stats-limits'));
  rows.push(row('adapter', `<span class="muted">${esc(s.adapter)}</span>`));
  return `<dl>${rows.join('')}</dl>${TOGGLE}`;
}
