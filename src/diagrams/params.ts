/**
 * Figure parameters from a URL query string or a custom element's attributes, validated.
 * Every problem becomes a readable message and the parameter falls back to its default (or is
 * clamped), so a bad link still draws a figure, with the message shown above it.
 *
 * Keys are case-insensitive (`maxFactor` = `maxfactor`, as HTML attributes are lowercased).
 * A factor is a number or key values `a..b..c` that the animation visits in turn.
 */
import { LINE_MODES, TRI_MODES, type LineMode, type TriMode } from '../pattern/types.ts';
import { FIGURES, type Figure } from './figures.ts';
import { defaultDuration, type Ease, type LoopMode, type Timing, type Track } from './timeline.ts';

export type Kind = 'line' | 'triangle';
export type Theme = 'auto' | 'light' | 'dark';
export type Stage = 'parallelogram' | 'clamp' | 'gap' | 'match' | 'full';
export type Shape = 'equilateral' | 'right' | 'thin';
export type LineView = 'line' | 'trace';

export interface Message {
  key: string;
  text: string;
}

export interface CommonParams {
  /** The preset this figure started from (title, caption), if any. */
  fig: string | null;
  /** Frozen time in seconds (paused there), or null. */
  t: number | null;
  /** Time to start at when not frozen. */
  start: number;
  autoplay: boolean;
  speed: number;
  timing: Timing;
  ease: Ease;
  snap: boolean;
  chrome: boolean;
  caption: boolean;
  theme: Theme;
  labels: boolean;
  maxFactor: number;
  /** Set by an iframe embedding: no page header, transparent margins. */
  embed: boolean;
}

export interface LineParams extends CommonParams {
  kind: 'line';
  modes: LineMode[];
  factor: Track;
  view: LineView;
  /** Trace view: follow the point nearest this position (display units) at the sweep's end. */
  track: number | null;
  /** Show only the first half of the edge, in half-edge units (D3D11's symmetric half). */
  half: boolean;
  /** Dashed reference positions (display units). */
  marks: number[];
  /** Colour segments: small (split) green, big (not yet split) red. */
  segments: boolean;
}

export interface TriParams extends CommonParams {
  kind: 'triangle';
  modes: TriMode[];
  factors: [Track, Track, Track];
  /** D3D11 inside factor; null = the mean of the edge factors (as the pattern CLI). */
  inside: Track | null;
  reverse: [boolean, boolean, boolean];
  stage: Stage;
  shape: Shape;
  loops: boolean;
  points: boolean;
}

export type Params = LineParams | TriParams;

export interface Parsed<P extends Params = Params> {
  params: P;
  messages: Message[];
  figure: Figure | null;
}

const COMMON_KEYS = [
  'fig',
  't',
  'start',
  'autoplay',
  'speed',
  'duration',
  'hold',
  'loop',
  'ease',
  'snap',
  'chrome',
  'caption',
  'theme',
  'labels',
  'maxfactor',
  'embed',
];
const LINE_KEYS = ['mode', 'factor', 'from', 'to', 'view', 'track', 'half', 'marks', 'segments'];
const TRI_KEYS = ['mode', 'from', 'to', 'f0', 'f1', 'f2', 'inside', 'reverse', 'stage', 'shape', 'loops', 'points'];

export function knownKeys(kind: Kind): string[] {
  return [...COMMON_KEYS, ...(kind === 'line' ? LINE_KEYS : TRI_KEYS)];
}

export const STAGES: readonly Stage[] = ['parallelogram', 'clamp', 'gap', 'match', 'full'];
export const SHAPES: readonly Shape[] = ['equilateral', 'right', 'thin'];
export const THEMES: readonly Theme[] = ['auto', 'light', 'dark'];
const LOOPS: readonly LoopMode[] = ['pingpong', 'repeat', 'once'];
const EASES: readonly Ease[] = ['linear', 'log'];
const VIEWS: readonly LineView[] = ['line', 'trace'];

export const MAX_KEYS = 16;

type Raw = Map<string, string>;

export function toRaw(input: string | URLSearchParams | Record<string, string | null | undefined>): Raw {
  const raw: Raw = new Map();
  if (typeof input === 'string' || input instanceof URLSearchParams) {
    const sp = typeof input === 'string' ? new URLSearchParams(input.startsWith('?') ? input.slice(1) : input) : input;
    for (const [k, v] of sp) raw.set(k.toLowerCase(), v);
  } else {
    for (const [k, v] of Object.entries(input)) if (v !== null && v !== undefined) raw.set(k.toLowerCase(), v);
  }
  return raw;
}

export function findFigure(id: string): Figure | null {
  return FIGURES.find((f) => f.id === id) ?? null;
}

