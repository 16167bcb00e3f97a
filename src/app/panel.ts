/**
 * The demo's control panel (lil-gui), declared as data: PANEL lists each folder's controls (label,
 * kind, options or range, the parameter they bind, what a change invalidates, when they show),
 * and buildPanel turns the table into lil-gui controls. Every change of a parameter updates the
 * URL first (the demo's syncUrl), then asks the demo for what it invalidates (src/app/tessellation-demo.ts).
 */
import GUI, { type Controller } from 'lil-gui';
import { BUILTIN_MODELS } from './models.ts';
import { MATERIALS } from '../gpu/contract/render.ts';
import {
  COMPARE_SURFACES,
  DSCALE_RANGE,
  ERR_RANGE,
  FACTOR_RANGE,
  LEVEL_CHOICES,
  LOD_RANGE,
  type CompareSurface,
  type DemoParams,
} from './params.ts';
import { isAcc, isExact, SURFACE_NAMES } from './surfaces.ts';
import { openFile } from './file-input.ts';
import { showToast } from './ui.ts';
import type { PickerDisplay } from './demo-scene.ts';
import type { TessellationDemo } from './tessellation-demo.ts';

export interface Panel extends PickerDisplay {
  gui: GUI;
}

/** What the panel holds besides the parameters: the model picked, and the error range as shown
 * (the view's default while the URL has none). */
interface PanelState {
  picked: string;
  errRange: number;
}

/** One control of the panel. */
interface Control {
  label: string;
  /** toggle: a checkbox; choice: a drop-down of `options`; range: a slider over `range`; number:
   * a number field (changed when editing ends); action: a button. */
  kind: 'toggle' | 'choice' | 'range' | 'number' | 'action';
  options?: Record<string, string | number> | readonly number[];
  range?: { min: number; max: number; step: number };
  /** The parameter it binds (its URL parameter); none for a button. */
  param?: keyof DemoParams;
  /** The value shown, and a chosen value written back, where it is not the parameter's own. */
  read?: (p: DemoParams, s: PanelState) => unknown;
  write?: (p: DemoParams, s: PanelState, value: unknown) => void;
  /** A number field's value made the parameter when editing ends (before the URL follows). */
  commit?: (p: DemoParams, s: PanelState) => void;
  /** What a change invalidates (after the URL follows it); a button's action. */
  change: (demo: TessellationDemo, s: PanelState) => void;
  /** Shown only while this holds (checked after every change). */
  shown?: (p: DemoParams) => boolean;
  /** A tooltip. */
  title?: string;
}

interface Folder {
  title: string;
  /** Closed at start while this holds. */
  closed?: (p: DemoParams) => boolean;
  controls: Control[];
}

// What a change invalidates: the build (the factors it uses), only the frame, the displacement
// on the tessellators, the cage overlay's lines, or the model's placement.
const rebuild = (demo: TessellationDemo) => demo.invalidateGeometry();
const redraw = (demo: TessellationDemo) => demo.requestFrame();
const displace = (demo: TessellationDemo) => demo.applyDisplacement();

/** The error views and the comparison apply to an ACC surface, or a comparison already asked
 * for: the other surfaces' panel stays as it was. */
const accShown = (p: DemoParams) => isAcc(p.surface) || isAcc(p.compare);
const byName = <T extends string>(names: Record<T, string>, keys: readonly T[]) => Object.fromEntries(keys.map((k) => [names[k], k]));

