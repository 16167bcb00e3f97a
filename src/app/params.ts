/**
 * The demo's tunables, read from and written back to the URL, so that any view can be shared
 * or reproduced: `?model=torus&mode=fixed&factor=12&wire=1&cage=0&lod=1.5&up=z&t=0&surface=phong`.
 * Pure functions (no DOM) so the unit tests can hold them to their contract.
 */
import { MAX_FACTOR } from '../pattern/max-factor.ts';
import { POW2_LEVELS } from '../pattern/pow2.ts';
import { MATERIALS, type Material } from '../gpu/contract/render.ts';

export type Mode = 'adaptive' | 'fixed';
export type UpAxis = 'y' | 'z';
/** What is drawn: the Catmull-Clark limit surface, Phong tessellation, or the cage's flat faces. */
export type Surface = 'catmull-clark' | 'phong' | 'cage' | 'bezier-acc' | 'gregory-acc' | 'pm-acc';
/** The three approximations of the Catmull-Clark limit (ACC) the compute tessellator also draws. */
export const ACC_SURFACES = ['bezier-acc', 'gregory-acc', 'pm-acc'] as const;
/** Every value of `surface`. */
export const SURFACES: readonly Surface[] = ['catmull-clark', 'phong', 'cage', ...ACC_SURFACES];
/** Other spellings a shared URL may carry. */
const SURFACE_ALIASES: Record<string, Surface> = { cc: 'catmull-clark', catmullclark: 'catmull-clark', tessellated: 'phong' };
/** Who tessellates: the compute tessellator (built once, the stored mesh drawn in every pass) or
 * the instanced power-of-two tessellator (src/gpu/instanced/instanced.ts: re-evaluates in every pass). */
export type TessellatorKind = 'compute' | 'instanced';

export interface DemoParams {
  /** A model name from the project's list, or the path of an OBJ on the page's own site (model-source.ts). */
  model: string | null;
  /** The shown model's up axis: Y, OBJ's convention, as the project's models and the talk's are
   * stored; some exporters (CAD, Blender without its axis conversion) write Z-up. */
  up: UpAxis;
  mode: Mode;
  /** The tessellated Catmull-Clark or Phong surface, or the cage's own faces (flat, before
   * tessellation). `surface=tessellated` (older links) reads as Phong, what it used to draw. */
  surface: Surface;
  /** Tint the Catmull-Clark surface by the kind of patch under it (regular, irregular, ...). */
  patches: boolean;
  /** The surface's material under the studio lights (`material=metal`): clay or metal. */
  material: Material;
  /** Catmull-Clark: blend from the flat triangle to the surface at low tess factors (no pops). */
  flat: boolean;
  /** Adaptive mode's global LOD scale (1 = the default density). */
  lod: number;
  /** Fixed mode's one factor. */
  factor: number;
  wire: boolean;
  cage: boolean;
  /** Turntable: the camera turns around the model (and adaptive mode rebuilds every frame). */
  spin: boolean;
  /** Render one fixed frame at this time (seconds) and stop: deterministic screenshots. */
  t: number | null;
  /** Camera yaw and pitch in degrees, and distance in bounding radii (null = framed automatically). */
  yaw: number | null;
  pitch: number | null;
  dist: number | null;
  /** Show the control panel and stats (off for clean embeds). */
  ui: boolean;
  /** Output buffer capacity, millions of vertices (and as many triangles). The talk uses 16. */
  capacity: number;
  /** `tessellator=instanced`: the instanced power-of-two tessellator draws instead (Phong
   * surface; factors adaptive → its dynamic LOD scaled by `lod`, fixed → every patch at `level`). */
  tessellator: TessellatorKind;
  /** The instanced tessellator's static level: one of LEVEL_CHOICES (powers of two). */
  level: number;
  /** Split view: the compute tessellator on the left half, the instanced one on the right, same
   * cage, camera and settings (whatever `tessellator` says). */
  split: boolean;
  /** The instanced tessellator's surface (`instsurface=`): Phong, the exact Catmull-Clark limit,
   * or one of the ACC schemes (closed quad and triangle cages; elsewhere it falls back to Phong
   * and says why). */
  instSurface: InstancedSurface;
  /** The instanced tessellator's flat shading (`flatshade=1`): each facet by its own normal. */
  flatShade: boolean;
  /** The ACC error views (`errorview=geometry|normal`; the NVIDIA sample's "Geometry Error" and
   * "Normal Error"): an ACC surface coloured by its error against the exact Catmull-Clark limit
   * at each output vertex; 'off' for the usual colours. */
  errorView: ErrorView;
  /** The top of the error colour bar (`errrange=`), in the view's unit: a fraction of the
   * bounding-box diagonal (geometry) or degrees (normal); null: the view's default. */
  errRange: number | null;
  /** Comparison view (`compare=`): the left half draws `surface`, the right half this one, same
   * cage and camera; null: off. */
  compare: CompareSurface | null;
  /** Displacement by the model's height map (`disp=0` turns it off; models without one ignore it). */
  disp: boolean;
  /** The height map's scale, as a multiple of the model's own (`dscale=`). */
  dscale: number;
  /** The UV-seam view (`seams=1`): the cage's edges, UV seams highlighted. */
  seams: boolean;
}

