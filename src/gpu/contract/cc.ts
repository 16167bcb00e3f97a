/**
 * The Catmull-Clark patch build's side of the contract (src/gpu/cc/build.ts, wgsl/cc/build.wgsl):
 * its bind group, the point range of a level dispatch, the sections of its words (CC_STATIC) and
 * the sentinel of its words. The words
 * themselves are declared in src/gpu/cc/words.ts; what its shader starts with is assembled in
 * contract.ts (ccBuildPrelude).
 */
import { defineArena, defineBindGroup } from './define.ts';
import { defineStruct } from './layout.ts';

/** The point range of one level dispatch of the patch build (face points, or edge and vertex points). */
export const CC_RANGE = defineStruct('Range', [
  ['first', 'u32', 'Global index of the range’s first point.'],
  ['count', 'u32'],
  ['faceFirst', 'u32', 'The level’s face points: from here to the end of the range (its edge and vertex points come first).'],
] as const);

/**
 * The patch build's group (wgsl/cc/build.wgsl): it reads the static words, writes cageBuf, and its
 * level dispatches take their point range in `range`.
 */
export const CC_BUILD_GROUP = defineBindGroup(0, {
  params: { binding: 0, space: 'uniform', type: 'Params' },
  staticBuf: { binding: 1, space: 'read', type: 'array<u32>' },
  cageBuf: { binding: 2, space: 'read_write', type: 'array<f32>' },
  range: { binding: 3, space: 'uniform', type: 'Range' },
});
export type CcBuildBinding = keyof typeof CC_BUILD_GROUP.binding;
export const CC_BUILD_BINDINGS = Object.keys(CC_BUILD_GROUP.binding) as CcBuildBinding[];
/** Sentinel of the Catmull-Clark words: no fan, no region, an idle slice thread. */
export const CC_NONE = 0xffffffff;

/** The sections of the Catmull-Clark words (src/gpu/cc/build.ts has what each holds). */
export type CcSection = 'tri' | 'poly' | 'regions' | 'patchIdx' | 'fans' | 'sectors' | 'threads' | 'cos' | 'rules' | 'inputs' | 'vertexFan';

/**
 * The Catmull-Clark words (the `cc` array of TESS_STATIC), section after section, each as long as
 * the array build.ts packs into it. Its offsets reach the shaders as the Params fields `ccTri`,
 * `ccPoly`, … (TESS_PARAMS spreads `offsetFields`), each plus where `cc` starts in staticBuf.
 */
export const CC_STATIC = defineArena<CcSection, Readonly<Record<CcSection, number>>, 'cc'>(
  [
    ['tri', (s) => s.tri],
    ['poly', (s) => s.poly],
    ['regions', (s) => s.regions],
    ['patchIdx', (s) => s.patchIdx],
    ['fans', (s) => s.fans],
    ['sectors', (s) => s.sectors],
    ['threads', (s) => s.threads],
    ['cos', (s) => s.cos],
    ['rules', (s) => s.rules],
    ['inputs', (s) => s.inputs],
    ['vertexFan', (s) => s.vertexFan],
  ],
  'cc',
);
/** CC_STATIC's sizes without the Catmull-Clark surface: every section empty (all offsets 0). */
export const CC_NO_WORDS = Object.fromEntries(CC_STATIC.names.map((k) => [k, 0])) as Record<CcSection, number>;
