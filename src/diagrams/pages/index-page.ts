/** diagrams/index.html: every figure, with a thumbnail drawn from the same code as the figure. */
import './page.css';
import { FIGURES, figureUrl, type Figure } from '../figures.ts';
import { lineFigure } from '../line-figure.ts';
import { parseParams } from '../params.ts';
import { PALETTES, escapeXml, sceneToSvg } from '../scene.ts';
import { triangleFigure } from '../triangle-figure.ts';

function thumbnail(f: Figure, theme: 'light' | 'dark'): string {
  const { params } = parseParams(f.kind, `fig=${f.id}`);
  const t = params.t ?? params.start;
  const frame = params.kind === 'line' ? lineFigure(params, t, f.title) : triangleFigure(params, t, f.title);
  return sceneToSvg(frame.scene, PALETTES[theme]);
}

function card(f: Figure, theme: 'light' | 'dark'): HTMLElement {
  const el = document.createElement('article');
  el.className = 'card';
  el.dataset.fig = f.id;
  el.dataset.testid = 'figure-card';
  const url = figureUrl(f);
  el.innerHTML = `
    <a class="thumb" href="${escapeXml(url)}" aria-label="${escapeXml(f.title)}" tabindex="-1">${thumbnail(f, theme)}</a>
    <div class="body">
      <h3><a href="${escapeXml(url)}">${escapeXml(f.title)}</a></h3>
      <p>${escapeXml(f.caption)}</p>
      <div class="slide">Talk: ${escapeXml(f.slide)}</div>
      <code class="url">${escapeXml(url)}</code>
    </div>`;
  return el;
}

const dark = matchMedia('(prefers-color-scheme: dark)');
function renderAll(): void {
  const theme = dark.matches ? 'dark' : 'light';
  for (const kind of ['line', 'triangle'] as const) {
    const list = document.getElementById(`figs-${kind}`) as HTMLElement;
    list.replaceChildren(...FIGURES.filter((f) => f.kind === kind).map((f) => card(f, theme)));
  }
  document.body.dataset.ready = '1';
}
renderAll();
dark.addEventListener('change', renderAll);
