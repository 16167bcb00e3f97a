/**
 * The interactive figure: caption, canvas and controls around a pure figure function. Shared by
 * the pages (line.html, triangle.html) and the <tess-diagram> custom element. Plain DOM.
 *
 * Time: `?t=` freezes the figure (paused at t); otherwise it starts at `start`, playing unless
 * `autoplay=0` or the reader prefers reduced motion. It only animates while on screen.
 * Keyboard (figure focused): Space or K play/pause, ← → step 0.1 s (Shift: 1 s), Home/End.
 */
import { LINE_MODES, TRI_MODES } from '../pattern/types.ts';
import { download, exportGif, exportPng, exportSvg, exportWebm } from './export.ts';
import { LINE_MODE_LABEL, TRI_MODE_LABEL, fmtFactor, plural } from './labels.ts';
import { lineFigure } from './line-figure.ts';
import type { FigureFrame } from './model.ts';
import { parseParams, toQuery, type Kind, type Message, type Params } from './params.ts';
import { PALETTES, drawScene, type Palette } from './scene.ts';
import { isAnimated, period } from './timeline.ts';
import { triangleFigure } from './triangle-figure.ts';
import { h, ICON_PAUSE, ICON_PLAY, injectStyle } from './dom.ts';
import { appendViewOptions } from './view-options.ts';
import { addFactorSliders, type SliderEls, toPos } from './sliders.ts';

export interface PlayerOptions {
  kind: Kind;
  input: string | URLSearchParams | Record<string, string | null | undefined>;
  /** Element the figure is appended to. */
  mount: HTMLElement;
  /** Where the stylesheet goes (the document or a shadow root). */
  styleRoot: Document | ShadowRoot;
  /** URL of the folder holding line.html and triangle.html (share links, embed code). */
  pagesBase: string;
  /** Called with the figure's query string whenever the reader changes a parameter. */
  onParamsChange?: (query: string) => void;
  /** Heading level of the title (2 on the pages, 3 inside an article). */
  headingLevel?: number;
  /** Problems found outside the parameters (shown with theirs). */
  extraMessages?: Message[];
}

const GENERIC_CAPTION: Record<Kind, [string, string]> = {
  line: ['Line patterns', 'Points of each line pattern at the same tessellation factor. Red points are sliding or new.'],
  triangle: ['Triangle patterns', 'Triangle patterns at the same edge factors. Red vertices are the ones moving at this moment.'],
};

export function prefersReducedMotion(): boolean {
  return typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
}

export class DiagramPlayer {
  readonly root: HTMLElement;
  params: Params;
  readonly messages: Message[];
  private readonly initialQuery: string;
  private readonly title: string;
  private time: number;
  private playing: boolean;
  private visible = true;
  private raf = 0;
  private last = 0;
  private frame: FigureFrame | null = null;
  private scale = 1;
  private busy = false;
  private readonly canvas: HTMLCanvasElement;
  private readonly stage: HTMLElement;
  private readonly els: {
    play?: HTMLButtonElement;
    mini?: HTMLButtonElement;
    scrub?: HTMLInputElement;
    time?: HTMLElement;
    counts: HTMLElement;
    sliders: SliderEls;
    status?: HTMLElement;
    embed?: HTMLTextAreaElement;
    theme?: HTMLButtonElement;
    controls?: HTMLElement;
  };
  private readonly cleanup: (() => void)[] = [];
  private readonly darkQuery: MediaQueryList | null;

