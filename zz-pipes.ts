import { createNodeDevice } from './src/gpu/device/node-device.ts';
import { Renderer } from './src/gpu/render/renderer.ts';
import { createTessPipelines } from './src/gpu/tess/pipelines.ts';
const { device } = await createNodeDevice();
const t = (label: string, f: () => unknown) => {
  const t0 = performance.now();
  f();
  return device.queue.onSubmittedWorkDone().then(() => console.log(label, (performance.now() - t0).toFixed(0), 'ms'));
};
await t('renderer (all render pipelines)', () => Renderer.create(device, { colorFormat: 'rgba8unorm', timestamps: false }));
for (const s of ['catmull-clark', 'phong', 'gregory-acc'] as const) await t(`tess pipelines ${s}`, () => createTessPipelines(device, s));
const rp = await import('./src/gpu/render/pipelines.ts');
for (let i = 0; i < 1; i++) await t('render pipelines again', () => rp.createRenderPipelines(device, 'rgba8unorm', 4, true));
process.exit(0);