/** The panel, folder by folder, control by control, in the order shown. */
export const PANEL: readonly Folder[] = [
  {
    title: 'Model',
    controls: [
      {
        label: 'cage',
        kind: 'choice',
        options: Object.fromEntries(BUILTIN_MODELS.map((m) => [m.label, m.name])),
        param: 'model',
        read: (_, s) => s.picked,
        write: (p, s, v) => (s.picked = p.model = v as string),
        change: (demo, s) => void demo.loadBuiltin(s.picked),
      },
      {
        label: 'up axis',
        kind: 'choice',
        options: { 'Y (OBJ convention)': 'y', Z: 'z' },
        param: 'up',
        change: (demo) => demo.placeModel(),
      },
      { label: 'open an OBJ file…', kind: 'action', change: (demo) => openFile((file) => void demo.loadFile(file)) },
    ],
  },
  {
    title: 'Tessellation',
    controls: [
      {
        label: 'surface',
        kind: 'choice',
        options: Object.fromEntries(Object.entries(SURFACE_NAMES).map(([k, v]) => [v, k])),
        param: 'surface',
        change: (demo) => void demo.controller.setSurface(demo.params.surface),
      },
      { label: 'flat baseline', kind: 'toggle', param: 'flat', change: rebuild, shown: (p) => isExact(p.surface) },
      { label: 'factors', kind: 'choice', options: { adaptive: 'adaptive', fixed: 'fixed' }, param: 'mode', change: rebuild },
      {
        label: 'LOD scale',
        kind: 'range',
        range: { ...LOD_RANGE, step: 0.05 },
        param: 'lod',
        change: rebuild,
        shown: (p) => p.mode === 'adaptive',
      },
      {
        label: 'fixed factor',
        kind: 'range',
        range: { ...FACTOR_RANGE, step: 0.25 },
        param: 'factor',
        change: rebuild,
        // The instanced tessellator alone takes its fixed level from 'level (fixed)'.
        shown: (p) => p.mode === 'fixed' && !(p.tessellator === 'instanced' && !p.split),
      },
    ],
  },
  {
    title: 'View',
    controls: [
      {
        label: 'material',
        kind: 'choice',
        options: Object.fromEntries(MATERIALS.map((m) => [m, m])),
        param: 'material',
        change: (demo) => demo.requestFrame(),
      },
      {
        label: 'patch colours',
        kind: 'toggle',
        param: 'patches',
        change: (demo) => {
          demo.updateLegend();
          demo.requestFrame();
        },
      },
      // The ACC error views (the NVIDIA sample's names), for the ACC surfaces.
      {
        label: 'error view',
        kind: 'choice',
        options: { off: 'off', 'geometry error': 'geometry', 'normal error': 'normal' },
        param: 'errorView',
        // A range typed for one unit means nothing in the other: back to the view's default.
        write: (p, _, v) => {
          p.errorView = v as DemoParams['errorView'];
          p.errRange = null;
        },
        change: (demo, s) => {
          demo.setErrorView(demo.params.errorView, null);
          s.errRange = demo.errorRange;
        },
        shown: accShown,
      },
      {
        label: 'error range',
        kind: 'number',
        param: 'errRange',
        read: (_, s) => s.errRange,
        write: (_, s, v) => (s.errRange = v as number),
        commit: (p, s) => {
          const x = s.errRange;
          p.errRange = Number.isFinite(x) && x > 0 ? Math.min(ERR_RANGE.max, Math.max(ERR_RANGE.min, x)) : null;
        },
        change: (demo, s) => {
          demo.setErrorView(demo.params.errorView, demo.params.errRange);
          s.errRange = demo.errorRange;
        },
        shown: (p) => accShown(p) && p.errorView !== 'off',
        title: 'The error drawn red: a fraction of the diagonal (geometry) or degrees (normal).',
      },
      {
        label: 'compare (right half)',
        kind: 'choice',
        options: { off: 'off', ...byName(SURFACE_NAMES, COMPARE_SURFACES) },
        param: 'compare',
        read: (p) => p.compare ?? 'off',
        write: (p, _, v) => (p.compare = v === 'off' ? null : (v as CompareSurface)),
        change: (demo) => demo.setCompare(demo.params.compare),
        shown: (p) => accShown(p) || p.compare !== null,
      },
      { label: 'wireframe', kind: 'toggle', param: 'wire', change: redraw },
      { label: 'cage overlay', kind: 'toggle', param: 'cage', change: (demo) => demo.uploadCageOverlay() },
      { label: 'turntable', kind: 'toggle', param: 'spin', change: redraw },
      { label: 'reset camera', kind: 'action', change: (demo) => demo.resetCamera() },
      { label: 'copy link to this view', kind: 'action', change: (demo) => shareLink(demo) },
    ],
  },
  // Displacement by the model's height map (the project's displaced models have one; drop or
  // open a PNG for a model with uvs).
  {
    title: 'Displacement',
    closed: (p) => p.disp && p.dscale === 1 && !p.seams,
    controls: [
      { label: 'displace', kind: 'toggle', param: 'disp', change: displace },
      { label: 'scale (× the map’s)', kind: 'range', range: { ...DSCALE_RANGE, step: 0.05 }, param: 'dscale', change: displace },
      { label: 'UV seams', kind: 'toggle', param: 'seams', change: (demo) => demo.uploadCageOverlay() },
      {
        label: 'open a PNG height map…',
        kind: 'action',
        change: (demo) => openFile((file) => void demo.loadFile(file), '.png,image/png'),
      },
    ],
  },
  // NVIDIA's instanced power-of-two tessellator beside the compute one (closed unless in use).
  {
    title: 'Instanced tessellator',
    closed: (p) => p.tessellator !== 'instanced' && !p.split,
    controls: [
      {
        label: 'tessellator',
        kind: 'choice',
        options: { 'compute (built once)': 'compute', 'instanced (per pass)': 'instanced' },
        param: 'tessellator',
        change: (demo) => demo.setTessellator(demo.params.tessellator),
      },
      { label: 'split: compute | inst.', kind: 'toggle', param: 'split', change: (demo) => demo.setSplit(demo.params.split) },
      {
        label: 'its surface',
        kind: 'choice',
        options: byName(SURFACE_NAMES, ['phong', 'catmull-clark', 'bezier-acc', 'gregory-acc', 'pm-acc']),
        param: 'instSurface',
        change: (demo) => demo.setInstancedSurface(demo.params.instSurface),
      },
      { label: 'flat shading', kind: 'toggle', param: 'flatShade', change: (demo) => demo.setInstancedFlat(demo.params.flatShade) },
      // Its static LOD (factors: fixed): one power-of-two level for every patch; adaptive factors
      // give it its dynamic LOD, scaled by the LOD scale.
      {
        label: 'level (fixed)',
        kind: 'choice',
        options: LEVEL_CHOICES,
        param: 'level',
        write: (p, _, v) => (p.level = Number(v)),
        change: rebuild,
      },
    ],
  },
];