  constructor(private readonly opts: PlayerOptions) {
    injectStyle(opts.styleRoot);
    const parsed = parseParams(opts.kind, opts.input);
    this.params = parsed.params;
    this.messages = [...(opts.extraMessages ?? []), ...parsed.messages];
    this.initialQuery = toQuery(this.params);
    const [gTitle, gCaption] = GENERIC_CAPTION[opts.kind];
    this.title = parsed.figure?.title ?? gTitle;
    const caption = parsed.figure?.caption ?? gCaption;
    const p = this.params;
    this.time = p.t ?? p.start;
    this.playing = p.t === null && p.autoplay && !prefersReducedMotion();
    this.darkQuery = typeof matchMedia === 'function' ? matchMedia('(prefers-color-scheme: dark)') : null;

    this.canvas = h('canvas', { class: 'td-canvas', 'data-testid': 'diagram-canvas', role: 'img' });
    this.els = { counts: h('output', { class: 'td-counts', 'data-testid': 'counts', 'aria-live': 'off' }), sliders: new Map() };
    const level = Math.min(6, Math.max(1, opts.headingLevel ?? 2));
    const head = p.caption
      ? h(
          'header',
          { class: 'td-head' },
          h(`h${level}` as 'h2', { class: 'td-title', text: this.title }),
          h('p', { class: 'td-caption', 'data-testid': 'caption', text: caption }),
        )
      : null;
    const msgs = h('div', { class: 'td-msgs', role: 'alert', 'data-testid': 'messages', hidden: this.messages.length === 0 });
    if (this.messages.length) {
      msgs.append(
        h('strong', { text: 'Some parameters were not understood: ' }),
        h('ul', {}, ...this.messages.map((m) => h('li', { text: m.text }))),
      );
    }
    const stage = h('div', { class: 'td-stage' }, this.canvas);
    this.stage = stage;
    this.root = h(
      'figure',
      {
        class: 'td',
        tabindex: 0,
        'data-kind': opts.kind,
        'data-testid': 'diagram',
        'aria-label': this.title,
        'aria-keyshortcuts': 'Space K ArrowLeft ArrowRight Home End',
      },
      head,
      msgs,
      stage,
    );
    if (p.chrome) {
      this.root.append(this.buildControls());
    } else {
      // Without controls there is still a visible pause button (WCAG 2.2.2).
      this.els.mini = h('button', { class: 'td-mini', type: 'button', 'data-testid': 'play' });
      this.els.mini.addEventListener('click', () => this.setPlaying(!this.playing));
      this.root.append(h('div', { class: 'td-minibar' }, this.els.mini));
    }
    opts.mount.append(this.root);
    this.canvas.addEventListener('click', () => this.setPlaying(!this.playing));
    this.root.addEventListener('keydown', (e) => this.onKey(e));

    // The figure's own width, not the window's, picks its layout (an embed in a narrow blog
    // column is a phone too): redraw whenever the stage changes size.
    if (typeof ResizeObserver === 'function') {
      const ro = new ResizeObserver(() => this.render());
      ro.observe(stage);
      this.cleanup.push(() => ro.disconnect());
    }
    if (typeof IntersectionObserver === 'function') {
      const io = new IntersectionObserver((entries) => {
        this.visible = entries.some((e) => e.isIntersecting);
        this.schedule();
      });
      io.observe(this.root);
      this.cleanup.push(() => io.disconnect());
    }
    const onTheme = () => this.render();
    this.darkQuery?.addEventListener('change', onTheme);
    this.cleanup.push(() => this.darkQuery?.removeEventListener('change', onTheme));
    // A new pixel ratio (another screen, zoom) needs a sharper or smaller backing store.
    const watchDpr = () => {
      if (typeof matchMedia !== 'function') return;
      const mq = matchMedia(`(resolution: ${devicePixelRatio}dppx)`);
      const onDpr = () => {
        this.render();
        watchDpr();
      };
      mq.addEventListener('change', onDpr, { once: true });
      this.cleanup.push(() => mq.removeEventListener('change', onDpr));
    };
    watchDpr();
    const onVis = () => this.schedule();
    document.addEventListener('visibilitychange', onVis);
    this.cleanup.push(() => document.removeEventListener('visibilitychange', onVis));
    this.syncPlayButtons();
    this.render();
    this.schedule();
  }

  destroy(): void {
    cancelAnimationFrame(this.raf);
    this.raf = 0;
    for (const f of this.cleanup) f();
    this.root.remove();
  }

  get isPlaying(): boolean {
    return this.playing;
  }

  get currentTime(): number {
    return this.time;
  }

  // -------------------------------------------------------------------------------- rendering

  private palette(): Palette {
    return PALETTES[this.resolvedTheme()];
  }

