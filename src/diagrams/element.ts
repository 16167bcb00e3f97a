/**
 * <tess-diagram>: a figure in a blog post without an iframe.
 *
 *   <script type="module" src=".../tess-diagram.js"></script>
 *   <tess-diagram fig="hable"></tess-diagram>
 *   <tess-diagram kind="triangle" mode="fractional_even,clamped" from="16" to="16" inside="16"></tess-diagram>
 *
 * Attributes are the URL parameters of the pages (case-insensitive), plus `kind` ("line" or
 * "triangle"; taken from `fig` when absent), `params` (a whole query string, under the other
 * attributes) and `base` (the URL of the diagram pages, for share links). The figure lives in a
 * shadow root, so the blog's CSS does not leak in; it animates only while on screen.
 */
import { findFigure, knownKeys, type Kind, type Message } from './params.ts';
import { DiagramPlayer } from './player.ts';

const EXTRA = ['kind', 'params', 'base'];
const ALL_KEYS = Array.from(new Set([...knownKeys('line'), ...knownKeys('triangle'), ...EXTRA]));

/** Where the pages live, seen from this module (dev server: /src/diagrams/; build: assets/). */
function defaultBase(): string {
  try {
    const rel = import.meta.env?.DEV ? '../../diagrams/' : (import.meta.env?.VITE_TESS_DIAGRAMS_BASE ?? '../diagrams/');
    return new URL(rel, import.meta.url).href;
  } catch {
    return './';
  }
}

export class TessDiagramElement extends HTMLElement {
  static observedAttributes = ALL_KEYS;
  private player: DiagramPlayer | null = null;
  private pending = false;

  get diagram(): DiagramPlayer | null {
    return this.player;
  }

  connectedCallback(): void {
    this.rebuild();
  }

  disconnectedCallback(): void {
    this.player?.destroy();
    this.player = null;
  }

  attributeChangedCallback(): void {
    if (!this.isConnected || this.pending) return;
    this.pending = true;
    queueMicrotask(() => {
      this.pending = false;
      if (this.isConnected) this.rebuild();
    });
  }

  private rebuild(): void {
    const shadow = this.shadowRoot ?? this.attachShadow({ mode: 'open' });
    this.player?.destroy();
    if (!shadow.querySelector('style[data-host]')) {
      const host = document.createElement('style');
      host.dataset.host = '';
      host.textContent = ':host { display: block; margin: 1.5em 0; } :host([hidden]) { display: none; }';
      shadow.append(host);
    }
    const input: Record<string, string> = {};
    const params = this.getAttribute('params');
    if (params) for (const [k, v] of new URLSearchParams(params)) input[k.toLowerCase()] = v;
    for (const a of Array.from(this.attributes)) {
      const k = a.name.toLowerCase();
      if (!EXTRA.includes(k) && k !== 'class' && k !== 'style' && k !== 'id' && !k.startsWith('data-') && !k.startsWith('aria-'))
        input[k] = a.value;
    }
    const kindAttr = this.getAttribute('kind');
    const fig = input.fig ? findFigure(input.fig) : null;
    const kind: Kind = kindAttr === 'triangle' || kindAttr === 'line' ? kindAttr : (fig?.kind ?? 'line');
    const mount = document.createElement('div');
    shadow.append(mount);
    const extraMessages: Message[] = [];
    if (kindAttr !== null && kindAttr !== 'line' && kindAttr !== 'triangle') {
      extraMessages.push({
        key: 'kind',
        text: `kind=${JSON.stringify(kindAttr)} should be "line" or "triangle"; drawing a ${kind} figure.`,
      });
    }
    this.player = new DiagramPlayer({
      kind,
      input,
      mount,
      styleRoot: shadow,
      pagesBase: this.getAttribute('base') ?? defaultBase(),
      headingLevel: 3,
      extraMessages,
    });
    this.player.onReplace = (p) => (this.player = p);
  }
}

export function defineTessDiagram(name = 'tess-diagram'): void {
  if (typeof customElements !== 'undefined' && !customElements.get(name)) customElements.define(name, TessDiagramElement);
}

defineTessDiagram();
