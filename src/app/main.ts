/**
 * The demo page's entry: reads the URL's parameters, finds the canvas, starts the demo on the GPU
 * (DemoBase.start shows the message when WebGPU is missing or refuses), then adds the panel and
 * file dropping and loads the first model. The demo itself: src/app/tessellation-demo.ts.
 */
import { enableDrop } from './file-input.ts';
import { DEFAULT_MODEL } from './models.ts';
import { buildPanel } from './panel.ts';
import { modelSource } from './model-source.ts';
import { paramNotes, parseParams } from './params.ts';
import { showToast } from './ui.ts';
import { TessellationDemo } from './tessellation-demo.ts';

async function main(): Promise<void> {
  const params = parseParams(location.search);
  document.body.classList.toggle('no-ui', !params.ui);
  const canvas = document.getElementById('view') as HTMLCanvasElement;
  const demo = new TessellationDemo(canvas, params);
  // Debug and test hook: the live demo, and a way to simulate a device loss.
  (window as unknown as { tessellab: unknown }).tessellab = {
    demo,
    loseDevice: () => demo.gpu.device.destroy(),
    /** Hold back (true) or hand over (false) models' surface data: the page shows what it draws meanwhile. */
    holdPreparation: (hold: boolean) => demo.holdPreparation(hold),
    /** The bytes (and counts) of the page's live GPU buffers and textures, and per label. */
    gpuMemory: () => ({ ...demo.memory.counts, byLabel: demo.memory.byLabel() }),
    /** Where the shown model's +Y points in the world (up on screen when it is [0, 1, 0]). */
    modelUp: () => demo.modelUp(),
    /** The instanced tessellator's bucket draw records (GPU) and the CPU's count (static mode). */
    instancedRecords: () => demo.instancedRecords(),
  };
  // Test hook: hold the first model's surface data from the start (e2e/loading.spec.ts).
  if ((window as { tessellabHoldPreparation?: boolean }).tessellabHoldPreparation) demo.holdPreparation(true);
  if (!(await demo.start())) return;

  // The URL's numbers the page changed (clamped, rounded, defaulted): said, not done silently.
  const notes = paramNotes(location.search);
  if (notes.length) showToast(notes.join('\n'), { title: 'Link parameters adjusted', timeout: 10000 });
  const source = modelSource(params.model ?? DEFAULT_MODEL, location.href);
  demo.panel = params.ui ? buildPanel(demo, source.kind === 'builtin' ? source.name : DEFAULT_MODEL) : null;
  enableDrop((file) => void demo.loadFile(file));

  const camera = { yaw: params.yaw, pitch: params.pitch, dist: params.dist, up: params.up };
  if (source.kind === 'url') {
    await demo.loadUrl(source.url, camera);
  } else if (source.kind === 'refused') {
    // Said instead of fetched; the default model is shown meanwhile.
    showToast(source.reason, { kind: 'error', title: 'Model link not loaded' });
    await demo.loadBuiltin(DEFAULT_MODEL, camera);
  } else if (!(await demo.loadBuiltin(source.name, camera)) && source.name !== DEFAULT_MODEL && !demo.model) {
    await demo.loadBuiltin(DEFAULT_MODEL, camera);
  }
}

void main();