  resolvedTheme(): 'light' | 'dark' {
    if (this.params.theme !== 'auto') return this.params.theme;
    return this.darkQuery?.matches ? 'dark' : 'light';
  }

  /** The frame at time t, laid out for `width` CSS px (the wide layout if not given: exports). */
  frameAt(t: number, width?: number): FigureFrame {
    const p = this.params;
    return p.kind === 'line' ? lineFigure(p, t, this.title, width) : triangleFigure(p, t, this.title, width);
  }

  /** The width the canvas can take: the stage's content box, in CSS px (0 before layout).
   * Fractional (clientWidth rounds, and a layout 1 px wider than its space draws 1/300 smaller). */
  private availableWidth(): number {
    const st = getComputedStyle(this.stage);
    return this.stage.getBoundingClientRect().width - (parseFloat(st.paddingLeft) || 0) - (parseFloat(st.paddingRight) || 0);
  }

  render(): void {
    const fr = this.frameAt(this.time, this.availableWidth() || undefined);
    this.frame = fr;
    const { scene } = fr;
    const theme = this.resolvedTheme();
    this.root.dataset.theme = theme;
    // Size: the canvas fills the stage's width, pixels at the device's ratio. (A compact scene is
    // as wide as the stage already, so it draws at one scene unit per CSS px.)
    const c = this.canvas;
    c.style.aspectRatio = `${scene.width} / ${scene.height}`;
    c.style.maxWidth = `${Math.round(scene.width * 1.3)}px`;
    const cssW = c.clientWidth || scene.width;
    const dpr = typeof devicePixelRatio === 'number' && devicePixelRatio > 0 ? devicePixelRatio : 1;
    const pw = Math.max(1, Math.round(cssW * dpr));
    const ph = Math.max(1, Math.round((pw * scene.height) / scene.width));
    if (c.width !== pw || c.height !== ph) {
      c.width = pw;
      c.height = ph;
    }
    this.scale = pw / scene.width;
    const ctx = c.getContext('2d');
    if (ctx) drawScene(ctx, scene, PALETTES[theme], this.scale);
    c.setAttribute('aria-label', `${scene.title}. ${scene.desc}`);
    c.dataset.time = this.time.toFixed(3);
    this.updateReadouts(fr);
  }

  private updateReadouts(fr: FigureFrame): void {
    const counts = this.els.counts;
    counts.replaceChildren(
      ...fr.counts.map((k) => {
        const what = this.params.kind === 'line' ? ['point', 'segment', 'zero-length'] : ['vertex', 'triangle', 'degenerate'];
        const span = h(
          'span',
          {
            class: 'td-count',
            'data-mode': k.mode,
            'data-vertices': k.vertices,
            'data-triangles': k.triangles,
            'data-degenerate': k.degenerate,
          },
          h('b', { text: `${k.label}:` }),
          ` ${plural(k.vertices, what[0], what[0] === 'vertex' ? 'vertices' : `${what[0]}s`)}, ${plural(k.triangles, what[1])}, ${k.degenerate} ${what[2]}`,
        );
        return span;
      }),
    );
    const per = period(this.params.timing);
    if (this.els.scrub && document.activeElement !== this.els.scrub) {
      this.els.scrub.max = String(per);
      this.els.scrub.value = String(((this.time % per) + per) % per);
    }
    if (this.els.time) {
      const f = fr.factors.map((v) => `${v.name === 'factor' ? 'f' : v.name} ${fmtFactor(v.value)}`).join(' · ');
      this.els.time.textContent = `${this.time.toFixed(2)} s · ${f}`;
    }
    for (const v of fr.factors) {
      const s = this.els.sliders.get(v.name);
      if (!s) continue;
      s.out.value = fmtFactor(v.value);
      s.wrap.classList.toggle('td-animated', v.animated);
      if (document.activeElement !== s.input) s.input.value = String(toPos(v.value, Number(s.input.dataset.max)));
      s.input.setAttribute('aria-valuetext', fmtFactor(v.value));
    }
  }

  // -------------------------------------------------------------------------------- time

