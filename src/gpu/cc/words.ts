/**
 * Packed words of the Catmull-Clark data (src/gpu/cc/build.ts has the layouts) declared once for
 * TypeScript and WGSL (defineBits, src/gpu/contract.ts); src/gpu/cc/shaders.ts prepends their
 * getters to the shaders. The fan and sector words are still shifted by hand.
 */
import { defineBits } from '../contract.ts';

/**
 * Word 0 of a region. kind: 1 patch, 2 EV sector; rot: the region's frame is rot_rot of the
 * root square; mask: phantom sides of a patch; crease: a single-crease patch (σ after its 16
 * indices, crease on the frame's x = 0 side); offset, sector: of an EV sector region; patchKind:
 * the colour. (ccSector still reads offset and sector by hand-written shifts of these bits.)
 */
export const CC_REGION_WORD = defineBits('CcRegionWord', {
  kind: [0, 2],
  rot: [2, 2],
  mask: [4, 4],
  offset: [8, 4],
  sector: [12, 6],
  crease: [18, 1],
  patchKind: [24, 2],
});

/**
 * Per cage vertex, where its limit (factor rule, flat baseline) is made: a fan (crease 0, index
 * = fan id) or a vertex on a straight semi-sharp crease (crease 1, index = word offset in
 * patchIdx of its 3×3 neighbourhood and σ). All ones: none (isolated vertex).
 */
export const CC_VERTEX_LIMIT_WORD = defineBits('CcVertexLimitWord', { index: [0, 31], crease: [31, 1] });