/** The preset's values under the given ones. Factors are replaced as groups: giving `from`/`to`
 * (or a line's `factor`) drops the preset's factors, giving `f1` drops only its `f1`. */
function mergePreset(kind: Kind, fig: Figure, given: Raw): Raw {
  const base = toRaw(fig.query);
  const out: Raw = new Map(base);
  const has = (k: string) => given.has(k);
  if (kind === 'line' && (has('factor') || has('from') || has('to'))) for (const k of ['factor', 'from', 'to']) out.delete(k);
  if (kind === 'triangle' && (has('from') || has('to'))) for (const k of ['from', 'to', 'f0', 'f1', 'f2']) out.delete(k);
  for (const [k, v] of given) out.set(k, v);
  return out;
}

class Reader {
  readonly messages: Message[] = [];
  constructor(readonly raw: Raw) {}
  has(k: string): boolean {
    return this.raw.has(k);
  }
  say(key: string, text: string): void {
    this.messages.push({ key, text });
  }
  num(k: string, def: number, lo: number, hi: number, what = 'a number'): number {
    const s = this.raw.get(k);
    if (s === undefined) return def;
    const v = s.trim() === '' ? NaN : Number(s);
    if (!Number.isFinite(v)) {
      this.say(k, `${k}=${JSON.stringify(s)} is not ${what}; using ${def}.`);
      return def;
    }
    if (v < lo || v > hi) {
      const c = Math.min(hi, Math.max(lo, v));
      this.say(k, `${k}=${s} is outside [${lo}, ${hi}]; using ${c}.`);
      return c;
    }
    return v;
  }
  bool(k: string, def: boolean): boolean {
    const s = this.raw.get(k);
    if (s === undefined) return def;
    const v = s.trim().toLowerCase();
    if (['', '1', 'true', 'yes', 'on'].includes(v)) return true;
    if (['0', 'false', 'no', 'off'].includes(v)) return false;
    this.say(k, `${k}=${JSON.stringify(s)} should be 1 or 0; using ${def ? 1 : 0}.`);
    return def;
  }
  pick<T extends string>(k: string, options: readonly T[], def: T): T {
    const s = this.raw.get(k);
    if (s === undefined) return def;
    const v = s.trim().toLowerCase() as T;
    if (options.includes(v)) return v;
    this.say(k, `${k}=${JSON.stringify(s)} is not one of ${options.join(', ')}; using ${def}.`);
    return def;
  }
  /** A factor track: `8` or `1..16` or `8..1..8`, each key clamped to [lo, hi]. */
  track(k: string, def: Track, lo: number, hi: number): Track {
    const s = this.raw.get(k);
    if (s === undefined) return def;
    return this.parseTrack(k, s, def, lo, hi);
  }
  parseTrack(k: string, s: string, def: Track, lo: number, hi: number): Track {
    const parts = s.split('..').map((p) => p.trim());
    if (parts.length > MAX_KEYS) {
      this.say(k, `${k} has ${parts.length} key values; at most ${MAX_KEYS} are allowed. Using ${def.join('..')}.`);
      return def;
    }
    const vals = parts.map((p) => (p === '' ? NaN : Number(p)));
    if (vals.some((v) => !Number.isFinite(v))) {
      this.say(
        k,
        `${k}=${JSON.stringify(s)} is not a factor (a number such as 5.5, or key values such as 1..16); using ${def.join('..')}.`,
      );
      return def;
    }
    const clamped = vals.map((v) => Math.min(hi, Math.max(lo, v)));
    if (clamped.some((v, i) => v !== vals[i])) this.say(k, `${k}=${s}: factors must be in [${lo}, ${hi}]; using ${clamped.join('..')}.`);
    return clamped;
  }
  list<T extends string>(k: string, options: readonly T[], def: T[]): T[] {
    const s = this.raw.get(k);
    if (s === undefined) return def;
    const out: T[] = [];
    const bad: string[] = [];
    for (const part of s
      .split(',')
      .map((p) => p.trim())
      .filter(Boolean)) {
      const m = resolveMode(part, options);
      if (m === null) bad.push(part);
      else if (!out.includes(m)) out.push(m);
    }
    if (bad.length) this.say(k, `unknown ${k} ${bad.map((b) => JSON.stringify(b)).join(', ')}: choose from ${options.join(', ')}.`);
    if (!out.length) {
      if (!bad.length) this.say(k, `${k} is empty; using ${def.join(',')}.`);
      else this.say(k, `no valid ${k} left; using ${def.join(',')}.`);
      return def;
    }
    return out;
  }
}

