/**
 * Packed words of the Catmull-Clark data (src/gpu/cc/build.ts has the layouts) declared once for
 * TypeScript and WGSL (defineBits, src/gpu/contract/define.ts): build.ts packs through .pack, the CPU
 * side of the region lookup reads through .get, and src/gpu/cc/shaders.ts prepends the generated
 * getters (`ccFanWord_depth(w)`, …) to the shaders, which decode nothing by hand.
 */
import { defineBits } from '../contract/define.ts';

/**
 * Word 0 of a region. kind: 1 patch, 2 EV sector; rot: the region's frame is rot_rot of the
 * root square; mask: phantom sides of a patch; crease: a single-crease patch (σ after its 16
 * indices, crease on the frame's x = 0 side); offset, sector: of an EV sector region (its fan
 * starts `offset` levels above the region's); patchKind: the colour.
 */
export const CC_REGION_WORD = defineBits('CcRegionWord', {
  kind: [0, 2],
  rot: [2, 2],
  mask: [4, 4],
  offset: [8, 4],
  sector: [12, 12],
  patchKind: [24, 2],
  crease: [26, 1],
});

/**
 * Per cage vertex, where its limit (factor rule, flat baseline) is made: a fan (crease 0, index
 * = fan id) or a vertex on a straight semi-sharp crease (crease 1, index = word offset in
 * patchIdx of its 3×3 neighbourhood and σ). All ones: none (isolated vertex).
 */
export const CC_VERTEX_LIMIT_WORD = defineBits('CcVertexLimitWord', { index: [0, 31], crease: [31, 1] });

/**
 * Word 0 of a point's rule. kind: 0 face, 1 edge, 2 vertex point; count: the face's corners,
 * the edge's inputs (2 on a boundary, else 4) or the vertex's edges; faces: the vertex's faces;
 * parent, child: the vertex's rule before and after the step (0 smooth, 1 crease, 2 corner);
 * sharp: the edge's sharpness follows its inputs (else 0).
 */
export const CC_RULE_WORD = defineBits('CcRuleWord', {
  kind: [0, 2],
  parent: [2, 2],
  child: [4, 2],
  sharp: [6, 1],
  count: [8, 12],
  faces: [20, 12],
});

/** Two edge positions in a vertex's ring: a vertex rule's or a fan's crease pair. */
export const CC_PAIR_WORD = defineBits('CcPairWord', { a: [0, 16], b: [16, 16] });

/**
 * Word 0 of a fan. sectors: its threads (valence, + 1 pseudo-sector on a boundary); valence;
 * boundary; rule: the centre's (0 smooth or dart, 1 crease, 2 corner); depth: its steps D;
 * odd: its slices keep the sectors' points of the odd steps only (src/gpu/cc/build.ts "slices").
 */
export const CC_FAN_WORD = defineBits('CcFanWord', {
  sectors: [0, 12],
  valence: [12, 12],
  boundary: [24, 1],
  rule: [25, 2],
  depth: [27, 4],
  odd: [31, 1],
});

/** Words per fan (src/gpu/cc/build.ts "fans"). */
export const CC_FAN_WORDS = 9;

/** A sector's axis word (its first): infinitely sharp. 0 is smooth; anything else a semi-sharp
 * axis's sharpness at the fan's start level, as f32 bits (which are never 1). */
export const CC_AXIS_INFINITE = 1;

/** A step's rule of a fan centre with semi-sharp edges (src/gpu/cc/fans.ts stepRules): the
 * vertex rule before and after the step (0 smooth or dart, 1 crease, 2 corner). */
export const CC_STEP_RULE_WORD = defineBits('CcStepRuleWord', { parent: [0, 2], child: [2, 2] });

/** The most sectors a fan has (its word's field): the widest vertex the build takes. */
export const CC_MAX_FAN_SECTORS = 2 ** CC_FAN_WORD.fields.sectors[1] - 1;

/**
 * One slice-kernel thread: its fan and its sector (all ones: idle). A fan wider than a workgroup
 * has a workgroup of its own, whose first word has sector CC_WIDE_FAN (and the rest idle): its
 * threads take its sectors in turn (wgsl/cc/build.wgsl wideSlices).
 */
export const CC_THREAD_WORD = defineBits('CcThreadWord', { fan: [0, 24], sector: [24, 8] });
export const CC_WIDE_FAN = 2 ** CC_THREAD_WORD.fields.sector[1] - 1;

/**
 * Word 1 of a prepared triangle. corners: its face's (4: a quad); fan: which triangle of the face
 * it is (src/gpu/tess/prepare.ts triFan): face corners (0, fan, fan + 1), or with centred set
 * (centre, fan, fan + 1 mod n); depth: the face's region depth inside the quad or inside each
 * n-gon sub-face.
 */
export const CC_TRI_WORD = defineBits('CcTriWord', { corners: [0, 8], fan: [8, 19], centred: [27, 1], depth: [28, 4] });

export const CC_WORDS = [
  CC_REGION_WORD,
  CC_VERTEX_LIMIT_WORD,
  CC_RULE_WORD,
  CC_PAIR_WORD,
  CC_FAN_WORD,
  CC_STEP_RULE_WORD,
  CC_THREAD_WORD,
  CC_TRI_WORD,
];