  setPlaying(on: boolean): void {
    this.playing = on;
    this.syncPlayButtons();
    this.schedule();
  }

  setTime(t: number): void {
    this.time = Math.max(0, t);
    this.render();
  }

  private syncPlayButtons(): void {
    const still = !this.animated;
    for (const b of [this.els.play, this.els.mini]) {
      if (!b) continue;
      // A figure whose factors never change has nothing to play (a sweep makes it move again).
      b.disabled = still;
      b.title = still ? 'Every factor is fixed in this figure: set a sweep to animate it' : '';
      b.innerHTML =
        (this.playing ? ICON_PAUSE : ICON_PLAY) + (b === this.els.play ? `<span>${this.playing ? 'Pause' : 'Play'}</span>` : '');
      b.setAttribute('aria-label', this.playing ? 'Pause animation' : 'Play animation');
      b.dataset.state = this.playing ? 'playing' : 'paused';
    }
    this.root.dataset.state = this.playing ? 'playing' : 'paused';
  }

  /** Whether any factor changes with time (a static figure needs no frames). */
  get animated(): boolean {
    const p = this.params;
    return p.kind === 'line' ? isAnimated(p.factor) : p.factors.some(isAnimated) || (p.inside !== null && isAnimated(p.inside));
  }

  private schedule(): void {
    const run = this.playing && this.visible && !document.hidden && this.animated;
    if (run && !this.raf) {
      this.last = performance.now();
      this.raf = requestAnimationFrame((now) => this.tick(now));
    } else if (!run && this.raf) {
      cancelAnimationFrame(this.raf);
      this.raf = 0;
    }
  }

  private tick(now: number): void {
    this.raf = 0;
    const dt = Math.min(0.1, Math.max(0, (now - this.last) / 1000));
    this.last = now;
    this.time += dt * this.params.speed;
    const p = this.params;
    if (p.timing.loop === 'once' && this.time >= p.timing.duration) {
      this.time = p.timing.duration;
      this.playing = false;
      this.syncPlayButtons();
    }
    this.render();
    this.schedule();
  }

  private onKey(e: KeyboardEvent): void {
    const target = e.composedPath()[0] as HTMLElement | undefined;
    const tag = target?.tagName;
    if (tag === 'INPUT' || tag === 'SELECT' || tag === 'TEXTAREA' || tag === 'BUTTON' || tag === 'SUMMARY') return;
    const step = e.shiftKey ? 1 : 0.1;
    if (e.key === ' ' || e.key === 'k' || e.key === 'K') this.setPlaying(!this.playing);
    else if (e.key === 'ArrowRight') this.step(step);
    else if (e.key === 'ArrowLeft') this.step(-step);
    else if (e.key === 'Home') this.step(-this.time);
    else if (e.key === 'End') this.step(period(this.params.timing) / 2 - this.time);
    else return;
    e.preventDefault();
  }

  private step(dt: number): void {
    this.setPlaying(false);
    this.setTime(this.time + dt);
  }

  // -------------------------------------------------------------------------------- params

  private changed(): void {
    this.render();
    this.syncPlayButtons();
    this.schedule();
    const q = toQuery(this.params);
    this.opts.onParamsChange?.(q);
    if (this.els.embed) this.els.embed.value = this.embedCode(q);
  }

  shareUrl(q = toQuery(this.params)): string {
    return `${this.opts.pagesBase}${this.params.kind}.html${q ? `?${q}` : ''}`;
  }

  private embedCode(q: string): string {
    const url = this.shareUrl(q);
    const sep = url.includes('?') ? '&' : '?';
    const attrs = [`kind="${this.params.kind}"`];
    for (const [k, v] of new URLSearchParams(q)) attrs.push(`${k.toLowerCase()}="${v}"`);
    return [
      url,
      '',
      `<iframe src="${url}${sep}embed=1" title="${this.title}" style="width:100%;border:0" loading="lazy"></iframe>`,
      '',
      `<tess-diagram ${attrs.join(' ')}></tess-diagram>`,
    ].join('\n');
  }

