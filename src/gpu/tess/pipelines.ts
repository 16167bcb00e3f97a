/**
 * The compute tessellator's pipelines, built from the passes of passes.ts: one per pass, each
 * with the explicit layout of the bindings its entry point uses. A Tessellator (tessellator.ts)
 * creates them when it is made, unless it is handed a set made before for its surface (the demo
 * keeps one set per surface on its device: src/app/tess-pipelines.ts).
 *
 * Made with createComputePipeline, not createComputePipelineAsync: on a software GPU the exact
 * surface's eleven passes take about 4 s to compile (SwiftShader, in Node), and compiled side by
 * side through the async call in Chromium the page's first frame came no sooner (navigation to the
 * first frame 6.3-7.6 s either way, cold) while pages that load the exact surface took about 15 %
 * longer under a test runner's load (e2e/talk-models.spec.ts and e2e/displacement.spec.ts: 63 s
 * against 54 s), the compiles contending with the page's own work on two cores.
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
  /** The surface they evaluate (a set is only for a tessellator of that surface). */
  surface: Surface;
  pipelines: Partial<Record<PassName, Pipeline>>;
}

/** Every pass of a tessellator of `surface` but the variants (passes.ts variantOf, made on
 * demand by variantPipeline): its pipeline's descriptor and the rest of its Pipeline. */
function passDescriptors(device: GPUDevice, surface: Surface) {
  // Explicit layouts: each pass binds what its entry point uses, so a shared helper that starts
  // reading one more buffer changes only the layouts of the passes that call it.
  const modules = new Map<string, GPUShaderModule>();
  return tessellatorPasses(surface)
    .filter((pass) => !pass.variantOf)
    .map((pass) => {
      let module = modules.get(pass.module);
      if (!module) modules.set(pass.module, (module = device.createShaderModule({ label: `tess ${pass.module}`, code: pass.code })));
      const { names, entries } = passBindings(pass);
      const layout = device.createBindGroupLayout({ label: pass.label, entries });
      const descriptor: GPUComputePipelineDescriptor = {
        label: pass.label,
        layout: device.createPipelineLayout({ label: pass.label, bindGroupLayouts: [layout] }),
        compute: { module, entryPoint: pass.entry, constants: pass.constants },
      };
      const binding = pass.group === 'ccBuild' ? CC_BUILD_GROUP.binding : TESS_GROUP.binding;
      return { name: pass.name, descriptor, layout, bindings: names, binding };
    });
}

/** Every pipeline of a tessellator of `surface` but the variants (passes.ts variantOf), made now
 * (each compiles before the next call). */
export function createTessPipelines(device: GPUDevice, surface: Surface): TessPipelines {
  const pipelines: Partial<Record<PassName, Pipeline>> = {};
  for (const p of passDescriptors(device, surface))
    pipelines[p.name] = {
      pipeline: device.createComputePipeline(p.descriptor),
      layout: p.layout,
      bindings: p.bindings,
      binding: p.binding,
    };
  return { surface, pipelines };
}

/** The pipeline of variant `name` of a set (passes.ts variantOf), made and kept in the set the
 * first time it is asked for (a set is shared by the tessellators of its surface). It binds with
 * the layout of the pass it is a variant of, so that pass's bind groups serve it. */
export function variantPipeline(device: GPUDevice, set: TessPipelines, name: PassName): Pipeline {
  const made = set.pipelines[name];
  if (made) return made;
  // Only this pass's module and pipeline are made (not every pass's descriptor).
  const pass = tessellatorPasses(set.surface).find((p) => p.name === name);
  const base = pass?.variantOf && set.pipelines[pass.variantOf];
  if (!pass || !base) throw new Error(`${name} is not a variant of a pass of the ${set.surface} tessellator`);
  const pipeline = device.createComputePipeline({
    label: pass.label,
    layout: device.createPipelineLayout({ label: pass.label, bindGroupLayouts: [base.layout] }),
    compute: {
      module: device.createShaderModule({ label: `tess ${pass.module} (${pass.name})`, code: pass.code }),
      entryPoint: pass.entry,
      constants: pass.constants,
    },
  });
  return (set.pipelines[name] = { ...base, pipeline });
}
