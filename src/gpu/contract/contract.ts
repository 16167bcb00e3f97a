/**
 * What the TypeScript and the WGSL must agree on, declared once. Each declaration gives both
 * sides: the WGSL text that is prepended to the shaders, and the TypeScript that writes or reads
 * the same bytes. Nothing here is counted by hand twice. This folder holds:
 *
 *   define.ts      the mechanism: packed words (defineBits), bind groups (defineBindGroup,
 *                  usedBindings), arrays carved out of one storage buffer (defineArena), WGSL
 *                  `const` and f32 literals
 *   layout.ts      uniform structs (defineStruct): the WGSL struct and its byte offsets
 *   constants.ts   shared numbers (workgroup sizes, the dispatch grid's width), as TypeScript
 *                  values and as a WGSL `const` prelude (constantsWgsl)
 *   tess.ts        the compute tessellator's: its buffers as arenas (TESS_STATIC, TESS_CAGE,
 *                  TESS_WORK), its uniforms (TESS_PARAMS), its bind group (TESS_GROUP), the budget's
 *                  candidate scales, the packed words its shaders read, its constants
 *   cc.ts          the Catmull-Clark patch build's bind group and level range, and the sections
 *                  of its words (CC_STATIC, whose offsets are Params' cc* fields)
 *   acc.ts         the ACC patch build's: its static words as an arena (ACC_STATIC), its uniforms
 *                  (ACC_BUILD_PARAMS), its bind group (ACC_BUILD_GROUP), its sector word
 *   render.ts      the renderer's uniforms (SCENE_UNIFORMS), bind group layouts and which pipeline
 *                  uses which (RENDER_BIND_GROUPS, RENDER_PIPELINE_GROUPS), the patch colours
 *   tessellated-mesh.ts  the tessellator's output, as everything that draws or reads it sees it
 *   contract.ts    (this file) the preludes: what each family of shaders starts with, assembled
 *                  from the declarations above
 *
 * The Catmull-Clark words of src/gpu/cc/build.ts are declared with defineBits too, in
 * src/gpu/cc/words.ts, and their WGSL getters are generated from there like the tessellator's.
 *
 * tests/gpu/contract/contract.test.ts parses the generated WGSL back and checks it against the TypeScript
 * views; tests/gpu/contract/contract.gpu.test.ts runs it through a real WGSL compiler.
 */
import {
  KIND_BEZIER,
  KIND_GREGORY_QUAD,
  KIND_GREGORY_TRI,
  KIND_PM_QUAD,
  KIND_PM_TRI,
  KIND_PM_TRI_LS,
  KIND_REGULAR,
  SECTOR_CONE,
  SECTOR_CORNER,
  SECTOR_CREASE,
  TRI_FACE,
} from '../../subdiv/acc.ts';
import { ACC_BUILD_GROUP, ACC_BUILD_PARAMS, ACC_SECTOR_WORD } from './acc.ts';
import { CC_BUILD_GROUP, CC_NONE, CC_RANGE } from './cc.ts';
import { constantsWgsl, PHONG_ALPHA } from './constants.ts';
import { wgslConstants, wgslF32 } from './define.ts';
import { GROUND_EXTENT, PATCH_COLOURS, SCENE_GROUP, SCENE_UNIFORMS } from './render.ts';
import {
  ACC_TRI_CORNERS,
  ACC_TRI_WORD,
  BARY_WORD,
  DISP_TRI_WORD,
  OWNER_WORD,
  PATTERN_FRAME_WORD,
  BUDGET_SCALES,
  TESS_BINDINGS,
  TESS_CONSTANTS,
  TESS_GROUP,
  TESS_PARAMS,
  type TessBinding,
  tableHeaderWgsl,
} from './tess.ts';

/** What wgsl/cc/build.wgsl starts with (then the packed words' getters, src/gpu/cc/shaders.ts). */
export function ccBuildPrelude(): string {
  return [TESS_PARAMS.wgsl, constantsWgsl, wgslConstants({ CC_NONE }), CC_RANGE.wgsl, CC_BUILD_GROUP.wgsl()].join('\n');
}

/** What wgsl/acc/build.wgsl starts with: its uniforms, the constants, its bindings, the sector word. */
export function accBuildPrelude(): string {
  // The patch kinds, the sector kinds and the ring's triangle marker, as the CPU's ACC writes them.
  const acc = { TRI_FACE, KIND_REGULAR, KIND_BEZIER, KIND_GREGORY_QUAD, KIND_GREGORY_TRI, KIND_PM_QUAD, KIND_PM_TRI, KIND_PM_TRI_LS };
  const sectors = { SECTOR_CREASE, SECTOR_CORNER, SECTOR_CONE };
  return [ACC_BUILD_PARAMS.wgsl, constantsWgsl, wgslConstants({ ...acc, ...sectors }), ACC_BUILD_GROUP.wgsl(), ACC_SECTOR_WORD.wgsl].join(
    '\n',
  );
}

/** What every tessellator shader starts with: Params, the constants, the bindings `names` (all by
 * default), the packed words' getters and the table header's. */
export function tessPrelude(names: readonly TessBinding[] = TESS_BINDINGS): string {
  return [
    TESS_PARAMS.wgsl,
    constantsWgsl,
    wgslConstants(TESS_CONSTANTS),
    `const PHONG_ALPHA: f32 = ${wgslF32(PHONG_ALPHA)};`,
    `const BUDGET_SCALES = array<f32, ${BUDGET_SCALES.length}>(${BUDGET_SCALES.map(wgslF32).join(', ')});`,
    TESS_GROUP.wgsl(names),
    PATTERN_FRAME_WORD.wgsl,
    BARY_WORD.wgsl,
    OWNER_WORD.wgsl,
    ACC_TRI_WORD.wgsl,
    ACC_TRI_CORNERS.wgsl,
    DISP_TRI_WORD.wgsl,
    tableHeaderWgsl('staticBuf', 'params'),
  ].join('\n');
}

/** What every render shader starts with: the per-frame uniforms (the struct and its binding,
 * group 0 everywhere) and the constants the TypeScript shares with the render shaders. */
export const sceneWgsl = scenePrelude(SCENE_GROUP);

/** sceneWgsl with the scene uniform bound where `sceneGroup` says (SCENE_GROUP.moved). */
export function scenePrelude(sceneGroup: typeof SCENE_GROUP): string {
  return [
    SCENE_UNIFORMS.wgsl,
    sceneGroup.wgsl(),
    `const GROUND_EXTENT: f32 = ${wgslF32(GROUND_EXTENT)};`,
    `const PATCH_SRGB = array<vec3f, ${PATCH_COLOURS.length}>(${PATCH_COLOURS.map((p) => `vec3f(${p.srgb.map(wgslF32).join(', ')})`).join(', ')});`,
    '',
  ].join('\n');
}
