/**
 * The stats panel's text: what the cage is, what the GPU built from it, how full the output
 * buffers are, and where the GPU time goes. A pure function from numbers to HTML (escaped).
 */
import type { LoadedModel } from './models.ts';
import type { MeshCounts } from './counts.ts';

export interface StatsInput {
  model: LoadedModel | null;
  counts: MeshCounts | null;
  vertexCapacity: number;
  triangleCapacity: number;
  source: 'cage' | 'tessellator';
  mode: 'adaptive' | 'fixed';
  tessTimes: Record<string, number>;
  drawTimes: Record<string, number>;
  timestamps: boolean;
  frameMs: number;
  jsMs: number;
  rebuilds: number;
  adapter: string;
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

function ms(x: number): string {
  return x < 0.01 ? '<0.01' : x.toFixed(2);
}

function row(label: string, value: string, testid?: string): string {
  return `<dt>${label}</dt><dd${testid ? ` data-testid="${testid}"` : ''}>${value}</dd>`;
}

export function renderStats(s: StatsInput): string {
  const rows: string[] = [];
  if (s.model) {
    const nv = s.model.cage.positions.length / 3;
    const nf = s.model.cage.faceOffsets.length - 1;
    rows.push(row('cage', `<b>${esc(s.model.title)}</b> · ${int.format(nv)} verts · ${int.format(nf)} faces`, 'stats-cage'));
  }
  const c = s.counts;
  const what = s.source === 'cage' ? 'cage (flat)' : s.mode;
  rows.push(row('output', c ? `${int.format(c.vertexCount)} verts · ${int.format(c.triangleCount)} tris <span class="muted">${what}</span>` : '…', 'stats-output'));
  if (c) {
    let buffers = `verts ${percent(c.vertexCount, s.vertexCapacity)} · tris ${percent(c.triangleCount, s.triangleCapacity)}`;
    if (c.budgetScale < 1) buffers += ` · <span class="warn">over budget: factors ×${c.budgetScale.toFixed(2)}</span>`;
    rows.push(row('buffers', buffers, 'stats-buffers'));
  }
  if (s.timestamps) {
    // The build runs only when the camera, factors or model change; the draw passes every frame.
    const tess = Object.entries(s.tessTimes);
    if (tess.length) {
      const total = tess.reduce((a, [, v]) => a + v, 0);
      const detail = tess.map(([k, v]) => `${esc(k)} ${ms(v)}`).join(' · ');
      rows.push(row('build ms', `<b>${ms(total)}</b> <span class="muted">${detail}</span>`, 'stats-build'));
    }
    const draw = Object.entries(s.drawTimes).map(([k, v]) => `${esc(k)} ${ms(v)}`).join(' · ');
    rows.push(row('draw ms', draw || '…', 'stats-gpu'));
  } else {
    rows.push(row('GPU ms', '<span class="muted">no timestamp-query on this device</span>', 'stats-gpu'));
  }
  rows.push(row('frame', `${s.frameMs ? `${s.frameMs.toFixed(1)} ms` : 'idle'} · JS ${s.jsMs.toFixed(2)} ms · ${int.format(s.rebuilds)} builds`, 'stats-frame'));
  rows.push(row('adapter', `<span class="muted">${esc(s.adapter)}</span>`));
  return `<dl>${rows.join('')}</dl>`;
}
