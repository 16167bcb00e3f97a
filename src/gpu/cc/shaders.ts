/**
 * The Catmull-Clark shader sources with what they include. The evaluator: the packed words'
 * getters (words.ts), wgsl/cc/crease-basis.wgsl for single-crease patches, wgsl/cc/slices.wgsl
 * (the fans' slices, shared with the build: read, and an odd fan's even steps made again),
 * wgsl/cc/surface.wgsl (after the tessellator's prelude). The patch build: its own prelude (Params, the shared
 * constants, CC_BUILD_GROUP's bindings and the level range struct: contract/contract.ts
 * ccBuildPrelude), the wide-fan mark of the slice kernel's thread words, the getters, wgsl/cc/slices.wgsl,
 * wgsl/cc/build.wgsl.
 */
import creaseBasisWgsl from '../../../wgsl/cc/crease-basis.wgsl?raw';
import surfaceWgsl from '../../../wgsl/cc/surface.wgsl?raw';
import buildWgsl from '../../../wgsl/cc/build.wgsl?raw';
import slicesWgsl from '../../../wgsl/cc/slices.wgsl?raw';
import { wgslConstants } from '../contract/define.ts';
import { CC_NONE } from '../contract/cc.ts';
import { ccBuildPrelude } from '../contract/contract.ts';
import { CC_AXIS_INFINITE, CC_FAN_WORDS, CC_WIDE_FAN, CC_WORDS } from './words.ts';

const wordsWgsl = CC_WORDS.map((w) => w.wgsl).join('\n');

export const CC_SURFACE_WGSL = [
  wgslConstants({ CC_NONE, CC_FAN_WORDS, CC_AXIS_INFINITE }),
  wordsWgsl,
  creaseBasisWgsl,
  slicesWgsl,
  surfaceWgsl,
].join('\n');
export const CC_BUILD_WGSL = [
  ccBuildPrelude(),
  wgslConstants({ CC_WIDE_FAN, CC_FAN_WORDS, CC_AXIS_INFINITE }),
  wordsWgsl,
  slicesWgsl,
  buildWgsl,
].join('\n');
