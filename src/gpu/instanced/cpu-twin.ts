/**
 * The CPU reference of the instanced tessellator's GPU passes (wgsl/instanced/levels.wgsl,
 * common.wgsl), for checks: the static / per-patch level rule and its buckets, a pattern point's
 * cage triangle and weights, the snap of boundary vertices, and the dynamic and factor-rule levels
 * of an edge.
 */
import { BUCKETS, PATCH_WORDS } from './buffer-layouts.ts';
import { patchCanonical, patchDomain, patchEdgeIds, type InstancedMesh } from './prepare-patches.ts';
import { LEVEL_DEFAULTS, type LevelParams } from './instanced-options.ts';
import { edgeFactor, type Vec3 } from '../tess/factors.ts';
import { packPatterns, snapVertex, edgePoint, POW2_LEVEL_COUNT, MAX_POW2_LEVEL, type PackedPatterns } from '../../pattern/pow2.ts';

/** log2 of a level rounded down to a power of two in [1, 64] (the GPU's levelLog2). */
export function levelLog2(L: number): number {
  return Math.min(Math.floor(Math.log2(Math.max(L, 1))), POW2_LEVEL_COUNT - 1);
}

export interface CpuLevels {
  edgeLevels: Uint32Array;
  patchLevels: Uint32Array;
  counts: Uint32Array;
  /** 5 words per bucket, as the GPU's records pass writes them. */
  records: Uint32Array;
}

/** The static / per-patch level rule on the CPU: edge = min over its patches, patch = its own. */
export function cpuLevels(m: InstancedMesh, wanted: ArrayLike<number>, patterns: PackedPatterns = packPatterns()): CpuLevels {
  const patchLevels = Uint32Array.from({ length: m.patchCount }, (_, p) => 1 << levelLog2(wanted[p]));
  const edgeLevels = new Uint32Array(m.edgeCount).fill(MAX_POW2_LEVEL);
  for (let p = 0; p < m.patchCount; p++) for (const e of patchEdgeIds(m, p)) edgeLevels[e] = Math.min(edgeLevels[e], patchLevels[p]);
  const counts = new Uint32Array(BUCKETS);
  for (let p = 0; p < m.patchCount; p++) counts[(patchDomain(m, p) === 'tri' ? POW2_LEVEL_COUNT : 0) + levelLog2(patchLevels[p])]++;
  const records = new Uint32Array(5 * BUCKETS);
  patterns.entries.forEach((e, b) => records.set([e.indexCount, counts[b], e.firstIndex, e.baseVertex, 0], 5 * b));
  return { edgeLevels, patchLevels, counts, records };
}

/** The cage triangle and 16.16 weights of pattern point (i, j) of patch p at level P
 * (wgsl/instanced/common.wgsl patchTriangle). */
export function patchTriangle(m: InstancedMesh, p: number, P: number, i: number, j: number): { t: number; w: [number, number, number] } {
  const s = 65536 / P,
    t0 = m.patches[PATCH_WORDS * p];
  if (patchDomain(m, p) === 'tri') return { t: t0, w: [(P - i - j) * s, i * s, j * s] };
  if (i >= j) return { t: t0, w: [(P - i) * s, (i - j) * s, j * s] };
  return { t: t0 + 1, w: [(P - j) * s, i * s, (j - i) * s] };
}

/** Snapped (i, j) of pattern vertex (i, j) of patch p at level P, given every edge's level. */
export function snapPatchVertex(
  m: InstancedMesh,
  p: number,
  P: number,
  i: number,
  j: number,
  edgeLevels: ArrayLike<number>,
): [number, number] {
  const levels = patchEdgeIds(m, p).map((e) => Math.min(edgeLevels[e], P));
  return snapVertex(patchDomain(m, p), P, i, j, levels, patchCanonical(m, p));
}

/**
 * The dynamic rule for edge e on the CPU (wgsl/instanced/levels.wgsl edgeView), in double
 * precision, with the surface given as a function of (cage triangle, float weights). Returns the
 * level and the continuous segment count it was rounded from (a check skips edges whose count
 * lies within f32 noise of a power of two).
 */
export function cpuDynamicEdgeLevel(
  m: InstancedMesh,
  e: number,
  lp: LevelParams,
  surface: (t: number, w: [number, number, number]) => number[],
): { level: number; n: number } {
  const owner = m.edgeOwner[e],
    p = owner >> 2,
    k = owner & 3;
  const dom = patchDomain(m, p);
  const vp = lp.viewProj ?? new Float32Array(16);
  const [W, H] = lp.viewport ?? [1, 1];
  const s: number[][] = [];
  let behind = false;
  for (let q = 0; q < 3; q++) {
    const [i, j] = edgePoint(dom, 2, k, q);
    const { t, w } = patchTriangle(m, p, 2, i, j);
    const x = surface(t, [w[0] / 65536, w[1] / 65536, w[2] / 65536]);
    const clip = [0, 1, 2, 3].map((r) => vp[r] * x[0] + vp[4 + r] * x[1] + vp[8 + r] * x[2] + vp[12 + r]);
    behind ||= clip[3] <= 0;
    s.push([(clip[0] / clip[3]) * 0.5 * W, (clip[1] / clip[3]) * 0.5 * H]);
  }
  if (behind) return { level: 1 << levelLog2(lp.level ?? LEVEL_DEFAULTS.level), n: NaN };
  const chord = Math.hypot(s[2][0] - s[0][0], s[2][1] - s[0][1]);
  const dev = Math.hypot(s[1][0] - 0.5 * (s[0][0] + s[2][0]), s[1][1] - 0.5 * (s[0][1] + s[2][1]));
  const n =
    (lp.lodScale ?? LEVEL_DEFAULTS.lodScale) *
    Math.max(chord / (lp.targetPixels ?? LEVEL_DEFAULTS.targetPixels), Math.sqrt(dev / (lp.pixelError ?? LEVEL_DEFAULTS.pixelError)));
  const c = Math.ceil(Math.min(Math.max(n, 1), MAX_POW2_LEVEL));
  return { level: c <= 1 ? 1 : 2 ** Math.ceil(Math.log2(c)), n };
}

/**
 * The factor-rule mode for edge e on the CPU (wgsl/instanced/levels.wgsl edgeFactorRule): the
 * compute tessellator's adaptive factor's edge term (src/gpu/tess/factors.ts edgeFactor without a
 * bulge, double precision) at the
 * edge's two cage vertices as `point` gives them (cage positions and normals; the limit's for
 * Catmull-Clark), rounded up to a power of two. Returns the level and the factor.
 */
export function cpuFactorRuleEdgeLevel(
  m: InstancedMesh,
  e: number,
  lp: LevelParams,
  point: (v: number) => { pos: Vec3; normal: Vec3 },
): { level: number; f: number } {
  const a = point(m.edgeVerts[2 * e]),
    b = point(m.edgeVerts[2 * e + 1]);
  const f = edgeFactor(a.pos, b.pos, a.normal, b.normal, {
    mode: 'adaptive',
    fixedFactor: 1,
    lodScale: lp.lodScale ?? LEVEL_DEFAULTS.lodScale,
    viewProj: lp.viewProj ?? new Float32Array(16),
    eye: lp.eye ?? [0, 0, 0],
    pixelAngle: lp.pixelAngle ?? 1,
    maxFactor: MAX_POW2_LEVEL,
  });
  const c = Math.ceil(f);
  return { level: c <= 1 ? 1 : 2 ** Math.ceil(Math.log2(c)), f };
}
