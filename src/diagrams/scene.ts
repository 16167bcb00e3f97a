/**
 * The drawing model every figure produces: a flat list of shapes in CSS pixels, with colours
 * given as ROLES that a palette resolves (light or dark theme). Two renderers read it: an SVG
 * string (export, index thumbnails; pure, testable in Node) and a 2D canvas (the live view).
 * Nothing here knows about patterns.
 */

export type Role = 'bg' | 'ink' | 'muted' | 'faint' | 'grid' | 'accent' | 'green' | 'blue' | 'orange' | 'fill' | 'fillAlt' | 'fillOut';

export type Palette = Record<Role, string>;

/** The talk's red for moving points, a calm ink, two fills. */
export const PALETTES: Record<'light' | 'dark', Palette> = {
  light: {
    bg: '#ffffff',
    ink: '#1f2328',
    muted: '#636c76',
    faint: '#b8c0c8',
    grid: '#e4e8ec',
    accent: '#e0241b',
    green: '#138a43',
    blue: '#1f6feb',
    orange: '#c86a00',
    fill: '#edf2f8',
    fillAlt: '#fbe7c6',
    fillOut: '#f6f7f9',
  },
  dark: {
    bg: '#15181d',
    ink: '#e6e9ed',
    muted: '#9aa4ae',
    faint: '#56606b',
    grid: '#2a3038',
    accent: '#ff4d42',
    green: '#3fcf7c',
    blue: '#5b9dff',
    orange: '#f0a040',
    fill: '#1f2731',
    fillAlt: '#4a3717',
    fillOut: '#1a1e24',
  },
};

export const FONT_STACK = 'system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", "Liberation Sans", Arial, sans-serif';
export const MONO_STACK = 'ui-monospace, "SF Mono", Menlo, Consolas, "DejaVu Sans Mono", monospace';

export interface PathShape {
  kind: 'path';
  /** Sub-paths, each a flat list x0, y0, x1, y1, … */
  polys: number[][];
  closed: boolean;
  fill?: Role;
  stroke?: Role;
  width?: number;
  dash?: number[];
  opacity?: number;
}

export interface DotsShape {
  kind: 'dots';
  /** Centres, flat x0, y0, x1, y1, … */
  pts: number[];
  r: number;
  fill: Role;
  stroke?: Role;
  width?: number;
}

export interface TextShape {
  kind: 'text';
  x: number;
  y: number;
  text: string;
  size: number;
  role: Role;
  anchor?: 'start' | 'middle' | 'end';
  weight?: 400 | 600 | 700;
  mono?: boolean;
}

export type Shape = PathShape | DotsShape | TextShape;

export interface Scene {
  width: number;
  height: number;
  /** For the accessible name and the SVG <title>. */
  title: string;
  /** A one-line text description of the current frame (factor, counts). */
  desc: string;
  shapes: Shape[];
}

/** A small builder so that the figures read like drawing code. */
export class SceneBuilder {
  readonly shapes: Shape[] = [];
  path(polys: number[][], style: Omit<PathShape, 'kind' | 'polys' | 'closed'>, closed = false): void {
    const nonEmpty = polys.filter((p) => p.length >= 4);
    if (nonEmpty.length) this.shapes.push({ kind: 'path', polys: nonEmpty, closed, ...style });
  }
  line(x1: number, y1: number, x2: number, y2: number, stroke: Role, width = 1, dash?: number[]): void {
    this.path([[x1, y1, x2, y2]], dash ? { stroke, width, dash } : { stroke, width });
  }
  dots(pts: number[], r: number, fill: Role, stroke?: Role, width?: number): void {
    if (pts.length) this.shapes.push({ kind: 'dots', pts, r, fill, ...(stroke ? { stroke, width: width ?? 1 } : {}) });
  }
  text(
    x: number,
    y: number,
    text: string,
    size: number,
    role: Role,
    opts: { anchor?: TextShape['anchor']; weight?: TextShape['weight']; mono?: boolean } = {},
  ): void {
    this.shapes.push({ kind: 'text', x, y, text, size, role, ...opts });
  }
  build(width: number, height: number, title: string, desc: string): Scene {
    return { width, height, title, desc, shapes: this.shapes };
  }
}

// ---------------------------------------------------------------------------------------------
// SVG
// ---------------------------------------------------------------------------------------------

const r2 = (v: number) => {
  const s = (Math.round(v * 100) / 100).toString();
  return s === '-0' ? '0' : s;
};

export function escapeXml(s: string): string {
  return s.replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c] as string);
}

function pathData(polys: number[][], closed: boolean): string {
  let d = '';
  for (const p of polys) {
    d += `M${r2(p[0])} ${r2(p[1])}`;
    for (let i = 2; i < p.length; i += 2) d += `L${r2(p[i])} ${r2(p[i + 1])}`;
    if (closed) d += 'Z';
  }
  return d;
}