/** `fractional-even` and `FRACTIONAL_EVEN` name `fractional_even`; `one_at_a_time` names `one-at-a-time`. */
function resolveMode<T extends string>(s: string, options: readonly T[]): T | null {
  const v = s.toLowerCase();
  for (const o of options) if (o === v || o.replace(/[-_]/g, '') === v.replace(/[-_]/g, '')) return o;
  return null;
}

function isPow2(n: number): boolean {
  return Number.isInteger(n) && n >= 2 && n <= 256 && (n & (n - 1)) === 0;
}

/** Parse (and validate) the parameters of a `kind` figure. Never throws. */
export function parseParams<K extends Kind>(
  kind: K,
  input: string | URLSearchParams | Record<string, string | null | undefined>,
): Parsed<K extends 'line' ? LineParams : TriParams> {
  let given = toRaw(input);
  const pre: Message[] = [];
  let figure: Figure | null = null;
  const figId = given.get('fig');
  if (figId !== undefined) {
    const f = findFigure(figId.trim());
    if (!f) pre.push({ key: 'fig', text: `there is no figure ${JSON.stringify(figId)}; see the diagram index for the list.` });
    else if (f.kind !== kind)
      pre.push({
        key: 'fig',
        text: `figure ${JSON.stringify(figId)} is a ${f.kind} figure, not a ${kind} figure; open ${f.kind}.html?fig=${f.id}.`,
      });
    else {
      figure = f;
      given = mergePreset(kind, f, given);
    }
  }
  const r = new Reader(given);
  r.messages.push(...pre);
  const known = new Set(knownKeys(kind));
  for (const k of given.keys()) {
    if (!known.has(k) && !k.startsWith('utm_')) r.say(k, `unknown parameter ${JSON.stringify(k)} (ignored).`);
  }

  let maxFactor = 64;
  if (r.has('maxfactor')) {
    const s = r.raw.get('maxfactor') as string;
    const v = Number(s);
    if (isPow2(v)) maxFactor = v;
    else r.say('maxfactor', `maxFactor=${JSON.stringify(s)} must be a power of two from 2 to 256; using 64.`);
  }

  const ease = r.pick('ease', EASES, 'linear');
  const loop = r.pick('loop', LOOPS, 'pingpong');
  const common = {
    fig: figure ? figure.id : null,
    t: r.has('t') ? r.num('t', 0, 0, 3600, 'a time in seconds') : null,
    start: r.num('start', 0, 0, 3600, 'a time in seconds'),
    autoplay: r.bool('autoplay', true),
    speed: r.num('speed', 1, 0.05, 16),
    ease,
    snap: r.bool('snap', false),
    chrome: r.bool('chrome', true),
    caption: r.bool('caption', true),
    theme: r.pick('theme', THEMES, 'auto'),
    labels: r.bool('labels', false),
    maxFactor,
    embed: r.bool('embed', false),
  };

  let params: Params;
  let tracks: Track[];
  if (kind === 'line') {
    const modes = r.list('mode', LINE_MODES, ['hable']);
    let factor: Track = [1, 16];
    if (r.has('factor') && (r.has('from') || r.has('to'))) r.say('factor', 'give either factor or from/to, not both; using factor.');
    if (r.has('factor')) factor = r.track('factor', factor, 1, maxFactor);
    else if (r.has('from') || r.has('to')) {
      const from = r.num('from', 1, 1, maxFactor, 'a factor');
      const to = r.num('to', r.has('from') ? Math.min(maxFactor, Math.max(16, from)) : 16, 1, maxFactor, 'a factor');
      factor = [from, to];
    }
    const half = r.bool('half', false);
    const marks: number[] = [];
    if (r.has('marks')) {
      for (const part of (r.raw.get('marks') as string).split(',').filter((p) => p.trim() !== '')) {
        const v = Number(part);
        if (Number.isFinite(v) && v >= 0 && v <= 1) marks.push(v);
        else r.say('marks', `marks: ${JSON.stringify(part)} is not a position in [0, 1] (ignored).`);
      }
    }
    params = {
      kind: 'line',
      ...common,
      timing: { duration: 0, hold: 0, loop },
      modes,
      factor,
      view: r.pick('view', VIEWS, 'line'),
      track: r.has('track') ? r.num('track', 0.5, 0, 1, 'a position in [0, 1]') : null,
      half,
      marks,
      segments: r.bool('segments', false),
    };
    tracks = [factor];
  } else {
    const modes = r.list('mode', TRI_MODES, ['clamped']);
    const from = r.num('from', 1, 1, maxFactor, 'a factor');
    const to = r.num('to', r.has('from') ? Math.min(maxFactor, Math.max(8, from)) : 8, 1, maxFactor, 'a factor');
    const all: Track = from === to ? [from] : [from, to];
    const factors: [Track, Track, Track] = [
      r.track('f0', all, 1, maxFactor),
      r.track('f1', all, 1, maxFactor),
      r.track('f2', all, 1, maxFactor),
    ];
    const inside = r.has('inside') ? r.track('inside', [8], 1, 64) : null;
    if (inside && !modes.some((m) => m !== 'clamped'))
      r.say('inside', 'inside applies to the D3D11 modes only: the clamped pattern has no inside factor (ignored).');
    let reverse: [boolean, boolean, boolean] = [false, false, false];
    if (r.has('reverse')) {
      const s = (r.raw.get('reverse') as string).replace(/,/g, '').trim();
      if (/^[01]{3}$/.test(s)) reverse = [s[0] === '1', s[1] === '1', s[2] === '1'];
      else r.say('reverse', `reverse=${JSON.stringify(r.raw.get('reverse'))} should be three flags such as 0,1,0; using 0,0,0.`);
    }
    params = {
      kind: 'triangle',
      ...common,
      timing: { duration: 0, hold: 0, loop },
      modes,
      factors,
      inside,
      reverse,
      stage: r.pick('stage', STAGES, 'full'),
      shape: r.pick('shape', SHAPES, 'equilateral'),
      loops: r.bool('loops', false),
      points: r.bool('points', true),
    };
    tracks = [...factors, ...(inside ? [inside] : [])];
  }
  params.timing.duration = r.has('duration') ? r.num('duration', 4, 0.2, 120, 'a time in seconds') : defaultDuration(tracks, ease);
  params.timing.hold = r.num('hold', 0.6, 0, 30, 'a time in seconds');
  return { params: params as K extends 'line' ? LineParams : TriParams, messages: r.messages, figure };
}