/** Copy the link to the current view (shown instead where the clipboard refuses). */
function shareLink(demo: TessellationDemo): void {
  const url = demo.shareUrl();
  if (url === null) {
    showToast(
      `${demo.model?.title ?? 'This model'} is a file on this computer: a link cannot carry it. Links show the project's models, or an OBJ on this site (?model=path).`,
      { title: 'No link to a local file', timeout: 8000 },
    );
    return;
  }
  void navigator.clipboard?.writeText(url).then(
    () => showToast('Link to this view copied.', { timeout: 2500 }),
    () => showToast(url, { title: 'Link to this view' }),
  );
}

/** The panel of PANEL for `demo`, showing `initialModel` as picked. */
export function buildPanel(demo: TessellationDemo, initialModel: string): Panel {
  const p = demo.params;
  const state: PanelState = { picked: initialModel, errRange: demo.errorRange };
  const gui = new GUI({ title: 'Controls', width: 272 });
  gui.domElement.classList.add('panel');
  const all: { control: Control; ui: Controller }[] = [];
  const showAll = () => {
    for (const { control, ui } of all) if (control.shown) ui.show(control.shown(p));
  };
  const refresh = () => {
    for (const { ui } of all) ui.updateDisplay();
  };
  for (const folder of PANEL) {
    const f = gui.addFolder(folder.title);
    for (const control of folder.controls) {
      const ui = addControl(f, control, demo, state, () => {
        // The URL first, then what the panel shows, then what the change invalidates.
        control.commit?.(p, state);
        demo.syncUrl();
        showAll();
        control.change(demo, state);
        refresh();
      });
      if (control.title) ui.domElement.title = control.title;
      all.push({ control, ui });
    }
    if (folder.closed?.(p)) f.close();
  }
  showAll();
  if (window.matchMedia('(max-width: 640px)').matches) gui.close();
  // The model is framed left of the open panel (demo-base.ts panelCover): opening or closing it moves the picture.
  gui.onOpenClose(() => demo.requestFrame());
  return {
    gui,
    showPicked(name: string) {
      state.picked = name;
      refresh();
    },
  };
}

/** One lil-gui control for `control`, bound to its parameter (through read/write where given);
 * `changed` runs after each change the user makes. A button runs its action alone (no URL change). */
function addControl(folder: GUI, control: Control, demo: TessellationDemo, state: PanelState, changed: () => void): Controller {
  if (control.kind === 'action') return folder.add({ run: () => control.change(demo, state) }, 'run').name(control.label);
  const p = demo.params;
  const param = control.param!;
  // The value lil-gui reads and writes: the parameter itself, or its read/write.
  const bound = {
    get value(): unknown {
      return control.read ? control.read(p, state) : p[param];
    },
    set value(v: unknown) {
      if (control.write) control.write(p, state, v);
      else (p as unknown as Record<string, unknown>)[param] = v;
    },
  };
  const ui =
    control.kind === 'range'
      ? folder.add(bound, 'value', control.range!.min, control.range!.max, control.range!.step)
      : control.kind === 'choice'
        ? folder.add(bound, 'value', control.options as object)
        : folder.add(bound, 'value');
  ui.name(control.label);
  if (control.kind === 'number') ui.onFinishChange(changed);
  else ui.onChange(changed);
  return ui;
}