/** A standalone SVG document for the scene (colours resolved, fonts as a CSS stack). */
export function sceneToSvg(scene: Scene, palette: Palette, opts: { background?: boolean; width?: number } = {}): string {
  const w = opts.width ?? scene.width;
  const h = (w / scene.width) * scene.height;
  const out: string[] = [];
  out.push(
    `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ${r2(scene.width)} ${r2(scene.height)}" width="${r2(w)}" height="${r2(h)}" role="img" aria-label="${escapeXml(scene.title)}">`,
  );
  out.push(`<title>${escapeXml(scene.title)}</title><desc>${escapeXml(scene.desc)}</desc>`);
  if (opts.background !== false) out.push(`<rect width="100%" height="100%" fill="${palette.bg}"/>`);
  for (const s of scene.shapes) {
    if (s.kind === 'path') {
      const attrs = [`d="${pathData(s.polys, s.closed)}"`, `fill="${s.fill ? palette[s.fill] : 'none'}"`];
      if (s.stroke) {
        attrs.push(
          `stroke="${palette[s.stroke]}"`,
          `stroke-width="${r2(s.width ?? 1)}"`,
          'stroke-linejoin="round"',
          'stroke-linecap="round"',
        );
        if (s.dash) attrs.push(`stroke-dasharray="${s.dash.map(r2).join(' ')}"`);
      }
      if (s.opacity !== undefined && s.opacity !== 1) attrs.push(`opacity="${r2(s.opacity)}"`);
      out.push(`<path ${attrs.join(' ')}/>`);
    } else if (s.kind === 'dots') {
      const stroke = s.stroke ? ` stroke="${palette[s.stroke]}" stroke-width="${r2(s.width ?? 1)}"` : '';
      out.push(`<g fill="${palette[s.fill]}"${stroke}>`);
      for (let i = 0; i < s.pts.length; i += 2) out.push(`<circle cx="${r2(s.pts[i])}" cy="${r2(s.pts[i + 1])}" r="${r2(s.r)}"/>`);
      out.push('</g>');
    } else {
      const anchor = s.anchor ?? 'start';
      const family = s.mono ? MONO_STACK : FONT_STACK;
      out.push(
        `<text x="${r2(s.x)}" y="${r2(s.y)}" font-size="${r2(s.size)}" font-family='${family}' font-weight="${s.weight ?? 400}" text-anchor="${anchor}" fill="${palette[s.role]}">${escapeXml(s.text)}</text>`,
      );
    }
  }
  out.push('</svg>');
  return out.join('');
}

// ---------------------------------------------------------------------------------------------
// Canvas 2D
// ---------------------------------------------------------------------------------------------

type Ctx2D = CanvasRenderingContext2D | OffscreenCanvasRenderingContext2D;

/** Draw the scene into a context whose pixel size is `scale` times the scene's. */
export function drawScene(ctx: Ctx2D, scene: Scene, palette: Palette, scale: number, opts: { background?: boolean } = {}): void {
  ctx.save();
  ctx.setTransform(scale, 0, 0, scale, 0, 0);
  if (opts.background !== false) {
    ctx.fillStyle = palette.bg;
    ctx.fillRect(0, 0, scene.width, scene.height);
  } else {
    ctx.clearRect(0, 0, scene.width, scene.height);
  }
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  for (const s of scene.shapes) {
    if (s.kind === 'path') {
      ctx.beginPath();
      for (const p of s.polys) {
        ctx.moveTo(p[0], p[1]);
        for (let i = 2; i < p.length; i += 2) ctx.lineTo(p[i], p[i + 1]);
        if (s.closed) ctx.closePath();
      }
      ctx.globalAlpha = s.opacity ?? 1;
      if (s.fill) {
        ctx.fillStyle = palette[s.fill];
        ctx.fill();
      }
      if (s.stroke) {
        ctx.strokeStyle = palette[s.stroke];
        ctx.lineWidth = s.width ?? 1;
        ctx.setLineDash(s.dash ?? []);
        ctx.stroke();
        ctx.setLineDash([]);
      }
      ctx.globalAlpha = 1;
    } else if (s.kind === 'dots') {
      ctx.beginPath();
      for (let i = 0; i < s.pts.length; i += 2) {
        ctx.moveTo(s.pts[i] + s.r, s.pts[i + 1]);
        ctx.arc(s.pts[i], s.pts[i + 1], s.r, 0, Math.PI * 2);
      }
      ctx.fillStyle = palette[s.fill];
      ctx.fill();
      if (s.stroke) {
        ctx.strokeStyle = palette[s.stroke];
        ctx.lineWidth = s.width ?? 1;
        ctx.stroke();
      }
    } else {
      ctx.font = `${s.weight ?? 400} ${s.size}px ${s.mono ? MONO_STACK : FONT_STACK}`;
      ctx.textAlign = s.anchor === 'middle' ? 'center' : s.anchor === 'end' ? 'right' : 'left';
      ctx.textBaseline = 'alphabetic';
      ctx.fillStyle = palette[s.role];
      ctx.fillText(s.text, s.x, s.y);
    }
  }
  ctx.restore();
}
