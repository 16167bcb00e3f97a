/**
 * The compute tessellator's passes as code: which WGSL each pass compiles (the generated prelude
 * of contract/contract.ts, then the files), its entry point, and the bindings that entry point uses, from
 * which its explicit bind group layout comes. pipelines.ts builds the tessellator's pipelines from this, and
 * tests/contract*.test.ts check it against the contract without building anything.
 */
import commonWgsl from '../../../wgsl/tess/common.wgsl?raw';
import outputsWgsl from '../../../wgsl/tess/outputs.wgsl?raw';
import factorsWgsl from '../../../wgsl/tess/factors.wgsl?raw';
import factorRuleWgsl from '../../../wgsl/tess/factor-rule.wgsl?raw';
import factorBulgeWgsl from '../../../wgsl/tess/factor-bulge.wgsl?raw';
import countWgsl from '../../../wgsl/tess/count.wgsl?raw';
import weldWgsl from '../../../wgsl/tess/weld.wgsl?raw';
import patternWgsl from '../../../wgsl/tess/pattern.wgsl?raw';
import planWgsl from '../../../wgsl/tess/plan.wgsl?raw';
import emitWgsl from '../../../wgsl/tess/emit.wgsl?raw';
import scanWgsl from '../../../wgsl/tess/scan.wgsl?raw';
import displaceWgsl from '../../../wgsl/tess/displace.wgsl?raw';
import { CC_BUILD_WGSL as ccBuildWgsl } from '../cc/shaders.ts';
import { type SurfaceId, surfaceScheme } from '../surface/registry.ts';
import { CC_BUILD_BINDINGS, CC_BUILD_GROUP } from '../contract/cc.ts';
import { tessPrelude } from '../contract/contract.ts';
import { scanLanesWgsl, TESS_BINDINGS, TESS_GROUP } from '../contract/tess.ts';
import { usedBindings } from '../contract/define.ts';

/** The tessellator's surfaces (src/gpu/surface/registry.ts): Phong tessellation, the exact
 * Catmull-Clark limit, or one of the three approximations of it. */
export type Surface = SurfaceId;

export type PassName =
  | 'bulge'
  | 'count'
  | 'scanReduce'
  | 'scanDown'
  | 'plan'
  | 'emitVertices'
  | 'emitTriangles'
  | 'ccPoints'
  | 'ccSlices'
  | 'ccLimits';

/** One compute pass: its shader code, its entry point, and the bind group it draws its bindings
 * from (the tessellator's, or the patch build's). */
export interface PassSpec {
  name: PassName;
  label: string;
  module: string;
  code: string;
  entry: string;
  group: 'tess' | 'ccBuild';
  /** Values of the code's override constants for this pipeline (a specialisation of the code). */
  constants?: Record<string, number>;
  /** It evaluates the surface, so its pipeline takes the override values that say what a mesh's
   * surface has (SurfaceScheme.specialise): made once a mesh is set, not with the others. */
  specialised?: boolean;
}

/** The passes of a tessellator over `surface`, with their code: what the constructor builds, and
 * what tests/gpu/contract/contract.gpu.test.ts checks against the contract. */
export function tessellatorPasses(surface: Surface): PassSpec[] {
  const scheme = surfaceScheme(surface);
  const code = (...parts: string[]) => [tessPrelude(), commonWgsl, ...parts].join('\n');
  const surfaceWgsl = scheme.tessWgsl;
  const modules = {
    // The bulge term evaluates the surface inside each triangle; the count pass computes each
    // triangle's edge factors (the edge term reads the bulge) and counts its pattern.
    factors: code(surfaceWgsl, factorRuleWgsl, factorBulgeWgsl, factorsWgsl, patternWgsl, countWgsl),
    // The prefix sums, the budget's choice made in the second of them (which lanes are what: TESS_SCANS).
    scan: code(scanLanesWgsl(), scanWgsl),
    plan: code(patternWgsl, planWgsl),
    // The surface, then the displacement over it (surfaceAt), then what writes the vertices, where
    // the welded ones lie, and the whole output.
    emit: code(surfaceWgsl, displaceWgsl, outputsWgsl, patternWgsl, weldWgsl, emitWgsl),
    // The patch build's own prelude (contract/contract.ts ccBuildPrelude: CC_BUILD_GROUP) comes with it.
    ccBuild: ccBuildWgsl,
  };
  type Module = keyof typeof modules;
  const pass = (name: PassName, label: string, module: Module, entry = 'main', more: Partial<PassSpec> = {}): PassSpec => ({
    name,
    label,
    module,
    code: modules[module],
    entry,
    group: module === 'ccBuild' ? 'ccBuild' : 'tess',
    ...more,
  });
  const passes = [
    pass('bulge', 'tess bulge', 'factors', 'bulge', { specialised: true }),
    pass('count', 'tess factors + count', 'factors', 'main', { specialised: true }),
    pass('scanReduce', 'tess scan reduce', 'scan', 'scanReduce'),
    pass('scanDown', 'tess budget + scan down', 'scan', 'scanDown'),
    pass('plan', 'tess plan', 'plan'),
    // The vertices, with the displacement compiled out unless a mesh has it on (wgsl/tess/outputs.wgsl DISPLACED).
    pass('emitVertices', 'tess emit vertices', 'emit', 'vertices', { constants: { DISPLACED: 0 }, specialised: true }),
    pass('emitTriangles', 'tess emit triangles', 'emit', 'triangles'),
  ];
  // The Catmull-Clark patch build is the tessellator's own (into its work arena); AccPatches
  // builds the ACC patches itself, and Phong reads the cage.
  if (scheme.patchBuild === 'refinement') {
    passes.push(
      pass('ccPoints', 'cc level points', 'ccBuild', 'points'),
      pass('ccSlices', 'cc ev slices', 'ccBuild', 'slices'),
      pass('ccLimits', 'cc fan and vertex limits', 'ccBuild', 'limits'),
    );
  }
  return passes;
}

/** The bindings a pass's entry point uses, from its group: its bind group layout, entry for entry. */
export function passBindings(pass: PassSpec): { names: string[]; entries: GPUBindGroupLayoutEntry[] } {
  if (pass.group === 'ccBuild') {
    const names = usedBindings(pass.code, pass.entry, CC_BUILD_BINDINGS);
    return { names, entries: CC_BUILD_GROUP.layoutEntries(names) };
  }
  const names = usedBindings(pass.code, pass.entry, TESS_BINDINGS);
  return { names, entries: TESS_GROUP.layoutEntries(names) };
}