export type ErrorView = 'off' | 'geometry' | 'normal';
export const ERROR_VIEWS: readonly ErrorView[] = ['off', 'geometry', 'normal'];
/** What `errrange` may be (fractions of the diagonal are small, degrees up to 180). */
export const ERR_RANGE = { min: 1e-7, max: 180 } as const;
/** What the comparison's right half may draw: a tessellated surface. */
export type CompareSurface = 'catmull-clark' | 'phong' | 'bezier-acc' | 'gregory-acc' | 'pm-acc';
export const COMPARE_SURFACES: readonly CompareSurface[] = ['catmull-clark', 'phong', ...ACC_SURFACES];

export type InstancedSurface = 'phong' | 'catmull-clark' | 'bezier-acc' | 'gregory-acc' | 'pm-acc';
export const INSTANCED_SURFACES: readonly InstancedSurface[] = ['phong', 'catmull-clark', 'bezier-acc', 'gregory-acc', 'pm-acc'];

export const LOD_RANGE = { min: 0.05, max: 8 } as const;
export const FACTOR_RANGE = { min: 1, max: MAX_FACTOR } as const;
export const CAPACITY_RANGE = { min: 0.01, max: 16 } as const;
/** The instanced tessellator's levels: its patterns' (src/pattern/pow2.ts). */
export const LEVEL_CHOICES = POW2_LEVELS;
export const DSCALE_RANGE = { min: -4, max: 4 } as const;

export const DEFAULT_PARAMS: Readonly<DemoParams> = Object.freeze({
  model: null,
  up: 'y',
  mode: 'adaptive',
  surface: 'catmull-clark',
  patches: false,
  material: 'clay',
  flat: true,
  lod: 1,
  factor: 8,
  // Off: the surface is the showcase; the wireframe (the pattern's triangles) is one click away.
  wire: false,
  cage: false,
  spin: false,
  t: null,
  yaw: null,
  pitch: null,
  dist: null,
  ui: true,
  capacity: 4,
  tessellator: 'compute',
  level: 8,
  split: false,
  instSurface: 'phong',
  flatShade: false,
  errorView: 'off',
  errRange: null,
  compare: null,
  disp: true,
  dscale: 1,
  seams: false,
});

function num(v: string | null, min: number, max: number): number | null {
  if (v === null || v.trim() === '') return null;
  const x = Number(v);
  if (!Number.isFinite(x)) return null;
  return Math.min(max, Math.max(min, x));
}

function bool(v: string | null): boolean | null {
  if (v === null) return null;
  const s = v.trim().toLowerCase();
  if (s === '' || s === '1' || s === 'true' || s === 'yes' || s === 'on') return true;
  if (s === '0' || s === 'false' || s === 'no' || s === 'off') return false;
  return null;
}

/**
 * Parse a query string (with or without the leading '?'). Unknown keys are ignored, bad values
 * fall back to the defaults, numbers are clamped to their ranges: a URL can never break the page.
 * `freeze=1` is a synonym of `t=0`.
 */