  private buildControls(): HTMLElement {
    const p = this.params;
    const els = this.els;
    // Row 1: transport.
    els.play = h('button', { class: 'td-play', type: 'button', 'data-testid': 'play', 'aria-keyshortcuts': 'Space' });
    els.play.addEventListener('click', () => this.setPlaying(!this.playing));
    els.scrub = h('input', {
      class: 'td-scrub',
      type: 'range',
      min: 0,
      max: period(p.timing),
      step: 0.01,
      value: 0,
      'aria-label': 'Time',
      'data-testid': 'scrub',
    });
    els.scrub.addEventListener('input', () => {
      this.setPlaying(false);
      this.setTime(Number(els.scrub!.value));
    });
    els.time = h('span', { class: 'td-time', 'data-testid': 'time' });
    const speed = h('select', { 'aria-label': 'Speed', 'data-testid': 'speed' });
    for (const s of [0.25, 0.5, 1, 2, 4]) speed.append(h('option', { value: s, text: `${s}×`, selected: s === p.speed }));
    if (![0.25, 0.5, 1, 2, 4].includes(p.speed)) speed.prepend(h('option', { value: p.speed, text: `${p.speed}×`, selected: true }));
    speed.addEventListener('change', () => {
      p.speed = Number(speed.value);
      this.changed();
    });
    const transport = h(
      'div',
      { class: 'td-row' },
      els.play,
      els.scrub,
      els.time,
      h('label', {}, h('span', { class: 'td-sr', text: 'Speed' }), speed),
    );

    // Row 2: modes.
    const all = p.kind === 'line' ? LINE_MODES : TRI_MODES;
    const labels: Record<string, string> = p.kind === 'line' ? LINE_MODE_LABEL : TRI_MODE_LABEL;
    const chips = h('fieldset', { class: 'td-chips', 'data-testid': 'modes' }, h('legend', { text: 'Modes' }));
    for (const m of all) {
      const box = h('input', { type: 'checkbox', value: m, checked: (p.modes as string[]).includes(m) });
      box.addEventListener('change', () => {
        const cur = p.modes as string[];
        const next = box.checked ? [...cur, m] : cur.filter((x) => x !== m);
        if (!next.length) {
          box.checked = true;
          return;
        }
        (p as { modes: string[] }).modes = next;
        this.rebuildSliders();
        this.changed();
      });
      chips.append(h('label', { class: 'td-chip' }, box, h('span', { text: labels[m] })));
    }

    // Row 3: factors.
    const sliders = h('div', { class: 'td-sliders', 'data-testid': 'sliders' });
    this.sliderBox = sliders;
    this.rebuildSliders();

    // Row 4: view options, theme, export, share.
    const opts = h('div', { class: 'td-row' });
    appendViewOptions(opts, p, () => this.changed());
    els.theme = h('button', { type: 'button', 'data-testid': 'theme' });
    const themeLabel = () => (els.theme!.textContent = `Theme: ${p.theme}`);
    themeLabel();
    els.theme.addEventListener('click', () => {
      p.theme = p.theme === 'auto' ? (this.resolvedTheme() === 'dark' ? 'light' : 'dark') : p.theme === 'light' ? 'dark' : 'auto';
      themeLabel();
      this.changed();
    });
    opts.append(els.theme);

    const exp = h('div', { class: 'td-row', role: 'group', 'aria-label': 'Export' }, h('span', { class: 'td-label', text: 'Export' }));
    const exportButton = (label: string, run: () => Promise<void>) => {
      const b = h('button', { type: 'button', text: label, 'data-testid': `export-${label.toLowerCase()}` });
      b.addEventListener('click', async () => {
        if (this.busy) return;
        this.busy = true;
        exp.querySelectorAll('button').forEach((x) => (x.disabled = true));
        try {
          await run();
        } catch (err) {
          this.status(`Export failed: ${(err as Error).message}`);
        } finally {
          this.busy = false;
          exp.querySelectorAll('button').forEach((x) => (x.disabled = false));
        }
      });
      exp.append(b);
    };
    const name = () => `tessellab-${p.fig ?? p.kind}-t${this.time.toFixed(2)}`;
    exportButton('PNG', async () => {
      download(await exportPng(this.frameAt(this.time).scene, this.palette()), `${name()}.png`);
      this.status('PNG saved.');
    });
    exportButton('SVG', async () => {
      download(exportSvg(this.frameAt(this.time).scene, this.palette()), `${name()}.svg`);
      this.status('SVG saved.');
    });
    exportButton('WebM', async () => {
      this.setPlaying(false);
      const blob = await this.exportAnimation('webm', (i, n) => this.status(`Encoding WebM… ${Math.round((100 * i) / n)}%`));
      download(blob, `tessellab-${p.fig ?? p.kind}.webm`);
      this.status(`WebM saved (${(blob.size / 1024).toFixed(0)} KB).`);
    });
    exportButton('GIF', async () => {
      this.setPlaying(false);
      const blob = await this.exportAnimation('gif', (i, n) => this.status(`Encoding GIF… ${Math.round((100 * i) / n)}%`));
      download(blob, `tessellab-${p.fig ?? p.kind}.gif`);
      this.status(`GIF saved (${(blob.size / 1024).toFixed(0)} KB).`);
    });
    els.status = h('span', { class: 'td-status', role: 'status', 'data-testid': 'status' });
    exp.append(els.status);

    const copy = h('button', { type: 'button', text: 'Copy link', 'data-testid': 'copy-link' });
    copy.addEventListener('click', async () => {
      const url = new URL(this.shareUrl(), location.href).href;
      try {
        await navigator.clipboard.writeText(url);
        this.status('Link copied.');
      } catch {
        this.status(url);
      }
    });
    const reset = h('button', { type: 'button', text: 'Reset', 'data-testid': 'reset' });
    reset.addEventListener('click', () => this.replaceWith(this.initialQuery));
    exp.append(copy, reset);
    els.embed = h('textarea', {
      readonly: true,
      'aria-label': 'Link and embed code',
      'data-testid': 'embed-code',
      rows: 5,
      spellcheck: 'false',
    });
    els.embed.value = this.embedCode(toQuery(p));
    const embed = h('details', { class: 'td-embed' }, h('summary', { text: 'Link and embed code' }), els.embed);

    els.controls = h('div', { class: 'td-controls', 'data-testid': 'controls' }, transport, chips, sliders, opts, els.counts, exp, embed);
    return els.controls;
  }

