/**
 * The text of the page's legends, as HTML: the patch colours with each kind's count, the error
 * views' colour bar with its numbers and totals, and the labels over the comparison's two halves.
 * The demo decides which one shows (src/app/tessellation-demo.ts, updateLegend).
 */
import { PATCH_COLOURS } from '../gpu/render/renderer.ts';
import { HEAT_RAMP, type HeatView } from '../gpu/acc/heat.ts';
import type { DemoParams } from './params.ts';
import { degrees, percentOfDiagonal, type ErrorStats } from './stats.ts';
import { isAcc, isExact, SURFACE_NAMES } from './surfaces.ts';

function hex(c: readonly number[]): string {
  return `#${c
    .map((x) =>
      Math.round(x * 255)
        .toString(16)
        .padStart(2, '0'),
    )
    .join('')}`;
}

function swatch(k: number, name: string, count: number): string {
  return `<li><span class="swatch" style="background:${hex(PATCH_COLOURS[k].srgb)}"></span>${name} <span class="muted">${count}</span></li>`;
}

/** The instanced tessellator's patches by domain (wgsl/instanced/surface-*.wgsl patchColourIndex:
 * regular, irregular quad (ACC only), triangle). */
export function instancedPatchLegend(counts: readonly number[], acc: boolean): string {
  return `<strong>Patches (instanced)</strong><ul>${swatch(0, acc ? 'regular' : 'quad', counts[0])}${acc ? swatch(1, 'irregular quad', counts[1]) : ''}${swatch(2, 'triangle', counts[2])}</ul>`;
}

/** An ACC surface's patches (the sample's "show irregular patches"): regular, irregular quad, triangle. */
export function accPatchLegend(surface: DemoParams['surface'], kinds: ArrayLike<number>): string {
  const n = [0, 0, 0];
  for (let i = 0; i < kinds.length; i++) n[kinds[i]]++;
  return `<strong>Patches (${SURFACE_NAMES[surface]})</strong><ul>${[0, 1, 2].map((k) => swatch(k, PATCH_COLOURS[k].name, n[k])).join('')}</ul>`;
}

/** The Catmull-Clark tables' triangle kinds, each with its share of the cage's triangles. */
export function ccPatchLegend(kinds: ArrayLike<number>): string {
  const count = [0, 0, 0, 0];
  for (let i = 0; i < kinds.length; i++) count[kinds[i]]++;
  return `<strong>Patches</strong><ul>${PATCH_COLOURS.map((p) => swatch(p.kind, p.name, count[p.kind])).join('')}</ul>`;
}

/** The heat map's legend: its name, the colour bar and its numbers, and the max / RMS of `stats`. */
export function heatLegend(view: HeatView, range: number, stats: ErrorStats[]): string {
  const fmt = (x: number) => (view === 'normal' ? degrees(x) : percentOfDiagonal(x));
  const srgb = (c: readonly number[]) => `rgb(${c.map((x) => Math.round(255 * x)).join(', ')})`;
  const totals = stats
    .filter((e) => e.totals)
    .map((e) => {
      const t = e.totals!;
      const [max, rms] = view === 'normal' ? [t.maxAngle, t.rmsAngle] : [t.maxDistance, t.rmsDistance];
      return `<li>${SURFACE_NAMES[e.surface]}${e.side ? ` (${e.side})` : ''}: max ${fmt(max)} · RMS ${fmt(rms)}</li>`;
    })
    .join('');
  return (
    `<strong>${view === 'normal' ? 'Normal error' : 'Geometry error'}</strong>` +
    `<div class="heat-bar" data-testid="heat-bar" style="background: linear-gradient(to right, ${HEAT_RAMP.map(srgb).join(', ')})"></div>` +
    `<div class="heat-ticks" data-testid="heat-ticks"><span>0</span><span>${fmt(range / 2)}</span><span>≥ ${fmt(range)}</span></div>` +
    `<div class="muted">${view === 'normal' ? 'angle to the exact normal' : 'distance to the exact limit, of the diagonal'}</div>` +
    (totals ? `<ul>${totals}</ul>` : '')
  );
}

/** A comparison half's label: its surface and, for an ACC scheme, its max / RMS error in the
 * error view's unit (`view`: normal, else geometry). */
export function compareLabel(surface: string, side: 'left' | 'right', stats: ErrorStats[], view: DemoParams['errorView']): string {
  const name = SURFACE_NAMES[surface as DemoParams['surface']] ?? surface;
  const e = stats.find((x) => x.side === side);
  if (!isAcc(surface)) return isExact(surface) ? `${name} · exact` : name;
  if (!e?.totals) return `${name} · ${e?.unavailable ? 'no error view' : 'measuring…'}`;
  const t = e.totals;
  return view === 'normal'
    ? `${name} · max ${degrees(t.maxAngle)} · RMS ${degrees(t.rmsAngle)}`
    : `${name} · max ${percentOfDiagonal(t.maxDistance)} · RMS ${percentOfDiagonal(t.rmsDistance)}`;
}
