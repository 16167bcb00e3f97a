/**
 * The demo's control panel (lil-gui): the model, the tessellation, the view, the displacement and
 * the instanced tessellator. Each control writes its parameter, keeps the URL in step (syncUrl)
 * and tells the demo what the change invalidates (src/app/tessellation-demo.ts).
 */
import GUI from 'lil-gui';
import { BUILTIN_MODELS } from './models.ts';
import {
  COMPARE_SURFACES,
  DSCALE_RANGE,
  ERR_RANGE,
  FACTOR_RANGE,
  formatParams,
  LEVEL_CHOICES,
  LOD_RANGE,
  type CompareSurface,
  type DemoParams,
} from './params.ts';
import { isAcc, SURFACE_NAMES } from './surfaces.ts';
import { openFile } from './file-input.ts';
import { showToast } from './ui.ts';
import type { PickerDisplay } from './demo-scene.ts';
import type { TessellationDemo } from './tessellation-demo.ts';

function syncUrl(params: DemoParams): void {
  // Camera angles in the URL describe the first view only: drop them once the user changes anything.
  const p: DemoParams = { ...params, yaw: null, pitch: null, dist: null };
  history.replaceState(null, '', `${location.pathname}${formatParams(p)}`);
}

export interface Panel extends PickerDisplay {
  gui: GUI;
}

