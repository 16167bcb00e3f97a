/**
 * The compute tessellator's pipelines, built from the passes of passes.ts: one per pass, each
 * with the explicit layout of the bindings its entry point uses. Tessellator (tessellator.ts)
 * creates them once.
 */
import { type PassName, passBindings, type Surface, tessellatorPasses } from './passes.ts';
import { TESS_GROUP } from '../contract/tess.ts';
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
  return { pipelines };
}