export function parseParams(search: string): DemoParams {
  const q = new URLSearchParams(search.startsWith('?') ? search.slice(1) : search);
  const p: DemoParams = { ...DEFAULT_PARAMS };
  const model = q.get('model');
  if (model !== null && model.trim() !== '') p.model = model.trim();
  const up = q.get('up')?.trim().toLowerCase();
  if (up === 'y' || up === 'z') p.up = up;
  const mode = q.get('mode')?.trim().toLowerCase();
  if (mode === 'adaptive' || mode === 'fixed') p.mode = mode;
  const surface = q.get('surface')?.trim().toLowerCase();
  const named = surface ? (SURFACE_ALIASES[surface] ?? surface) : '';
  if ((SURFACES as readonly string[]).includes(named)) p.surface = named as Surface;
  p.patches = bool(q.get('patches')) ?? p.patches;
  const material = q.get('material')?.trim().toLowerCase();
  if ((MATERIALS as readonly string[]).includes(material ?? '')) p.material = material as Material;
  p.flat = bool(q.get('flat')) ?? p.flat;
  p.lod = num(q.get('lod'), LOD_RANGE.min, LOD_RANGE.max) ?? p.lod;
  p.factor = num(q.get('factor'), FACTOR_RANGE.min, FACTOR_RANGE.max) ?? p.factor;
  p.wire = bool(q.get('wire')) ?? p.wire;
  p.cage = bool(q.get('cage')) ?? p.cage;
  p.spin = bool(q.get('spin')) ?? p.spin;
  p.ui = bool(q.get('ui')) ?? p.ui;
  p.capacity = num(q.get('cap'), CAPACITY_RANGE.min, CAPACITY_RANGE.max) ?? p.capacity;
  const tessellator = q.get('tessellator')?.trim().toLowerCase();
  if (tessellator === 'compute' || tessellator === 'instanced') p.tessellator = tessellator;
  // Any level in range, rounded down to a power of two (what the instanced patterns have).
  const level = num(q.get('level'), LEVEL_CHOICES[0], LEVEL_CHOICES[LEVEL_CHOICES.length - 1]);
  if (level !== null) p.level = 2 ** Math.floor(Math.log2(level));
  p.split = bool(q.get('split')) ?? p.split;
  const instSurface = q.get('instsurface')?.trim().toLowerCase();
  p.flatShade = bool(q.get('flatshade')) ?? p.flatShade;
  if (instSurface && (INSTANCED_SURFACES as readonly string[]).includes(instSurface)) p.instSurface = instSurface as InstancedSurface;
  const errorView = q.get('errorview')?.trim().toLowerCase();
  if (errorView === 'geometry' || errorView === 'normal' || errorView === 'off') p.errorView = errorView;
  else if (errorView === 'position' || errorView === 'geom') p.errorView = 'geometry';
  p.errRange = num(q.get('errrange'), ERR_RANGE.min, ERR_RANGE.max);
  p.compare = compareSurface(q.get('compare'));
  p.disp = bool(q.get('disp')) ?? p.disp;
  p.dscale = num(q.get('dscale'), DSCALE_RANGE.min, DSCALE_RANGE.max) ?? p.dscale;
  p.seams = bool(q.get('seams')) ?? p.seams;
  p.t = num(q.get('t'), 0, 1e6);
  if (p.t === null && bool(q.get('freeze')) === true) p.t = 0;
  p.yaw = num(q.get('yaw'), -1e4, 1e4);
  p.pitch = num(q.get('pitch'), -89, 89);
  p.dist = num(q.get('dist'), 0.5, 40);
  return p;
}

