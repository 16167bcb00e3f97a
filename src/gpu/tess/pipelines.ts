/**
 * The compute tessellator's pipelines, built from the passes of passes.ts: one per pass, each
 * with the explicit layout of the bindings its entry point uses, and the prefix sum's three steps
 * over one shared layout. Tessellator (tessellator.ts) creates them once.
 */
import { type PassName, passBindings, SCAN_ENTRIES, scanCode, type Surface, tessellatorPasses } from './passes.ts';
import { SCAN_GROUP, TESS_GROUP } from '../contract/tess.ts';
import { CC_BUILD_GROUP } from '../contract/cc.ts';

/** A pass's pipeline and bind group layout. */
export interface Pipeline {
  pipeline: GPUComputePipeline;
  layout: GPUBindGroupLayout;
  /** Its bindings by name, and their numbers (from its group). */
  bindings: string[];
  binding: Readonly<Record<string, number>>;
}

export interface TessPipelines {
  pipelines: Partial<Record<PassName, Pipeline>>;
  scanPipelines: Record<keyof typeof SCAN_ENTRIES, GPUComputePipeline>;
  /** The scan steps' one layout: the whole SCAN_GROUP. */
  scanLayout: GPUBindGroupLayout;
}

/** Every pipeline of a tessellator of `surface`. */
export function createTessPipelines(device: GPUDevice, surface: Surface): TessPipelines {
  const pipelines: Partial<Record<PassName, Pipeline>> = {};
  // Explicit layouts: each pass binds what its entry point uses, so a shared helper that starts
  // reading one more buffer changes only the layouts of the passes that call it.
  const modules = new Map<string, GPUShaderModule>();
  for (const pass of tessellatorPasses(surface)) {
    let module = modules.get(pass.module);
    if (!module) modules.set(pass.module, (module = device.createShaderModule({ label: `tess ${pass.module}`, code: pass.code })));
    const { names, entries } = passBindings(pass);
    const layout = device.createBindGroupLayout({ label: pass.label, entries });
    const pipeline = device.createComputePipeline({
      label: pass.label,
      layout: device.createPipelineLayout({ label: pass.label, bindGroupLayouts: [layout] }),
      compute: { module, entryPoint: pass.entry },
    });
    const binding = pass.group === 'ccBuild' ? CC_BUILD_GROUP.binding : TESS_GROUP.binding;
    pipelines[pass.name] = { pipeline, layout, bindings: names, binding };
  }
  // The three scan steps share one bind group, so they share one layout: the whole SCAN_GROUP.
  const scanLayout = device.createBindGroupLayout({ label: 'scan', entries: SCAN_GROUP.layoutEntries() });
  const scanModule = device.createShaderModule({ label: 'scan', code: scanCode });
  const scanPipelineLayout = device.createPipelineLayout({ label: 'scan', bindGroupLayouts: [scanLayout] });
  const scanPipeline = (step: keyof typeof SCAN_ENTRIES) =>
    device.createComputePipeline({
      label: `scan ${step}`,
      layout: scanPipelineLayout,
      compute: { module: scanModule, entryPoint: SCAN_ENTRIES[step] },
    });
  const scanPipelines = { blocks: scanPipeline('blocks'), sums: scanPipeline('sums'), add: scanPipeline('add') };
  return { pipelines, scanPipelines, scanLayout };
}
