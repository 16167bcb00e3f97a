/**
 * The compute tessellator's pipelines, built from the passes of passes.ts: one per pass, each
 * with the explicit layout of the bindings its entry point uses. A Tessellator (tessellator.ts)
 * creates them when it is made, unless it is handed a set made before for its surface (the demo
 * keeps one set per surface on its device: src/app/tess-pipelines.ts). The passes that evaluate
 * the surface are compiled when a mesh is set, with the override values that say what it has
 * (SurfaceScheme.specialise), and kept in the set per combination.
 *
 * Made with createComputePipeline, not createComputePipelineAsync: on a software GPU the exact
 * surface's passes take about 4 s to compile (SwiftShader, in Node), and compiled side by
 * side through the async call in Chromium the page's first frame came no sooner (navigation to the
 * first frame 6.3-7.6 s either way, cold) while pages that load the exact surface took about 15 %
 * longer under a test runner's load (e2e/talk-models.spec.ts and e2e/displacement.spec.ts: 63 s
 * against 54 s), the compiles contending with the page's own work on two cores.
 */
import { type PassName, passBindings, type Surface, tessellatorPasses } from './passes.ts';
import { TESS_GROUP } from '../contract/tess.ts';
import { CC_BUILD_GROUP } from '../contract/cc.ts';

/** A pass's bind group layout and its pipelines: the one with the pass's own override values,
 * and those specialised for a mesh (specialise), each made the first time it is asked for. */
export interface Pipeline {
  layout: GPUBindGroupLayout;
  /** Its bindings by name, and their numbers (from its group). */
  bindings: string[];
  binding: Readonly<Record<string, number>>;
  /** The pass's label (its pipelines' and bind groups'). */
  label: string;
  /** It evaluates the surface: run with a mesh's override values (PassSpec.specialised). */
  specialised: boolean;
  /** The pipeline with these override values over the pass's own (PassSpec.constants); made on
   * first use and kept (a set is shared by the tessellators of its surface). */
  pipeline(constants?: Readonly<Record<string, number>>): GPUComputePipeline;
}

export interface TessPipelines {
  /** The surface they evaluate (a set is only for a tessellator of that surface). */
  surface: Surface;
  pipelines: Partial<Record<PassName, Pipeline>>;
}

/**
 * Every pass of a tessellator of `surface`: its bind group layout now, and its pipeline with the
 * pass's own override values now (each compiles before the next call), except for the passes that
 * evaluate the surface (PassSpec.specialised): those are compiled once a mesh says which of the
 * surface's override values it takes (Tessellator.setMesh), so that no pipeline is made that no
 * mesh runs. Explicit layouts: each pass binds what its entry point uses, so a shared helper that
 * starts reading one more buffer changes only the layouts of the passes that call it; a
 * specialised pipeline binds with its pass's layout, so one bind group serves every variant.
 */
export function createTessPipelines(device: GPUDevice, surface: Surface): TessPipelines {
  const modules = new Map<string, GPUShaderModule>();
  const pipelines: Partial<Record<PassName, Pipeline>> = {};
  for (const pass of tessellatorPasses(surface)) {
    const module = () => {
      let m = modules.get(pass.module);
      if (!m) modules.set(pass.module, (m = device.createShaderModule({ label: `tess ${pass.module}`, code: pass.code })));
      return m;
    };
    const { names, entries } = passBindings(pass);
    const layout = device.createBindGroupLayout({ label: pass.label, entries });
    const pipelineLayout = device.createPipelineLayout({ label: pass.label, bindGroupLayouts: [layout] });
    const made = new Map<string, GPUComputePipeline>();
    const pipeline = (constants: Readonly<Record<string, number>> = {}) => {
      const all = { ...pass.constants, ...constants };
      const key = Object.keys(all)
        .sort()
        .map((k) => `${k}=${all[k]}`)
        .join(' ');
      let p = made.get(key);
      if (!p) {
        p = device.createComputePipeline({
          label: key ? `${pass.label} (${key})` : pass.label,
          layout: pipelineLayout,
          compute: { module: module(), entryPoint: pass.entry, constants: all },
        });
        made.set(key, p);
      }
      return p;
    };
    if (!pass.specialised) pipeline();
    const binding = pass.group === 'ccBuild' ? CC_BUILD_GROUP.binding : TESS_GROUP.binding;
    pipelines[pass.name] = { layout, bindings: names, binding, label: pass.label, specialised: pass.specialised ?? false, pipeline };
  }
  return { surface, pipelines };
}
