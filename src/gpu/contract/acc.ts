/**
 * The ACC patch build's side of the contract (src/gpu/acc/patches.ts, wgsl/acc/build.wgsl): the
 * sections of its static words (ACC_STATIC), its uniforms (ACC_BUILD_PARAMS, whose offset fields
 * are the arena's), its bind group (ACC_BUILD_GROUP) and the packed sector word its shader reads
 * (ACC_SECTOR_WORD); and the bindings of the ACC error pass (HEAT_GROUP, src/gpu/acc/heat.ts). What
 * the build's shader starts with is assembled in contract.ts (accBuildPrelude).
 */
import { defineArena, defineBindGroup, defineBits } from './define.ts';
import { defineStruct } from './layout.ts';
import { SECTOR_WORD_FIELDS } from '../../subdiv/acc.ts';

/** The sections of the ACC build's static words (src/subdiv/acc.ts has their layouts). */
export type AccSection = 'corners' | 'ringOffs' | 'ringData' | 'valOffs' | 'valData' | 'sectors' | 'secOffs' | 'secData' | 'order';

/**
 * accStatic (u32, read-only, written once per topology), section after section, each as long as
 * the array patches.ts packs into it: corners (8 per patch: (vertex, ring rotation) × 4), ringOffs
 * (nVerts + 1), ringData (per vertex e_0..e_{n−1}, d_0..d_{n−1}), valOffs (per valence: start of
 * its constants in valData), valData (f32 bits: c, s, λ, s_n, α[n], β[n], cos(2πk/n)[n]), sectors
 * (4 per patch: ACC_SECTOR_WORD), secOffs (per (k, corner?) at 2k + corner: start in secData),
 * secData (f32 bits: cos θ, sin θ, n', ca[0..k], cb[0..k], crease mask[2k + 2]), order (nPatches:
 * thread i builds patch order[i], sorted by kind so a workgroup runs one construction).
 */
export const ACC_STATIC = defineArena<AccSection, Readonly<Record<AccSection, number>>>([
  ['corners', (s) => s.corners],
  ['ringOffs', (s) => s.ringOffs],
  ['ringData', (s) => s.ringData],
  ['valOffs', (s) => s.valOffs],
  ['valData', (s) => s.valData],
  ['sectors', (s) => s.sectors],
  ['secOffs', (s) => s.secOffs],
  ['secData', (s) => s.secData],
  ['order', (s) => s.order],
]);

/** The ACC build's uniforms (`bp` in wgsl/acc/build.wgsl): the patch count and ACC_STATIC's offsets. */
export const ACC_BUILD_PARAMS = defineStruct('AccBuildParams', [['nPatches', 'u32'], ...ACC_STATIC.offsetFields] as const);

/** The ACC build's group (wgsl/acc/build.wgsl); its pipeline's layout is these entries. */
export const ACC_BUILD_GROUP = defineBindGroup(0, {
  bp: { binding: 0, space: 'uniform', type: 'AccBuildParams' },
  accStatic: { binding: 1, space: 'read', type: 'array<u32>', doc: 'ACC_STATIC.' },
  cagePos: { binding: 2, space: 'read', type: 'array<f32>', doc: "xyz per cage vertex (the tessellator's cage buffer starts so)." },
  accPatchesB: { binding: 3, space: 'read', type: 'array<u32>', doc: '(kind, first point) per patch.' },
  accPointsB: { binding: 4, space: 'read_write', type: 'array<vec4<f32>>' },
});

/**
 * A patch corner's sector (ACC_STATIC `sectors`; its fields are src/subdiv/acc.ts SECTOR_WORD_FIELDS, which packs it): its kind (SECTOR_*
 * of src/subdiv/acc.ts: smooth, crease, corner, cone), its size k and the a of its constants.
 */
export const ACC_SECTOR_WORD = defineBits('AccSectorWord', SECTOR_WORD_FIELDS);

/**
 * The ACC error pass's own bindings (wgsl/acc/heat.wgsl, src/gpu/acc/heat.ts), in group 0 after the
 * reference tessellator's inputs (TESS_GROUP's params, staticBuf, cageBuf, work: bindings 0 to 3);
 * the ACC patches are group 1 (patches.ts accBindingsWgsl). Each entry point's layout holds what it
 * uses (usedBindings).
 */
export const HEAT_GROUP = defineBindGroup(0, {
  srcTri: { binding: 4, space: 'read', type: 'array<u32>', doc: "The output mesh's source triangle and weights per vertex." },
  bary: { binding: 5, space: 'read', type: 'array<u32>' },
  aux: { binding: 6, space: 'read_write', type: 'array<u32>', doc: 'HEAT_AUX (src/gpu/acc/heat.ts), offsets in heatPass.' },
  heatPass: { binding: 7, space: 'uniform', type: 'HeatPass' },
  outCounts: { binding: 8, space: 'read', type: 'array<u32>', doc: "The output's counts (word 0: vertices)." },
  dispatchArgs: { binding: 9, space: 'read_write', type: 'array<u32>', doc: "heatErrors' indirect dispatch." },
});
export type HeatBinding = keyof typeof HEAT_GROUP.binding;
export const HEAT_BINDINGS = Object.keys(HEAT_GROUP.binding) as HeatBinding[];

/**
 * The two buffers wgsl/acc/surface.wgsl reads (AccPatches' patch words and control points), at an
 * includer's group, from binding `first`: the ACC error views (group 1), the sample kernel (group
 * 0). The instanced tessellator declares them in its surface group (src/gpu/instanced/buffer-layouts.ts).
 */
export function accSurfaceGroup(group: number, first: number) {
  return defineBindGroup(group, {
    accPatches: { binding: first, space: 'read', type: 'array<u32>' },
    accPoints: { binding: first + 1, space: 'read', type: 'array<vec4<f32>>' },
  });
}

/** Group 0 of AccPatches.sample's kernel (src/gpu/acc/patches.ts): the patches (accSurfaceGroup(0, 0)),
 * then its (patch, u bits, v bits) points in and (position, normal) out. */
export const ACC_SAMPLE_GROUP = defineBindGroup(0, {
  sampleIn: { binding: 2, space: 'read', type: 'array<u32>', doc: '(patch, u bits, v bits) per point' },
  sampleOut: { binding: 3, space: 'read_write', type: 'array<f32>', doc: '(position, normal) per point' },
});

/** Group 0 of the ACC error kernel (src/gpu/acc/error.ts), after the compute tessellator's inputs
 * (TESS_INPUTS, bindings 0–3): its points in, the errors out and the triangles' ACC words. */
export const ACC_ERROR_GROUP = defineBindGroup(0, {
  errIn: { binding: 4, space: 'read', type: 'array<u32>', doc: '(t, w1, w2) per point' },
  errOut: { binding: 5, space: 'read_write', type: 'array<f32>', doc: '(distance, degrees) per point' },
  accTriMap: { binding: 6, space: 'read', type: 'array<u32>', doc: 'per cage triangle: ACC_TRI_WORD' },
});
