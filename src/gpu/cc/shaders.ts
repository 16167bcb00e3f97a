/**
 * The Catmull-Clark shader sources with what they include: the evaluator (the region word's
 * getters, wgsl/crease-basis.wgsl for single-crease patches, wgsl/surface-cc.wgsl) and the patch
 * build (the vertex-limit word's getters, wgsl/cc-build.wgsl). `struct Params` is prepended by
 * the tessellator.
 */
import creaseBasisWgsl from '../../../wgsl/crease-basis.wgsl?raw';
import surfaceWgsl from '../../../wgsl/surface-cc.wgsl?raw';
import buildWgsl from '../../../wgsl/cc-build.wgsl?raw';
import { CC_REGION_WORD, CC_VERTEX_LIMIT_WORD } from './words.ts';

export const CC_SURFACE_WGSL = [CC_REGION_WORD.wgsl, creaseBasisWgsl, surfaceWgsl].join('\n');
export const CC_BUILD_WGSL = [CC_VERTEX_LIMIT_WORD.wgsl, buildWgsl].join('\n');
