/**
 * The numbers every shader may read (workgroup sizes, the dispatch grid's width), exported as
 * TypeScript values and as a WGSL `const` prelude (constantsWgsl), and the 2D dispatch grid that
 * folds wide dispatches under GRID_X.
 */
import { wgslConstants } from './define.ts';

/** The largest tess factor (src/pattern/max-factor.ts: the pattern layer imports nothing from gpu). */
export { MAX_FACTOR } from '../../pattern/max-factor.ts';

/** Threads per workgroup of the tessellator's one-thread-per-item passes. */
export const WORKGROUP_SIZE = 64;
/** Threads per workgroup of the prefix-sum passes (wgsl/tess/scan.wgsl): 128, the most WebGPU's
 * compatibility mode allows (maxComputeInvocationsPerWorkgroup), so no pass needs more. */
export const SCAN_WORKGROUP_SIZE = 128;
/** Values each scan thread sums serially (wgsl/tess/scan.wgsl): one scan workgroup covers
 * SCAN_WORKGROUP_SIZE × SCAN_ITEMS = 4096 values. */
export const SCAN_ITEMS = 32;
/** Widest dispatch in x (WebGPU's default maxComputeWorkgroupsPerDimension); wider ones fold into y. */
export const GRID_X = 65535;

/** Phong tessellation's shape factor α (Boubekeur and Alexa's 3/4): the compute and instanced
 * tessellators' Phong surface, the factor rule's chord bound (src/gpu/tess/factors.ts), and the
 * per-edge α that src/gpu/surface/phong-alpha.ts lowers from it. An f32 in WGSL (tessPrelude). */
export const PHONG_ALPHA = 0.75;

/** The numbers every shader may read, by their WGSL names (all u32). */
export const SHARED_CONSTANTS = { WORKGROUP_SIZE, SCAN_WORKGROUP_SIZE, SCAN_ITEMS, GRID_X } as const;

/** Workgroup counts as a 2D grid: WebGPU caps each dimension at GRID_X (an over-limit indirect
 * dispatch silently does nothing; a direct one is a validation error). Shaders fold y back:
 * (wid.y * GRID_X + wid.x) * WORKGROUP_SIZE + lid. */
export function grid2d(groups: number): [number, number] {
  if (groups <= GRID_X) return [Math.max(groups, 1), 1];
  return [GRID_X, Math.ceil(groups / GRID_X)];
}

/** Workgroups of WORKGROUP_SIZE threads for one thread per item, folded into 2D. */
export function groupsFor(items: number): [number, number] {
  return grid2d(Math.ceil(items / WORKGROUP_SIZE));
}

/** The WGSL prelude of the shared constants. */
export const constantsWgsl = wgslConstants(SHARED_CONSTANTS);