  /**
   * One cycle of the animation (or the current frame, if nothing moves) as a GIF or WebM at the
   * default export settings, in the wide layout whatever the screen: a file for a blog post.
   */
  exportAnimation(format: 'gif' | 'webm', onProgress: (done: number, total: number) => void = () => {}): Promise<Blob> {
    const clip = {
      frameAt: (t: number) => this.frameAt(t).scene,
      start: this.animated ? 0 : this.time,
      length: period(this.params.timing),
    };
    return format === 'gif' ? exportGif(clip, this.palette(), onProgress) : exportWebm(clip, this.palette(), onProgress);
  }

  private sliderBox: HTMLElement | null = null;

  private rebuildSliders(): void {
    const box = this.sliderBox;
    if (!box) return;
    const p = this.params;
    this.els.sliders.clear();
    box.replaceChildren();
    addFactorSliders(
      box,
      p,
      this.els.sliders,
      () => this.changed(),
      () => this.rebuildSliders(),
    );
    if (this.frame) this.updateReadouts(this.frame);
  }

  private replaceWith(query: string): void {
    const parent = this.root.parentElement;
    if (!parent) return;
    const next = document.createElement('div');
    parent.insertBefore(next, this.root);
    this.destroy();
    const player = new DiagramPlayer({ ...this.opts, input: query, mount: next });
    next.replaceWith(player.root);
    this.opts.onParamsChange?.(query);
    this.onReplace?.(player);
  }

  /** Set by the owner to learn about the new player after a reset. */
  onReplace: ((p: DiagramPlayer) => void) | null = null;

  private status(text: string): void {
    if (this.els.status) this.els.status.textContent = text;
  }
}