export function buildPanel(demo: TessellationDemo, initialModel: string): Panel {
  const p = demo.params;
  const gui = new GUI({ title: 'Controls', width: 272 });
  gui.domElement.classList.add('panel');
  const state = {
    model: initialModel,
    open: () => openFile((file) => void demo.loadFile(file)),
    openHeight: () => openFile((file) => void demo.loadFile(file), '.png,image/png'),
    reset: () => demo.resetCamera(),
    share: () => {
      const url = demo.shareUrl();
      void navigator.clipboard?.writeText(url).then(
        () => showToast('Link to this view copied.', { timeout: 2500 }),
        () => showToast(url, { title: 'Link to this view' }),
      );
    },
  };
  const options = Object.fromEntries(BUILTIN_MODELS.map((m) => [m.label, m.name]));
  const modelFolder = gui.addFolder('Model');
  const picker = modelFolder
    .add(state, 'model', options)
    .name('cage')
    .onChange((name: string) => {
      p.model = name;
      syncUrl(p);
      void demo.loadBuiltin(name);
    });
  modelFolder
    .add(p, 'up', { 'Z (project models)': 'z', Y: 'y' })
    .name('up axis')
    .onChange(() => {
      syncUrl(p);
      demo.placeModel();
    });
  modelFolder.add(state, 'open').name('open an OBJ file…');

  const tess = gui.addFolder('Tessellation');
  const changed = () => {
    syncUrl(p);
    demo.invalidateGeometry();
  };
  tess
    .add(p, 'surface', Object.fromEntries(Object.entries(SURFACE_NAMES).map(([k, v]) => [v, k])))
    .name('surface')
    .onChange(() => {
      syncUrl(p);
      showFlat();
      showErrors();
      void demo.controller.setSurface(p.surface);
    });
  const flat = tess.add(p, 'flat').name('flat baseline').onChange(changed);
  const showFlat = () => flat.show(p.surface === 'catmull-clark');
  showFlat();
  tess
    .add(p, 'mode', { adaptive: 'adaptive', fixed: 'fixed' })
    .name('factors')
    .onChange(() => {
      showMode();
      changed();
    });
  const lod = tess.add(p, 'lod', LOD_RANGE.min, LOD_RANGE.max, 0.05).name('LOD scale').onChange(changed);
  const factor = tess.add(p, 'factor', FACTOR_RANGE.min, FACTOR_RANGE.max, 0.25).name('fixed factor').onChange(changed);
  const showMode = () => {
    const instancedOnly = p.tessellator === 'instanced' && !p.split;
    lod.show(p.mode === 'adaptive');
    factor.show(p.mode === 'fixed' && !instancedOnly);
  };
  showMode();

  const view = gui.addFolder('View');
  const redraw = () => {
    syncUrl(p);
    demo.requestFrame();
  };
  view
    .add(p, 'patches')
    .name('patch colours')
    .onChange(() => {
      demo.updateLegend();
      redraw();
    });
  // The ACC error views (the NVIDIA sample's names), for the ACC surfaces.
  const errState = { range: demo.errorRange };
  const errView = view
    .add(p, 'errorView', { off: 'off', 'geometry error': 'geometry', 'normal error': 'normal' })
    .name('error view')
    .onChange((v: DemoParams['errorView']) => {
      // A range typed for one unit means nothing in the other: back to the view's default.
      p.errRange = null;
      errState.range = demo.errorRange;
      errRange.updateDisplay();
      showErrors();
      syncUrl(p);
      demo.setErrorView(v, null);
    });
  const errRange = view
    .add(errState, 'range')
    .name('error range')
    .onFinishChange((v: number) => {
      const range = Number.isFinite(v) && v > 0 ? Math.min(ERR_RANGE.max, Math.max(ERR_RANGE.min, v)) : null;
      errState.range = range ?? demo.errorRange;
      errRange.updateDisplay();
      syncUrl({ ...p, errRange: range });
      demo.setErrorView(p.errorView, range);
    });
  errRange.domElement.title = 'The error drawn red: a fraction of the diagonal (geometry) or degrees (normal).';
  // Shown where they apply (an ACC surface, or a comparison already asked for): the other
  // surfaces' panel stays as it was.
  const showErrors = () => {
    const acc = isAcc(p.surface) || isAcc(p.compare);
    errView.show(acc);
    errRange.show(acc && p.errorView !== 'off');
    compare.show(acc || p.compare !== null);
  };
  const compareState = { compare: p.compare ?? 'off' };
  const compare = view
    .add(compareState, 'compare', { off: 'off', ...Object.fromEntries(COMPARE_SURFACES.map((c) => [SURFACE_NAMES[c], c])) })
    .name('compare (right half)')
    .onChange((v: string) => {
      const c = v === 'off' ? null : (v as CompareSurface);
      p.compare = c;
      syncUrl(p);
      showErrors();
      demo.setCompare(c);
    });
  showErrors();
  view.add(p, 'wire').name('wireframe').onChange(redraw);
  view.add(p, 'cage').name('cage overlay').onChange(redraw);
  view.add(p, 'spin').name('turntable').onChange(redraw);
  // Displacement by the model's height map (the project's displaced models have one; drop or
  // open a PNG for a model with uvs).
  const disp = gui.addFolder('Displacement');
  const displaced = () => {
    syncUrl(p);
    demo.applyDisplacement();
  };
  disp.add(p, 'disp').name('displace').onChange(displaced);
  disp.add(p, 'dscale', DSCALE_RANGE.min, DSCALE_RANGE.max, 0.05).name('scale (× the map’s)').onChange(displaced);
  disp
    .add(p, 'seams')
    .name('UV seams')
    .onChange(() => {
      syncUrl(p);
      demo.uploadCageOverlay();
    });
  disp.add(state, 'openHeight').name('open a PNG height map…');
  if (p.disp && p.dscale === 1 && !p.seams) disp.close();
  view.add(state, 'reset').name('reset camera');
  view.add(state, 'share').name('copy link to this view');
  // NVIDIA's instanced power-of-two tessellator beside the compute one (closed unless in use).
  const inst = gui.addFolder('Instanced tessellator');
  inst
    .add(p, 'tessellator', { 'compute (built once)': 'compute', 'instanced (per pass)': 'instanced' })
    .name('tessellator')
    .onChange((kind: DemoParams['tessellator']) => {
      syncUrl(p);
      showMode();
      demo.setTessellator(kind);
    });
  inst
    .add(p, 'split')
    .name('split: compute | inst.')
    .onChange((split: boolean) => {
      syncUrl(p);
      showMode();
      demo.setSplit(split);
    });
  inst
    .add(p, 'instSurface', {
      Phong: 'phong',
      'Catmull-Clark': 'catmull-clark',
      'Bezier ACC': 'bezier-acc',
      'Gregory ACC': 'gregory-acc',
      'Pm ACC': 'pm-acc',
    })
    .name('its surface')
    .onChange((v: DemoParams['instSurface']) => {
      syncUrl(p);
      demo.setInstancedSurface(v);
    });
  inst
    .add(p, 'flatShade')
    .name('flat shading')
    .onChange((v: boolean) => {
      syncUrl(p);
      demo.setInstancedFlat(v);
    });
  // Its static LOD (factors: fixed): one power-of-two level for every patch; adaptive factors
  // give it its dynamic LOD, scaled by the LOD scale.
  inst
    .add(p, 'level', [...LEVEL_CHOICES])
    .name('level (fixed)')
    .onChange((v: number | string) => {
      p.level = Number(v);
      changed();
    });
  if (p.tessellator !== 'instanced' && !p.split) inst.close();
  if (window.matchMedia('(max-width: 640px)').matches) gui.close();
  return {
    gui,
    showPicked(name: string) {
      state.model = name;
      picker.updateDisplay();
    },
  };
}