/** The query string for these params, listing only what differs from the defaults. */
export function formatParams(p: DemoParams): string {
  const q = new URLSearchParams();
  const d = DEFAULT_PARAMS;
  if (p.model) q.set('model', p.model);
  if (p.up !== d.up) q.set('up', p.up);
  if (p.mode !== d.mode) q.set('mode', p.mode);
  if (p.surface !== d.surface) q.set('surface', p.surface);
  if (p.patches !== d.patches) q.set('patches', p.patches ? '1' : '0');
  if (p.material !== d.material) q.set('material', p.material);
  if (p.flat !== d.flat) q.set('flat', p.flat ? '1' : '0');
  if (p.lod !== d.lod) q.set('lod', String(round(p.lod, 3)));
  if (p.factor !== d.factor) q.set('factor', String(round(p.factor, 3)));
  if (p.wire !== d.wire) q.set('wire', p.wire ? '1' : '0');
  if (p.cage !== d.cage) q.set('cage', p.cage ? '1' : '0');
  if (p.spin !== d.spin) q.set('spin', p.spin ? '1' : '0');
  if (p.ui !== d.ui) q.set('ui', p.ui ? '1' : '0');
  if (p.capacity !== d.capacity) q.set('cap', String(p.capacity));
  if (p.tessellator !== d.tessellator) q.set('tessellator', p.tessellator);
  if (p.level !== d.level) q.set('level', String(p.level));
  if (p.split !== d.split) q.set('split', p.split ? '1' : '0');
  if (p.instSurface !== d.instSurface) q.set('instsurface', p.instSurface);
  if (p.flatShade !== d.flatShade) q.set('flatshade', p.flatShade ? '1' : '0');
  if (p.errorView !== d.errorView) q.set('errorview', p.errorView);
  if (p.errRange !== null) q.set('errrange', String(p.errRange));
  if (p.compare !== null) q.set('compare', p.compare);
  if (p.disp !== d.disp) q.set('disp', p.disp ? '1' : '0');
  if (p.dscale !== d.dscale) q.set('dscale', String(round(p.dscale, 3)));
  if (p.seams !== d.seams) q.set('seams', p.seams ? '1' : '0');
  if (p.t !== null) q.set('t', String(p.t));
  if (p.yaw !== null) q.set('yaw', String(round(p.yaw, 1)));
  if (p.pitch !== null) q.set('pitch', String(round(p.pitch, 1)));
  if (p.dist !== null) q.set('dist', String(round(p.dist, 2)));
  const s = q.toString();
  return s ? `?${s}` : '';
}

/** A comparison surface by its URL name (the surface names, `cc` for Catmull-Clark); null for
 * anything else (`off`, `0`, an unknown name). */
function compareSurface(v: string | null): CompareSurface | null {
  const s = v?.trim().toLowerCase();
  if (!s) return null;
  if (s === 'cc' || s === 'catmullclark') return 'catmull-clark';
  return (COMPARE_SURFACES as readonly string[]).includes(s) ? (s as CompareSurface) : null;
}

function round(x: number, digits: number): number {
  const k = 10 ** digits;
  return Math.round(x * k) / k;
}

/** The numeric parameters, by URL key, and the field each sets. */
const NUMERIC: [key: string, field: keyof DemoParams][] = [
  ['lod', 'lod'],
  ['factor', 'factor'],
  ['cap', 'capacity'],
  ['level', 'level'],
  ['errrange', 'errRange'],
  ['dscale', 'dscale'],
  ['t', 't'],
  ['yaw', 'yaw'],
  ['pitch', 'pitch'],
  ['dist', 'dist'],
];

/**
 * Notes for the numbers a URL gave that the page could not use as given (out of range: clamped;
 * not a number: the default; a level between powers of two: rounded down), to show the visitor
 * which values are in effect instead of changing them silently (`cap=1e9` would otherwise raise
 * the GPU memory without a word).
 */
export function paramNotes(search: string): string[] {
  const q = new URLSearchParams(search.startsWith('?') ? search.slice(1) : search);
  const p = parseParams(search);
  const notes: string[] = [];
  for (const [key, field] of NUMERIC) {
    const raw = q.get(key);
    if (raw === null || raw.trim() === '') continue;
    const used = p[field];
    const x = Number(raw);
    const shown = raw.length > 24 ? `${raw.slice(0, 21)}...` : raw;
    if (!Number.isFinite(x)) notes.push(`${key}=${shown} is not a number: ${used === null ? 'the default' : used} is used`);
    else if (x !== used) notes.push(`${key}=${shown} is outside what the page takes: ${used} is used`);
  }
  return notes;
}

export { isModelUrl } from './model-source.ts';
