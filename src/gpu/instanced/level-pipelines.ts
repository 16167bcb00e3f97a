/**
 * The instanced tessellator's level passes (wgsl/instanced/levels.wgsl), each on an explicit
 * layout of what its entry point reads (usedBindings): group 0 (INST_LEVELS_GROUP) and, for a pass
 * that evaluates the surface, group 3 (INST_SURFACE_GROUP). InstancedLevels (levels.ts) makes them.
 */
import { usedBindings } from '../contract/define.ts';
import { INST_LEVELS_GROUP, INST_SURFACE_GROUP, type InstSurfaceBinding } from './buffer-layouts.ts';

export type LevelPass = 'patchEdges' | 'edgeView' | 'edgeFactorRule' | 'bucketPatches' | 'records';

/** A level pass's pipeline, its group 0 layout and bindings, and group 3's where it reads the surface. */
export interface LevelPipeline {
  pipeline: GPUComputePipeline;
  layout: GPUBindGroupLayout;
  used: (keyof typeof INST_LEVELS_GROUP.binding)[];
  surfaceLayout?: GPUBindGroupLayout;
  usedSurface: InstSurfaceBinding[];
}

/** Every level pass of the module `levelsCode`, over a surface group holding `surfaceNames`. */
export function createLevelPipelines(
  device: GPUDevice,
  levelsCode: string,
  surfaceNames: readonly InstSurfaceBinding[],
): Record<LevelPass, LevelPipeline> {
  const levels = device.createShaderModule({ label: 'instanced levels', code: levelsCode });
  const levelNames = Object.keys(INST_LEVELS_GROUP.binding) as (keyof typeof INST_LEVELS_GROUP.binding)[];
  const noBindings = device.createBindGroupLayout({ label: 'instanced (no bindings)', entries: [] });
  const pipeline = (entryPoint: LevelPass): LevelPipeline => {
    const used = usedBindings(levelsCode, entryPoint, levelNames);
    const usedSurface = usedBindings(levelsCode, entryPoint, surfaceNames);
    const label = `instanced ${entryPoint}`;
    const layout = device.createBindGroupLayout({ label, entries: INST_LEVELS_GROUP.layoutEntries(used) });
    const surfaceLayout = usedSurface.length
      ? device.createBindGroupLayout({ label: `${label} surface`, entries: INST_SURFACE_GROUP.layoutEntries(usedSurface) })
      : undefined;
    const groups = surfaceLayout ? [layout, noBindings, noBindings, surfaceLayout] : [layout];
    return {
      pipeline: device.createComputePipeline({
        label,
        layout: device.createPipelineLayout({ label, bindGroupLayouts: groups }),
        compute: { module: levels, entryPoint },
      }),
      layout,
      used,
      surfaceLayout,
      usedSurface,
    };
  };
  return {
    patchEdges: pipeline('patchEdges'),
    edgeView: pipeline('edgeView'),
    edgeFactorRule: pipeline('edgeFactorRule'),
    bucketPatches: pipeline('bucketPatches'),
    records: pipeline('records'),
  };
}