// ---------------------------------------------------------------------------------------------
// Back to a query string (share links, embed snippets)
// ---------------------------------------------------------------------------------------------

const fmtNum = (v: number) => String(Math.round(v * 1e4) / 1e4);
const fmtTrack = (t: Track) => t.map(fmtNum).join('..');
const fmtBool = (b: boolean) => (b ? '1' : '0');

/** Every parameter as strings (the canonical form compared by `toQuery`). */
export function formatParams(p: Params): Map<string, string> {
  const m = new Map<string, string>();
  if (p.t !== null) m.set('t', fmtNum(p.t));
  m.set('start', fmtNum(p.start));
  m.set('autoplay', fmtBool(p.autoplay));
  m.set('speed', fmtNum(p.speed));
  m.set('duration', fmtNum(p.timing.duration));
  m.set('hold', fmtNum(p.timing.hold));
  m.set('loop', p.timing.loop);
  m.set('ease', p.ease);
  m.set('snap', fmtBool(p.snap));
  m.set('chrome', fmtBool(p.chrome));
  m.set('caption', fmtBool(p.caption));
  m.set('theme', p.theme);
  m.set('labels', fmtBool(p.labels));
  m.set('maxfactor', String(p.maxFactor));
  m.set('mode', p.modes.join(','));
  if (p.kind === 'line') {
    m.set('factor', fmtTrack(p.factor));
    m.set('view', p.view);
    if (p.track !== null) m.set('track', fmtNum(p.track));
    m.set('half', fmtBool(p.half));
    m.set('marks', p.marks.map(fmtNum).join(','));
    m.set('segments', fmtBool(p.segments));
  } else {
    p.factors.forEach((f, i) => m.set(`f${i}`, fmtTrack(f)));
    if (p.inside) m.set('inside', fmtTrack(p.inside));
    m.set('reverse', p.reverse.map(fmtBool).join(','));
    m.set('stage', p.stage);
    m.set('shape', p.shape);
    m.set('loops', fmtBool(p.loops));
    m.set('points', fmtBool(p.points));
  }
  return m;
}

/** The shortest query string that parses back to `p`: `fig` plus what differs from it. */
export function toQuery(p: Params, extra: Record<string, string> = {}): string {
  const base = parseParams(p.kind, p.fig ? { fig: p.fig } : {}).params;
  const want = formatParams(p);
  const have = formatParams(base);
  const sp = new URLSearchParams();
  if (p.fig) sp.set('fig', p.fig);
  for (const [k, v] of want) if (k !== 'duration' && have.get(k) !== v) sp.set(k === 'maxfactor' ? 'maxFactor' : k, v);
  // The duration defaults from the factors: give it only when the rest would not imply it.
  const implied = formatParams(parseParams(p.kind, sp).params).get('duration');
  if (implied !== want.get('duration')) sp.set('duration', want.get('duration') as string);
  for (const [k, v] of Object.entries(extra)) sp.set(k, v);
  return sp.toString().replace(/%2C/g, ',');
}
