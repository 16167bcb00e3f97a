/**
 * Instanced power-of-two tessellation (NVIDIA's 2009 "Instanced Tessellation" sample; notes
 * acc-and-instanced.md §6): one precomputed pattern per level 1, 2, 4, … 64 and domain
 * (src/pattern/pow2.ts), patches bucketed by level on the GPU, one indirect instanced draw per
 * bucket, the surface evaluated in the vertex shader, T-junctions removed by the snap of boundary
 * vertices to each edge's level. Unlike the compute tessellator (tessellator.ts), which builds
 * the mesh once and draws the stored buffers in every pass, this re-evaluates the surface in
 * every pass (lit and shadow). Takes a GPUDevice, never the DOM.
 *
 * Patches are cage faces: a quad face is one quad patch, any other face gives one triangle patch
 * per fan triangle of src/gpu/tess/prepare.ts (a triangle face: itself). The surface is any WGSL module
 * with the compute tessellator's evalSurface contract (default Phong, wgsl/surface/phong.wgsl), the
 * three ACC surfaces (src/gpu/acc/patches.ts patches), or the exact Catmull-Clark surface through the
 * compute tessellator's own evaluator and buffers (src/gpu/instanced/surface-cc.ts says how). With the
 * option `displacement`, every vertex is moved by a height map in the same vertex function, its
 * boundary points evaluated through their owner triangle (crack-free at UV seams), from a lending
 * compute Tessellator's displacement arenas (src/gpu/instanced/displace-vertex.ts says how).
 *
 * Passes (encodeLevels, one compute pass, no readback):
 *   clear      edge codes and bucket counts
 *   patchEdges modes static / per-patch: each edge's level = min over its patches   one thread per patch
 *   edgeView   mode dynamic: each edge's level from the view                        one thread per edge
 *   edgeFactorRule  mode factor-rule: each edge's level by the compute tessellator's
 *              adaptive factor rule's edge term (the same screen-space measure; not its bulge
 *              term, which samples inside each cage triangle: not ported)   one thread per edge
 *   bucket     each patch's level, a slot in its bucket's list                      one thread per patch
 *   records    14 drawIndexedIndirect records (quad and triangle × 7 levels)        one workgroup
 * Then encodeDraw (lit or shadow pass: 14 drawIndexedIndirect, the bucket's list base by dynamic
 * offset, shaded by wgsl/instanced/frame.wgsl), or drawShadow / drawLit / drawWire inside the demo
 * renderer's passes (useRenderer: its scene uniform, shadow map and lit shading,
 * wgsl/render/instanced.wgsl), or headless (the same vertex function in compute, for checks and
 * the CLI). Buffer layouts: wgsl/instanced/common.wgsl, wgsl/instanced/levels.wgsl, wgsl/instanced/draw.wgsl.
 */
import commonWgsl from '../../../wgsl/instanced/common.wgsl?raw';
import levelsWgsl from '../../../wgsl/instanced/levels.wgsl?raw';
import factorRuleWgsl from '../../../wgsl/tess/factor-rule.wgsl?raw';
import drawWgsl from '../../../wgsl/instanced/draw.wgsl?raw';
import frameWgsl from '../../../wgsl/instanced/frame.wgsl?raw';
import headlessWgsl from '../../../wgsl/instanced/headless.wgsl?raw';
import renderInstancedWgsl from '../../../wgsl/render/instanced.wgsl?raw';
import triSurfaceWgsl from '../../../wgsl/instanced/surface-tri.wgsl?raw';
import accSurfaceWgsl from '../../../wgsl/instanced/surface-acc.wgsl?raw';
import plainVertexWgsl from '../../../wgsl/instanced/vertex-plain.wgsl?raw';
import { accBindingsWgsl, ACC_SURFACE_WGSL, type AccPatches } from '../acc/patches.ts';
import { ccSurfaceEntries, ccSurfaceLayoutEntries, checkCCSource, instancedCCSurfaceWgsl } from './surface-cc.ts';
import type { Tessellator } from '../tess/tessellator.ts';
import { checkLender, instancedDisplaceWgsl, lenderEntries, lenderLayoutEntries, setLenderDisplacement } from './displace-vertex.ts';
import type { DisplacementSettings } from '../tess/displacement-map.ts';
import { meshFaceStates, RENDER_SHADERS } from '../render/pipelines.ts';
import type { ShadingResources, SurfaceDrawer } from '../render/renderer.ts';
import phongSurfaceWgsl from '../../../wgsl/surface/phong.wgsl?raw';
import { defineStruct } from '../contract/layout.ts';
import { defineBits } from '../contract/define.ts';
import { constantsWgsl, grid2d, WORKGROUP_SIZE } from '../contract/constants.ts';
import { readBuffer } from '../device/readback.ts';
import { faceParam, type FaceParam } from '../tess/face-params.ts';
import { edgeFactor, type Vec3 } from '../tess/factors.ts';
import { phongTriAlphas } from '../surface/phong.ts';
import type { FactorParams } from '../contract/tessellated-mesh.ts';
import type { PreparedMesh } from '../tess/prepare.ts';
import type { Cage } from '../../mesh/types.ts';
import {
  packPatterns,
  snapVertex,
  edgePoint,
  vertexEdges,
  POW2_LEVEL_COUNT,
  MAX_POW2_LEVEL,
  type PackedPatterns,
  type PatchDomain,
} from '../../pattern/pow2.ts';

export const INST_PARAMS = defineStruct('InstParams', [
  ['viewProj', 'mat4x4<f32>'],
  // x, y: viewport size in pixels (dynamic mode).
  ['viewport', 'vec4<f32>'],
  // xyz: the eye in model space (factor-rule mode).
  ['eye', 'vec4<f32>'],
  ['nPatches', 'u32'],
  ['nQuads', 'u32'],
  ['nTris', 'u32'],
  ['nEdges', 'u32'],
  ['mode', 'u32'],
  ['staticLevel', 'u32'],
  ['lodScale', 'f32'],
  ['targetPixels', 'f32'],
  ['pixelError', 'f32'],
  // Factor-rule mode: radians per pixel (fovY / viewport height), as the compute tessellator's Params.
  ['pixelAngle', 'f32'],
  // staticBuf word offsets (wgsl/instanced/common.wgsl), cageBuf float offset of the normals.
  ['offTriVerts', 'u32'],
  ['offPatches', 'u32'],
  ['offEdgeOwner', 'u32'],
  ['offPatternIJ', 'u32'],
  ['offPatternIdx', 'u32'],
  ['offEntries', 'u32'],
  ['offNormals', 'u32'],
  ['offPhongAlpha', 'u32'],
  // work word offsets (wgsl/instanced/levels.wgsl).
  ['offWanted', 'u32'],
  ['offEdgeCode', 'u32'],
  ['offPatchLevel', 'u32'],
  ['offCounts', 'u32'],
  ['offLists', 'u32'],
  // 1: the renderer-pass lit draw shades facets (wgsl/render/instanced.wgsl; setFlatShading).
  ['flatShading', 'u32'],
] as const);

export const INST_BUCKET = defineStruct('InstBucket', [
  ['listBase', 'u32'],
  ['level', 'u32'],
  ['domain', 'u32'],
  ['baseVertex', 'u32'],
  ['firstIndex', 'u32'],
  ['vertexCount', 'u32'],
  ['triangleCount', 'u32'],
  ['outVertexBase', 'u32'],
  ['outTriangleBase', 'u32'],
  ['instances', 'u32'],
  ['outVertexTotal', 'u32'],
] as const);

/** An edge's owner: the patch and which of its sides (edge k) it is (wgsl/instanced/levels.wgsl). */
export const INST_OWNER_WORD = defineBits('InstOwnerWord', { side: [0, 2], patchId: [2, 30] });

export const INST_FRAME = defineStruct('InstFrame', [
  ['viewProj', 'mat4x4<f32>'],
  ['lightViewProj', 'mat4x4<f32>'],
  ['toLight', 'vec4<f32>'],
  ['eye', 'vec4<f32>'],
] as const);

/** Buckets: domain (0 quad, 1 triangle) · 7 + log2 level. */
export const BUCKETS = 2 * POW2_LEVEL_COUNT;
/** Bytes between two buckets' uniforms (minUniformBufferOffsetAlignment is at most 256). */
const BUCKET_STRIDE = 256;
export const PATCH_WORDS = 8;
const MODE = { static: 0, 'per-patch': 1, dynamic: 2, 'factor-rule': 3 } as const;

// ---- CPU side: patches and edges ------------------------------------------------------------

export interface InstancedMesh {
  prepared: PreparedMesh;
  quadCount: number;
  triCount: number;
  patchCount: number;
  edgeCount: number;
  /** PATCH_WORDS per patch: firstTri, flags, e0..e3, face, 0 (wgsl/instanced/common.wgsl). */
  patches: Uint32Array;
  /** Cage vertices of each patch's corners (4 per patch; a triangle's 4th is unused). */
  corners: Uint32Array;
  /** Two cage vertices per edge, lower first. */
  edgeVerts: Uint32Array;
  /** Per edge: patch · 4 + local edge of one patch that has it. */
  edgeOwner: Uint32Array;
}

export function patchDomain(m: InstancedMesh, p: number): PatchDomain {
  return m.patches[PATCH_WORDS * p + 1] & 1 ? 'tri' : 'quad';
}
export function patchEdgeIds(m: InstancedMesh, p: number): number[] {
  const n = patchDomain(m, p) === 'tri' ? 3 : 4;
  return Array.from({ length: n }, (_, k) => m.patches[PATCH_WORDS * p + 2 + k]);
}
export function patchCanonical(m: InstancedMesh, p: number): boolean[] {
  const n = patchDomain(m, p) === 'tri' ? 3 : 4;
  return Array.from({ length: n }, (_, k) => ((m.patches[PATCH_WORDS * p + 1] >> (1 + k)) & 1) === 1);
}

/** Patches and their edges from a cage and its prepared triangulation (prepare.ts). */
export function prepareInstanced(cage: Cage, prepared: PreparedMesh): InstancedMesh {
  const holes = new Set(cage.holes);
  const quads: { tri: number; face: number; c: number[] }[] = [];
  const tris: { tri: number; face: number; c: number[] }[] = [];
  // A quad is one patch (its first prepared triangle's id); every other face gives its prepared
  // triangles (a triangle itself, or the fan round an n-gon's centre) as triangle patches.
  let t = 0;
  for (let f = 0; f + 1 < cage.faceOffsets.length; f++) {
    if (holes.has(f)) continue;
    const s = cage.faceOffsets[f],
      n = cage.faceOffsets[f + 1] - s;
    if (n < 3) continue;
    if (prepared.triFace[t] !== f) throw new Error('prepareInstanced: the cage does not match its prepared mesh');
    const first = t;
    while (t < prepared.triangleCount && prepared.triFace[t] === f) t++;
    if (n === 4) quads.push({ tri: first, face: f, c: Array.from(cage.faceIndices.subarray(s, s + 4)) });
    else for (let k = first; k < t; k++) tris.push({ tri: k, face: f, c: Array.from(prepared.triVerts.subarray(3 * k, 3 * k + 3)) });
  }
  if (t !== prepared.triangleCount) throw new Error('prepareInstanced: the cage does not match its prepared mesh');
  const all = [...quads, ...tris];
  const patches = new Uint32Array(PATCH_WORDS * all.length);
  const corners = new Uint32Array(4 * all.length);
  const edgeIds = new Map<number, number>();
  const edgeVerts: number[] = [];
  const edgeOwner: number[] = [];
  const nV = prepared.vertexCount;
  all.forEach((q, p) => {
    const n = q.c.length;
    let flags = n === 3 ? 1 : 0;
    const o = PATCH_WORDS * p;
    patches[o] = q.tri;
    for (let k = 0; k < n; k++) {
      const a = q.c[k],
        b = q.c[(k + 1) % n];
      if (a < b) flags |= 1 << (1 + k);
      const key = Math.min(a, b) * nV + Math.max(a, b);
      let e = edgeIds.get(key);
      if (e === undefined) {
        e = edgeVerts.length / 2;
        edgeIds.set(key, e);
        edgeVerts.push(Math.min(a, b), Math.max(a, b));
        edgeOwner.push(INST_OWNER_WORD.pack({ side: k, patchId: p }));
      }
      patches[o + 2 + k] = e;
      corners[4 * p + k] = a;
    }
    patches[o + 1] = flags;
    patches[o + 6] = q.face;
  });
  return {
    prepared,
    quadCount: quads.length,
    triCount: tris.length,
    patchCount: all.length,
    edgeCount: edgeVerts.length / 2,
    patches,
    corners,
    edgeVerts: Uint32Array.from(edgeVerts),
    edgeOwner: Uint32Array.from(edgeOwner),
  };
}

// ---- CPU reference of the GPU passes ---------------------------------------------------------

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

/** The defaults of LevelParams, shared by the GPU upload and the CPU twin. */
const LEVEL_DEFAULTS = { level: 4, lodScale: 1, targetPixels: 12, pixelError: 0.5 };

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

/** The factor-rule levels for the compute tessellator's camera and LOD scale (its FactorParams, as
 * its adaptive mode reads them): the two tessellators then measure the view alike. */
export function factorRuleLevels(f: FactorParams): LevelParams {
  return {
    mode: 'factor-rule',
    viewProj: f.viewProj,
    eye: [f.eye[0], f.eye[1], f.eye[2]],
    pixelAngle: f.fovY / Math.max(1, f.viewportHeight),
    lodScale: f.lodScale,
  };
}

/**
 * Where each headless output vertex lies on its cage face, in the CPU reference's addressing
 * (src/gpu/tess/face-params.ts: `f u v` on quads, `f k s t` on sub-faces of other faces), for the
 * CLI's --params.
 */
export function instancedVertexParams(m: InstancedMesh, cage: Cage, out: HeadlessInstanced): FaceParam[] {
  const params: FaceParam[] = [];
  for (let v = 0; v < out.vertexCount; v++) {
    const p = out.patch[v],
      P = out.patchLevels[p];
    const { t, w } = patchTriangle(m, p, P, Math.round(out.uv[2 * v] * P), Math.round(out.uv[2 * v + 1] * P));
    params.push(faceParam(m.prepared, cage, t, [w[0] / 65536, w[1] / 65536, w[2] / 65536]));
  }
  return params;
}

/** The headless output as OBJ: positions, normals, 1-based triangles; vertices are welded
 * within each patch only, and the triangles the snap collapsed (zero area in (u, v)) are left out. */
export function instancedToObj(out: HeadlessInstanced, header: string): string {
  const lines: string[] = [`# ${header}`];
  for (let v = 0; v < out.vertexCount; v++) lines.push(`v ${out.positions[3 * v]} ${out.positions[3 * v + 1]} ${out.positions[3 * v + 2]}`);
  for (let v = 0; v < out.vertexCount; v++) lines.push(`vn ${out.normals[3 * v]} ${out.normals[3 * v + 1]} ${out.normals[3 * v + 2]}`);
  let kept = 0;
  for (let t = 0; t < out.triangleCount; t++) {
    const [a, b, c] = [0, 1, 2].map((k) => out.indices[3 * t + k]);
    const uv = (x: number, k: number) => out.uv[2 * x + k];
    const area2 = (uv(b, 0) - uv(a, 0)) * (uv(c, 1) - uv(a, 1)) - (uv(b, 1) - uv(a, 1)) * (uv(c, 0) - uv(a, 0));
    if (area2 === 0) continue;
    lines.push(`f ${a + 1}//${a + 1} ${b + 1}//${b + 1} ${c + 1}//${c + 1}`);
    kept++;
  }
  lines.splice(1, 0, `# ${out.vertexCount} vertices, ${kept} triangles (${out.triangleCount - kept} collapsed by the snap left out)`);
  return lines.join('\n') + '\n';
}

/** The headless output welded across patches (what the CLI writes, as the compute tessellator's
 * OBJ is welded). Copies are merged by where they lie on the cage, never by position: a patch
 * corner by its cage vertex, a point on a cage edge by the edge and its canonical parameter
 * (exact: a multiple of 1/64), an interior point by its patch and (i, j). The welded position is
 * the first copy's; `gap` is the largest distance between copies merged (the two sides of an edge
 * evaluate the surface in f32 each: the crack the weld closes). Triangles the snap collapsed
 * (zero area in (u, v), or two corners welded together) are left out. */
export interface WeldedInstanced {
  vertexCount: number;
  triangleCount: number;
  positions: Float32Array;
  normals: Float32Array;
  indices: Uint32Array;
  /** Per welded vertex: the headless output vertex it was taken from. */
  source: Uint32Array;
  /** Triangles of the draw left out (collapsed by the snap). */
  collapsed: number;
  /** Largest distance between merged copies, in model units. */
  gap: number;
}

export function weldInstanced(m: InstancedMesh, out: HeadlessInstanced): WeldedInstanced {
  const nV = m.prepared.vertexCount,
    nE = m.edgeCount;
  const S = MAX_POW2_LEVEL + 1;
  const ids = new Map<number, number>();
  const remap = new Uint32Array(out.vertexCount);
  const source: number[] = [];
  let gap = 0;
  for (let v = 0; v < out.vertexCount; v++) {
    const p = out.patch[v],
      P = out.patchLevels[p];
    const i = Math.round(out.uv[2 * v] * P),
      j = Math.round(out.uv[2 * v + 1] * P);
    const dom = patchDomain(m, p);
    const on = vertexEdges(dom, P, i, j);
    let key: number;
    if (on.length === 0) key = nV + nE * S + (p * S + i) * S + j;
    else {
      const { edge, t } = on[0];
      const n = dom === 'tri' ? 3 : 4;
      if (t === 0) key = m.corners[4 * p + edge];
      else if (t === P) key = m.corners[4 * p + ((edge + 1) % n)];
      else {
        const e = m.patches[PATCH_WORDS * p + 2 + edge];
        const canonical = ((m.patches[PATCH_WORDS * p + 1] >> (1 + edge)) & 1) === 1;
        const c = ((canonical ? t : P - t) * MAX_POW2_LEVEL) / P;
        key = nV + e * S + c;
      }
    }
    let w = ids.get(key);
    if (w === undefined) {
      w = source.length;
      ids.set(key, w);
      source.push(v);
    } else {
      const f = source[w];
      const d = Math.hypot(
        out.positions[3 * v] - out.positions[3 * f],
        out.positions[3 * v + 1] - out.positions[3 * f + 1],
        out.positions[3 * v + 2] - out.positions[3 * f + 2],
      );
      gap = Math.max(gap, d);
    }
    remap[v] = w;
  }
  const src = Uint32Array.from(source);
  const positions = new Float32Array(3 * src.length);
  const normals = new Float32Array(3 * src.length);
  src.forEach((v, w) => {
    positions.set(out.positions.subarray(3 * v, 3 * v + 3), 3 * w);
    normals.set(out.normals.subarray(3 * v, 3 * v + 3), 3 * w);
  });
  const tris: number[] = [];
  for (let t = 0; t < out.triangleCount; t++) {
    const [a, b, c] = [0, 1, 2].map((k) => out.indices[3 * t + k]);
    const uv = (x: number, k: number) => out.uv[2 * x + k];
    const area2 = (uv(b, 0) - uv(a, 0)) * (uv(c, 1) - uv(a, 1)) - (uv(b, 1) - uv(a, 1)) * (uv(c, 0) - uv(a, 0));
    const [wa, wb, wc] = [remap[a], remap[b], remap[c]];
    if (area2 === 0 || wa === wb || wb === wc || wa === wc) continue;
    tris.push(wa, wb, wc);
  }
  return {
    vertexCount: src.length,
    triangleCount: tris.length / 3,
    positions,
    normals,
    indices: Uint32Array.from(tris),
    source: src,
    collapsed: out.triangleCount - tris.length / 3,
    gap,
  };
}

/** The welded mesh as OBJ (positions, normals, 1-based triangles), as src/gpu/tess/headless.ts meshToObj. */
export function weldedToObj(w: WeldedInstanced, header: string): string {
  const lines: string[] = [
    `# ${header}`,
    `# ${w.vertexCount} vertices, ${w.triangleCount} triangles (${w.collapsed} collapsed by the snap left out; largest weld gap ${w.gap.toExponential(2)})`,
  ];
  for (let v = 0; v < w.vertexCount; v++) lines.push(`v ${w.positions[3 * v]} ${w.positions[3 * v + 1]} ${w.positions[3 * v + 2]}`);
  for (let v = 0; v < w.vertexCount; v++) lines.push(`vn ${w.normals[3 * v]} ${w.normals[3 * v + 1]} ${w.normals[3 * v + 2]}`);
  for (let t = 0; t < w.triangleCount; t++) {
    const [a, b, c] = [w.indices[3 * t] + 1, w.indices[3 * t + 1] + 1, w.indices[3 * t + 2] + 1];
    lines.push(`f ${a}//${a} ${b}//${b} ${c}//${c}`);
  }
  return lines.join('\n') + '\n';
}

/** Face parameters of the welded vertices (each its source copy's, instancedVertexParams). */
export function weldedVertexParams(m: InstancedMesh, cage: Cage, out: HeadlessInstanced, w: WeldedInstanced): FaceParam[] {
  const all = instancedVertexParams(m, cage, out);
  return Array.from(w.source, (v) => all[v]);
}

// ---- the GPU tessellator --------------------------------------------------------------------

export interface InstancedOptions {
  /** WGSL defining `fn evalSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint` (default: Phong,
   * wgsl/surface/phong.wgsl), evaluated through wgsl/instanced/surface-tri.wgsl. */
  surfaceWgsl?: string;
  /**
   * 'acc': the ACC surfaces (Bezier, Gregory or Pm ACC, by the AccPatches handed to setMesh:
   * src/gpu/acc/patches.ts builds them from the cage, wgsl/acc/surface.wgsl evaluates them through
   * wgsl/instanced/surface-acc.wgsl), their two buffers bound in a fourth bind group (group 3) in
   * every pass. 'catmull-clark': the exact limit surface, evaluated by the compute tessellator's
   * wgsl/cc/surface.wgsl over the buffers of a Catmull-Clark Tessellator handed to setMesh
   * (src/gpu/instanced/surface-cc.ts: ccSurfaceTessellator makes one), bound in group 3; encodeLevels runs
   * its patch build first.
   */
  surface?: 'evalSurface' | 'acc' | 'catmull-clark';
  /**
   * Displace every vertex the vertex function evaluates by a height map (src/gpu/instanced/displace-vertex.ts):
   * setMesh then needs a lending compute Tessellator holding the displacement arenas (on
   * Catmull-Clark the surface's own lender, made with the displacement; on Phong and ACC
   * displacementLender), bound in group 3; boundary points are evaluated through their owner
   * triangle (crack-free at UV seams). Off (default): the module has none of it.
   */
  displacement?: boolean;
  /** Render target format of the lit pipeline (default 'rgba8unorm'). */
  colorFormat?: GPUTextureFormat;
  /** Depth format of the lit and shadow pipelines (default 'depth32float'). */
  depthFormat?: GPUTextureFormat;
  /** Samples per pixel of the lit pass (the demo's renderer draws with 4× MSAA; default 1). */
  sampleCount?: number;
}

export interface LevelParams {
  /** static: every patch at `level`; per-patch: the levels given to setWanted; dynamic: per
   * edge from the view (viewProj, viewport, lodScale, targetPixels, pixelError); factor-rule: per
   * edge by the compute tessellator's adaptive rule (viewProj, eye, pixelAngle, lodScale:
   * factorRuleLevels makes them from its FactorParams), rounded up to a power of two. */
  mode: 'static' | 'per-patch' | 'dynamic' | 'factor-rule';
  /** The static level (also the dynamic mode's level for an edge behind the eye). Default 4. */
  level?: number;
  viewProj?: Float32Array;
  viewport?: [number, number];
  lodScale?: number;
  /** Dynamic: pixels per segment along an edge's chord (default 12). */
  targetPixels?: number;
  /** Dynamic: allowed distance in pixels between the curve and its segments (default 0.5). */
  pixelError?: number;
  /** Factor rule: the eye in model space, and radians per pixel (fovY / viewport height). */
  eye?: [number, number, number];
  pixelAngle?: number;
}

interface WorkLayout {
  wanted: number;
  edgeCode: number;
  patchLevel: number;
  counts: number;
  lists: number;
  words: number;
}

export interface HeadlessInstanced {
  vertexCount: number;
  triangleCount: number;
  positions: Float32Array;
  normals: Float32Array;
  /** Per vertex: its patch. */
  patch: Uint32Array;
  /** Per vertex: the snapped pattern point (u, v) on its patch. */
  uv: Float32Array;
  indices: Uint32Array;
  /** Patches per bucket, as the GPU counted them. */
  counts: Uint32Array;
  /** The 14 indirect draw records the GPU wrote. */
  records: Uint32Array;
  /** Per edge: its level; per patch: its pattern level. */
  edgeLevels: Uint32Array;
  patchLevels: Uint32Array;
  /** GPU milliseconds of the headless run's passes ({ levels, evaluate }; {} without
   * timestamp queries). */
  timings: Record<string, number>;
}

/** Move `@group(g) @binding(b)` declarations, one pass over the text: "g,b" → [g', b']. */
function rebind(code: string, moves: Record<string, [number, number]>): string {
  return code.replace(/@group\((\d+)\) @binding\((\d+)\)/g, (all, g, b) => {
    const to = moves[`${g},${b}`];
    return to ? `@group(${to[0]}) @binding(${to[1]})` : all;
  });
}

/** Bytes of drawArgs: 14 indexed records (5 words), then 14 wireframe records (4 words). */
const DRAW_ARGS_BYTES = 20 * BUCKETS + 16 * BUCKETS;
const WIRE_ARGS_OFFSET = 20 * BUCKETS;

export class InstancedTessellator implements SurfaceDrawer {
  readonly patterns = packPatterns();
  /** 14 drawIndexedIndirect records (5 u32 each), rewritten by every encodeLevels. */
  readonly drawArgs: GPUBuffer;
  /** The patterns' local indices (all levels), bound by encodeDraw. */
  readonly indexBuffer: GPUBuffer;
  private readonly params: GPUBuffer;
  private readonly paramsBytes = new ArrayBuffer(INST_PARAMS.size);
  private readonly bucketUniform: GPUBuffer;
  private readonly frame: GPUBuffer;
  private readonly levelPipelines: Record<'patchEdges' | 'edgeView' | 'edgeFactorRule' | 'bucketPatches' | 'records', GPUComputePipeline>;
  private readonly layouts: {
    mesh: GPUBindGroupLayout;
    bucket: GPUBindGroupLayout;
    frame: GPUBindGroupLayout;
    out: GPUBindGroupLayout;
    /** Group 3 of an ACC surface: its patches and control points. */
    surface: GPUBindGroupLayout;
  };
  private headlessPipelineMade?: GPUComputePipeline;
  private readonly code: (...parts: string[]) => string;
  /** Whether the surface is ACC (group 3: its patches and control points). */
  readonly acc: boolean;
  /** Whether the surface is the exact Catmull-Clark one (group 3: a compute Tessellator's buffers). */
  readonly cc: boolean;
  /** Group 3 of an ACC or Catmull-Clark surface, for the current mesh. */
  private surfaceGroup?: GPUBindGroup;
  private accPatches?: AccPatches;
  /** The Catmull-Clark surface's lending tessellator (owned by the caller). */
  private ccSource?: Tessellator;
  /** Whether the vertex function displaces (group 3 holds a lending tessellator's arenas). */
  readonly displaced: boolean;
  /** The lender of the displacement arenas (owned by the caller; on Catmull-Clark the ccSource). */
  private dispSource?: Tessellator;
  private frameModule?: GPUShaderModule;
  private readonly renderLayout: GPUPipelineLayout;
  private readonly colorFormat: GPUTextureFormat;
  private readonly depthFormat: GPUTextureFormat;
  private readonly sampleCount: number;
  private litPipeline?: GPURenderPipeline;
  private shadowPipeline?: GPURenderPipeline;
  private readonly bucketGroup: GPUBindGroup;
  private readonly frameGroup: GPUBindGroup;
  private mesh?: {
    m: InstancedMesh;
    staticBuf: GPUBuffer;
    cageBuf: GPUBuffer;
    work: GPUBuffer;
    layout: WorkLayout;
    meshGroup: GPUBindGroup;
  };

  constructor(
    readonly device: GPUDevice,
    opts: InstancedOptions = {},
  ) {
    this.colorFormat = opts.colorFormat ?? 'rgba8unorm';
    this.depthFormat = opts.depthFormat ?? 'depth32float';
    this.sampleCount = opts.sampleCount ?? 1;
    this.acc = opts.surface === 'acc';
    this.cc = opts.surface === 'catmull-clark';
    this.displaced = opts.displacement === true;
    // Storage buffers per stage: group 0's three (topology + patterns, cage, work) and the
    // surface's (ACC: 2; Catmull-Clark: the lending tessellator's static, cage and work) in the
    // vertex stage, with displacement the lender's static and cage (Phong, ACC: +2; Catmull-Clark:
    // already bound); the headless pass adds its output buffer (8 with ACC and displacement: core
    // WebGPU's minimum). A device with fewer (compatibility mode) is refused here with the numbers
    // rather than by a pipeline's validation error later.
    const vertexStorage = 3 + (this.acc ? 2 : this.cc ? 3 : 0) + (this.displaced && !this.cc ? 2 : 0);
    const limits = device.limits as GPUSupportedLimits & { maxStorageBuffersInVertexStage?: number };
    const inVertex = limits.maxStorageBuffersInVertexStage ?? limits.maxStorageBuffersPerShaderStage;
    if (inVertex < vertexStorage || limits.maxStorageBuffersPerShaderStage < vertexStorage + 1)
      throw new Error(
        `the instanced tessellator on this surface needs ${vertexStorage} storage buffers in the vertex stage and ${vertexStorage + 1} in compute; this device allows ${inVertex} and ${limits.maxStorageBuffersPerShaderStage}`,
      );
    const surface = this.acc
      ? [accBindingsWgsl(3, 0, 1), ACC_SURFACE_WGSL, accSurfaceWgsl].join('\n')
      : this.cc
        ? instancedCCSurfaceWgsl()
        : [triSurfaceWgsl, opts.surfaceWgsl ?? phongSurfaceWgsl].join('\n');
    const kind = this.acc ? 'acc' : this.cc ? 'catmull-clark' : 'evalSurface';
    const vertexSurface = this.displaced ? instancedDisplaceWgsl(kind) : plainVertexWgsl;
    const code = (...parts: string[]) =>
      [constantsWgsl, INST_OWNER_WORD.wgsl, INST_PARAMS.wgsl, INST_BUCKET.wgsl, commonWgsl, ...parts, surface, vertexSurface].join('\n');
    this.code = code;
    const levels = device.createShaderModule({ label: 'instanced levels', code: code(factorRuleWgsl, levelsWgsl) });
    const pipeline = (entryPoint: string) =>
      device.createComputePipeline({ label: `instanced ${entryPoint}`, layout: 'auto', compute: { module: levels, entryPoint } });
    this.levelPipelines = {
      patchEdges: pipeline('patchEdges'),
      edgeView: pipeline('edgeView'),
      edgeFactorRule: pipeline('edgeFactorRule'),
      bucketPatches: pipeline('bucketPatches'),
      records: pipeline('records'),
    };

    // Explicit layouts: one bucket bind group with a dynamic offset, shared by the lit, shadow and
    // headless pipelines.
    const VC = GPUShaderStage.VERTEX | GPUShaderStage.COMPUTE;
    const ro = { type: 'read-only-storage' } as const;
    this.layouts = {
      mesh: device.createBindGroupLayout({
        label: 'instanced mesh',
        entries: [
          { binding: 0, visibility: VC, buffer: { type: 'uniform' } },
          { binding: 1, visibility: VC, buffer: ro },
          { binding: 2, visibility: VC, buffer: ro },
          { binding: 3, visibility: VC, buffer: ro },
        ],
      }),
      bucket: device.createBindGroupLayout({
        label: 'instanced bucket',
        entries: [{ binding: 0, visibility: VC, buffer: { type: 'uniform', hasDynamicOffset: true, minBindingSize: INST_BUCKET.size } }],
      }),
      frame: device.createBindGroupLayout({
        label: 'instanced frame',
        entries: [{ binding: 0, visibility: GPUShaderStage.VERTEX | GPUShaderStage.FRAGMENT, buffer: { type: 'uniform' } }],
      }),
      out: device.createBindGroupLayout({
        label: 'instanced headless outputs',
        entries: [{ binding: 1, visibility: GPUShaderStage.COMPUTE, buffer: { type: 'storage' } }],
      }),
      surface: device.createBindGroupLayout({
        label: this.cc ? 'instanced Catmull-Clark surface' : this.acc ? 'instanced ACC surface' : 'instanced displacement lender',
        entries: [
          ...(this.cc
            ? ccSurfaceLayoutEntries(VC)
            : this.acc
              ? [
                  { binding: 0, visibility: VC, buffer: ro },
                  { binding: 1, visibility: VC, buffer: ro },
                ]
              : []),
          ...(this.displaced && !this.cc ? lenderLayoutEntries(kind, VC) : []),
        ],
      }),
    };
    this.renderLayout = device.createPipelineLayout({
      label: 'instanced render',
      bindGroupLayouts: this.withSurface([this.layouts.mesh, this.layouts.bucket, this.layouts.frame]),
    });

    this.params = device.createBuffer({
      label: 'instanced params',
      size: INST_PARAMS.size,
      usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
    });
    this.drawArgs = device.createBuffer({
      label: 'instanced draw records',
      size: DRAW_ARGS_BYTES,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.INDIRECT | GPUBufferUsage.COPY_SRC,
    });
    this.indexBuffer = device.createBuffer({
      label: 'instanced pattern indices',
      size: this.patterns.indices.byteLength,
      usage: GPUBufferUsage.INDEX | GPUBufferUsage.COPY_DST,
    });
    device.queue.writeBuffer(this.indexBuffer, 0, this.patterns.indices);
    this.bucketUniform = device.createBuffer({
      label: 'instanced buckets',
      size: BUCKET_STRIDE * BUCKETS,
      usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
    });
    this.bucketGroup = device.createBindGroup({
      label: 'instanced bucket',
      layout: this.layouts.bucket,
      entries: [{ binding: 0, resource: { buffer: this.bucketUniform, size: INST_BUCKET.size } }],
    });
    this.frame = device.createBuffer({
      label: 'instanced frame',
      size: INST_FRAME.size,
      usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
    });
    this.frameGroup = device.createBindGroup({
      label: 'instanced frame',
      layout: this.layouts.frame,
      entries: [{ binding: 0, resource: { buffer: this.frame } }],
    });
  }

  /** A pipeline's bind group layouts, with the ACC or Catmull-Clark surface's at group 3. */
  private withSurface(groups: GPUBindGroupLayout[]): GPUBindGroupLayout[] {
    return this.acc || this.cc || this.displaced ? [...groups, this.layouts.surface] : groups;
  }

  /** Bind the ACC or Catmull-Clark surface's buffers (group 3), where there is one. */
  private bindSurface(pass: GPURenderPassEncoder | GPUComputePassEncoder): void {
    if (this.surfaceGroup) pass.setBindGroup(3, this.surfaceGroup);
  }

  /** Group 3's entries for the current mesh (ACC patches, or the lending tessellator's buffers;
   * with displacement on Phong and ACC, the lender's). */
  private surfaceEntries(): GPUBindGroupEntry[] {
    if (this.ccSource) return ccSurfaceEntries(this.ccSource);
    const acc = this.accPatches ? this.accPatches.surfaceEntries(0, 1) : [];
    const lender = this.dispSource ? lenderEntries(this.acc ? 'acc' : 'evalSurface', this.dispSource) : [];
    return [...acc, ...lender];
  }

  get instancedMesh(): InstancedMesh | undefined {
    return this.mesh?.m;
  }

  /** GPU memory held for the current mesh, in bytes: topology and patterns, cage, work (levels and
   * bucket lists), pattern indices, draw records and uniforms. */
  get gpuBytes(): number {
    const m = this.mesh;
    const own = [this.params, this.drawArgs, this.indexBuffer, this.bucketUniform, this.frame].reduce((a, b) => a + b.size, 0);
    return own + (m ? m.staticBuf.size + m.cageBuf.size + m.work.size : 0);
  }

  /** Upload a cage's patches (topology once; updateCage for new positions). With an ACC surface,
   * `source`: its AccPatches for the same cage (built here from the cage positions, and again by
   * updateCage); with the Catmull-Clark surface, a Catmull-Clark Tessellator holding the same
   * prepared mesh, flat baseline off, its Params uploaded (src/gpu/instanced/surface-cc.ts ccSurfaceTessellator):
   * its buffers are read by every pass, its patch build run by every encodeLevels. */
  setMesh(m: InstancedMesh, source?: AccPatches | Tessellator, lender?: Tessellator): void {
    const device = this.device;
    this.releaseMesh();
    const isTess = (s: AccPatches | Tessellator | undefined): s is Tessellator => s !== undefined && 'encodePatchBuild' in s;
    const acc = this.acc && !isTess(source) ? source : undefined;
    if (this.acc && !acc) throw new Error('InstancedTessellator: an ACC surface needs its AccPatches (setMesh(mesh, acc))');
    if (this.cc) {
      if (!isTess(source))
        throw new Error('InstancedTessellator: the Catmull-Clark surface needs a Catmull-Clark Tessellator (setMesh(mesh, tess))');
      checkCCSource(source, m.prepared);
    }
    // The displacement lender: the Catmull-Clark source itself, else the one given.
    const dispSource = this.displaced ? (this.cc && isTess(source) ? source : lender) : undefined;
    if (this.displaced) {
      if (!dispSource)
        throw new Error('InstancedTessellator: displacement needs a lending Tessellator (setMesh(mesh, source, displacementLender(…)))');
      checkLender(dispSource, m.prepared);
    }
    const pr = m.prepared;
    const entries = new Uint32Array(4 * BUCKETS);
    this.patterns.entries.forEach((e, b) => entries.set([e.baseVertex, e.firstIndex, e.indexCount, e.vertexCount], 4 * b));
    const parts = [pr.triVerts, m.patches, m.edgeOwner, this.patterns.ij, this.patterns.indices, entries];
    const offsets: number[] = [];
    let at = 0;
    for (const p of parts) {
      offsets.push(at);
      at += p.length;
    }
    const words = new Uint32Array(at);
    parts.forEach((p, i) => words.set(p, offsets[i]));
    const staticBuf = device.createBuffer({
      label: 'instanced topology + patterns',
      size: words.byteLength,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
    });
    device.queue.writeBuffer(staticBuf, 0, words);
    // Positions, normals, then the Phong surface's α per triangle edge (wgsl/instanced/common.wgsl).
    const cage = new Float32Array(6 * pr.vertexCount + 3 * pr.triangleCount);
    cage.set(pr.positions, 0);
    cage.set(pr.normals, 3 * pr.vertexCount);
    cage.set(pr.triPhongAlpha, 6 * pr.vertexCount);
    const cageBuf = device.createBuffer({
      label: 'instanced cage',
      size: Math.max(16, cage.byteLength),
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
    });
    device.queue.writeBuffer(cageBuf, 0, cage);
    if (this.acc && acc) {
      this.accPatches = acc;
      const enc = device.createCommandEncoder({ label: 'instanced ACC build' });
      acc.encode(enc, cageBuf);
      device.queue.submit([enc.finish()]);
    }
    if (this.cc && isTess(source)) this.ccSource = source;
    this.dispSource = dispSource;
    if (this.acc || this.cc || this.displaced)
      this.surfaceGroup = device.createBindGroup({
        label: this.cc ? 'instanced Catmull-Clark surface' : this.acc ? 'instanced ACC surface' : 'instanced displacement lender',
        layout: this.layouts.surface,
        entries: this.surfaceEntries(),
      });

    let w = 0;
    const take = (n: number) => {
      const at = w;
      w += n;
      return at;
    };
    const layout: WorkLayout = {
      wanted: take(m.patchCount),
      edgeCode: take(m.edgeCount),
      patchLevel: take(m.patchCount),
      counts: take(BUCKETS),
      lists: take(POW2_LEVEL_COUNT * m.patchCount),
      words: 0,
    };
    layout.words = w;
    const work = device.createBuffer({
      label: 'instanced work',
      size: 4 * layout.words,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST | GPUBufferUsage.COPY_SRC,
    });

    INST_PARAMS.write(new DataView(this.paramsBytes), {
      nPatches: m.patchCount,
      nQuads: m.quadCount,
      nTris: m.triCount,
      nEdges: m.edgeCount,
      offTriVerts: offsets[0],
      offPatches: offsets[1],
      offEdgeOwner: offsets[2],
      offPatternIJ: offsets[3],
      offPatternIdx: offsets[4],
      offEntries: offsets[5],
      offNormals: 3 * pr.vertexCount,
      offPhongAlpha: 6 * pr.vertexCount,
      offWanted: layout.wanted,
      offEdgeCode: layout.edgeCode,
      offPatchLevel: layout.patchLevel,
      offCounts: layout.counts,
      offLists: layout.lists,
    });

    // Each bucket's uniform: where its list starts and its pattern.

    const meshGroup = device.createBindGroup({
      label: 'instanced mesh',
      layout: this.layouts.mesh,
      entries: [this.params, staticBuf, cageBuf, work].map((buffer, binding) => ({ binding, resource: { buffer } })),
    });
    this.mesh = { m, staticBuf, cageBuf, work, layout, meshGroup };
    const buckets = new ArrayBuffer(BUCKET_STRIDE * BUCKETS);
    const lists = this.listBases();
    this.patterns.entries.forEach((_, b) => INST_BUCKET.write(new DataView(buckets, BUCKET_STRIDE * b), this.bucketFields(b, lists)));
    device.queue.writeBuffer(this.bucketUniform, 0, buckets);
  }

  /** New cage positions and vertex normals for the same topology (the Catmull-Clark surface's
   * lending tessellator gets them too; the next encodeLevels runs its patch build). */
  updateCage(positions: Float32Array, normals: Float32Array): void {
    const m = this.requireMesh();
    this.device.queue.writeBuffer(m.cageBuf, 0, positions);
    this.device.queue.writeBuffer(m.cageBuf, 12 * m.m.prepared.vertexCount, normals);
    // The Phong surface's α per edge follows the normals (phong.ts phongTriAlphas).
    this.device.queue.writeBuffer(m.cageBuf, 24 * m.m.prepared.vertexCount, phongTriAlphas(m.m.prepared, positions, normals));
    this.ccSource?.updateCage(positions, normals);
    if (this.accPatches) {
      const enc = this.device.createCommandEncoder({ label: 'instanced ACC build' });
      this.accPatches.encode(enc, m.cageBuf);
      this.device.queue.submit([enc.finish()]);
    }
  }

  /** Flat shading in the renderer's lit pass (the sample's "flat shading"): the vertex normal is
   * dropped and the lit shader shades each facet by its own normal. */
  setFlatShading(flat: boolean): void {
    INST_PARAMS.write(new DataView(this.paramsBytes), { flatShading: flat ? 1 : 0 });
    this.device.queue.writeBuffer(this.params, 0, this.paramsBytes);
  }

  /** Displacement settings (scale, mid-level, on/off), written into the lender's Params and
   * uploaded: the next draw or headless run displaces by them. */
  setDisplacement(settings: Partial<DisplacementSettings>): void {
    if (!this.dispSource)
      throw new Error('InstancedTessellator.setDisplacement: no displacement (options.displacement and a lender in setMesh)');
    setLenderDisplacement(this.dispSource, settings);
  }

  /** The levels of per-patch mode (one per patch, rounded down to a power of two in [1, 64]). */
  setWanted(levels: Uint32Array): void {
    const m = this.requireMesh();
    if (levels.length !== m.m.patchCount) throw new Error(`setWanted: ${levels.length} levels for ${m.m.patchCount} patches`);
    this.device.queue.writeBuffer(m.work, 4 * m.layout.wanted, levels);
  }

  /** Record the level, bucket and record passes (one compute pass; `timestampWrites` times it).
   * With the Catmull-Clark surface, the lending tessellator's patch build first (its own pass):
   * the dynamic rule and every draw after this read the refined points it writes. */
  encodeLevels(encoder: GPUCommandEncoder, lp: LevelParams, timestampWrites?: GPUComputePassTimestampWrites): void {
    const m = this.requireMesh();
    this.ccSource?.encodePatchBuild(encoder);
    INST_PARAMS.write(new DataView(this.paramsBytes), {
      viewProj: lp.viewProj ?? new Float32Array(16),
      viewport: [lp.viewport?.[0] ?? 1, lp.viewport?.[1] ?? 1, 0, 0],
      eye: [...(lp.eye ?? [0, 0, 0]), 0],
      pixelAngle: lp.pixelAngle ?? 1,
      mode: MODE[lp.mode],
      staticLevel: lp.level ?? LEVEL_DEFAULTS.level,
      lodScale: lp.lodScale ?? LEVEL_DEFAULTS.lodScale,
      targetPixels: lp.targetPixels ?? LEVEL_DEFAULTS.targetPixels,
      pixelError: lp.pixelError ?? LEVEL_DEFAULTS.pixelError,
    });
    this.device.queue.writeBuffer(this.params, 0, this.paramsBytes);
    // Edge codes and bucket counts start at 0 (atomicMax / atomicAdd).
    encoder.clearBuffer(m.work, 4 * m.layout.edgeCode, 4 * m.m.edgeCount);
    encoder.clearBuffer(m.work, 4 * m.layout.counts, 4 * BUCKETS);
    const cp = encoder.beginComputePass({ label: 'instanced levels', timestampWrites });
    const run = (name: keyof InstancedTessellator['levelPipelines'], groups: number, group: GPUBindGroup) => {
      cp.setPipeline(this.levelPipelines[name]);
      cp.setBindGroup(0, group);
      // The dynamic rule evaluates the surface: an ACC or Catmull-Clark surface's buffers (its
      // auto layout's group 3).
      if (name === 'edgeView' && (this.acc || this.cc)) cp.setBindGroup(3, this.edgeViewSurfaceGroup());
      // The factor rule reads the limit at the cage vertices on Catmull-Clark (group 3).
      if (name === 'edgeFactorRule' && this.cc) cp.setBindGroup(3, this.factorRuleSurfaceGroup());
      cp.dispatchWorkgroups(...grid2d(groups));
    };
    const nP = m.m.patchCount;
    if (lp.mode === 'dynamic') run('edgeView', Math.ceil(m.m.edgeCount / 64), this.levelGroupFor('edgeView'));
    else if (lp.mode === 'factor-rule') run('edgeFactorRule', Math.ceil(m.m.edgeCount / 64), this.levelGroupFor('edgeFactorRule'));
    else run('patchEdges', Math.ceil(nP / 64), this.levelGroupFor('patchEdges'));
    run('bucketPatches', Math.ceil(nP / 64), this.levelGroupFor('bucketPatches'));
    run('records', 1, this.levelGroupFor('records'));
    cp.end();
  }

  private factorRuleSurface?: GPUBindGroup;
  /** Group 3 of the factor rule on Catmull-Clark: its auto layout holds what it reads, the lending
   * tessellator's Params and cage arena (the vertex limits). */
  private factorRuleSurfaceGroup(): GPUBindGroup {
    this.factorRuleSurface ??= this.device.createBindGroup({
      label: 'instanced edgeFactorRule surface',
      layout: this.levelPipelines.edgeFactorRule.getBindGroupLayout(3),
      entries: this.surfaceEntries().filter((e) => e.binding === 0 || e.binding === 2),
    });
    return this.factorRuleSurface;
  }

  private edgeViewSurface?: GPUBindGroup;
  private edgeViewSurfaceGroup(): GPUBindGroup {
    this.edgeViewSurface ??= this.device.createBindGroup({
      label: 'instanced edgeView surface',
      layout: this.levelPipelines.edgeView.getBindGroupLayout(3),
      // The level pass evaluates the undisplaced surface: on ACC its patches only.
      entries: this.surfaceEntries().filter((e) => this.cc || e.binding < 2),
    });
    return this.edgeViewSurface;
  }

  // Auto layouts differ per entry point (each holds only the bindings it uses), so each level
  // pass gets its own bind group, made once per mesh.
  private levelGroups = new Map<string, GPUBindGroup>();
  private levelGroupFor(name: keyof InstancedTessellator['levelPipelines']): GPUBindGroup {
    const m = this.requireMesh();
    let g = this.levelGroups.get(name);
    if (!g) {
      const all: Record<number, GPUBuffer> = { 0: this.params, 1: m.staticBuf, 2: m.cageBuf, 3: m.work, 4: this.drawArgs };
      const used: Record<string, number[]> = {
        patchEdges: [0, 1, 3],
        // The cage buffer is read by the Phong surface; an ACC or Catmull-Clark surface reads its
        // own control points (group 3).
        edgeView: this.acc || this.cc ? [0, 1, 3] : [0, 1, 2, 3],
        // The cage's positions and normals, or on Catmull-Clark the lending tessellator's limits.
        edgeFactorRule: this.cc ? [0, 1, 3] : [0, 1, 2, 3],
        bucketPatches: [0, 1, 3],
        records: [0, 1, 3, 4],
      };
      g = this.device.createBindGroup({
        label: `instanced ${name}`,
        layout: this.levelPipelines[name].getBindGroupLayout(0),
        entries: used[name].map((binding) => ({ binding, resource: { buffer: all[binding] } })),
      });
      this.levelGroups.set(name, g);
    }
    return g;
  }

  /** What the last encodeLevels left on the GPU (checks): records, per-edge and per-patch
   * levels, each bucket's list of patches. */
  async readLevels(): Promise<{
    records: Uint32Array;
    counts: Uint32Array;
    edgeLevels: Uint32Array;
    patchLevels: Uint32Array;
    lists: Uint32Array[];
  }> {
    const m = this.requireMesh();
    const records = new Uint32Array(await readBuffer(this.device, this.drawArgs, 20 * BUCKETS));
    const w = new Uint32Array(await readBuffer(this.device, m.work, 4 * m.layout.words));
    const counts = Uint32Array.from({ length: BUCKETS }, (_, b) => w[m.layout.counts + b]);
    return {
      records,
      counts,
      edgeLevels: Uint32Array.from(w.subarray(m.layout.edgeCode, m.layout.edgeCode + m.m.edgeCount), (c) => 1 << (POW2_LEVEL_COUNT - c)),
      patchLevels: Uint32Array.from(w.subarray(m.layout.patchLevel, m.layout.patchLevel + m.m.patchCount), (lg) => 1 << lg),
      lists: this.listBases().map((base, b) => w.slice(base, base + counts[b])),
    };
  }

  /** The per-frame uniform of the lit and shadow passes. */
  writeFrame(f: {
    viewProj: Float32Array;
    lightViewProj?: Float32Array;
    toLight?: [number, number, number];
    eye: [number, number, number];
  }): void {
    const bytes = new ArrayBuffer(INST_FRAME.size);
    const l = f.toLight ?? [0.4, 0.8, 0.45];
    const n = Math.hypot(...l);
    INST_FRAME.write(new DataView(bytes), {
      viewProj: f.viewProj,
      lightViewProj: f.lightViewProj ?? f.viewProj,
      toLight: [l[0] / n, l[1] / n, l[2] / n, 0],
      eye: [...f.eye, 1],
    });
    this.device.queue.writeBuffer(this.frame, 0, bytes);
  }

  /** Draw every bucket into an open render pass: 'lit' (colour + depth, colorFormat/depthFormat)
   * or 'shadow' (depth only, from the frame's lightViewProj). Needs encodeLevels before, in an
   * earlier pass. */
  encodeDraw(pass: GPURenderPassEncoder, kind: 'lit' | 'shadow'): void {
    const m = this.requireMesh();
    pass.setPipeline(kind === 'lit' ? this.lit() : this.shadow());
    pass.setBindGroup(0, m.meshGroup);
    pass.setBindGroup(2, this.frameGroup);
    this.bindSurface(pass);
    pass.setIndexBuffer(this.indexBuffer, 'uint32');
    for (let b = 0; b < BUCKETS; b++) {
      pass.setBindGroup(1, this.bucketGroup, [BUCKET_STRIDE * b]);
      pass.drawIndexedIndirect(this.drawArgs, 20 * b);
    }
  }

  /** Made on first use (a page that only draws never compiles it). */
  private get headlessPipeline(): GPUComputePipeline {
    this.headlessPipelineMade ??= this.device.createComputePipeline({
      label: 'instanced headless',
      layout: this.device.createPipelineLayout({
        label: 'instanced headless',
        bindGroupLayouts: this.withSurface([this.layouts.mesh, this.layouts.bucket, this.layouts.out]),
      }),
      compute: {
        module: this.device.createShaderModule({ label: 'instanced headless', code: this.code(drawWgsl, headlessWgsl) }),
        entryPoint: 'headless',
      },
    });
    return this.headlessPipelineMade;
  }

  private drawFrameModule(): GPUShaderModule {
    this.frameModule ??= this.device.createShaderModule({ label: 'instanced draw', code: this.code(drawWgsl, frameWgsl) });
    return this.frameModule;
  }

  private lit(): GPURenderPipeline {
    // The existing renderer's lit state: triangle list, no culling (open surfaces), depth less.
    this.litPipeline ??= this.device.createRenderPipeline({
      label: 'instanced lit',
      layout: this.renderLayout,
      vertex: { module: this.drawFrameModule(), entryPoint: 'litVertex' },
      fragment: { module: this.drawFrameModule(), entryPoint: 'litFragment', targets: [{ format: this.colorFormat }] },
      primitive: { topology: 'triangle-list', cullMode: 'none', frontFace: 'ccw' },
      depthStencil: { format: this.depthFormat, depthWriteEnabled: true, depthCompare: 'less' },
      multisample: { count: this.sampleCount },
    });
    return this.litPipeline;
  }

  private shadow(): GPURenderPipeline {
    // The renderer's shadow state: depth only, slope-scaled bias against acne.
    this.shadowPipeline ??= this.device.createRenderPipeline({
      label: 'instanced shadow',
      layout: this.renderLayout,
      vertex: { module: this.drawFrameModule(), entryPoint: 'shadowVertex' },
      primitive: { topology: 'triangle-list', cullMode: 'none' },
      depthStencil: { format: this.depthFormat, depthWriteEnabled: true, depthCompare: 'less', depthBias: 2, depthBiasSlopeScale: 2.0 },
    });
    return this.shadowPipeline;
  }

  // ---- inside the demo renderer's passes (src/gpu/render/renderer.ts SurfaceDrawer) ------------------

  private inRenderer?: {
    res: ShadingResources;
    module: GPUShaderModule;
    /** Scene uniform only (the shadow pass: the shadow map is its attachment there). */
    sceneGroup: GPUBindGroup;
    /** Scene uniform, shadow map and sampler (the lit pass). */
    litGroup: GPUBindGroup;
    sceneLayout: GPUPipelineLayout;
    litLayout: GPUPipelineLayout;
    pipelines: Map<string, GPURenderPipeline>;
  };

  /**
   * Draw inside a Renderer's passes (drawShadow, drawLit, drawWire), with its scene uniform, shadow
   * map and lit shading (wgsl/render/instanced.wgsl prepends the renderer's own lit shader, its
   * bindings moved to group 2). Call again for another renderer.
   */
  useRenderer(res: ShadingResources): void {
    const device = this.device;
    const F = GPUShaderStage.FRAGMENT,
      VF = GPUShaderStage.VERTEX | F;
    const sceneBgl = device.createBindGroupLayout({
      label: 'instanced renderer scene',
      entries: [{ binding: 0, visibility: VF, buffer: { type: 'uniform' } }],
    });
    const litBgl = device.createBindGroupLayout({
      label: 'instanced renderer scene + shading',
      entries: [
        { binding: 0, visibility: VF, buffer: { type: 'uniform' } },
        { binding: 1, visibility: F, texture: { sampleType: 'depth' } },
        { binding: 2, visibility: F, sampler: { type: 'comparison' } },
      ],
    });
    // The renderer's lit shader: scene (0, 0), shadow map and sampler (1, 0–1), its patch colours'
    // buffers (2, 0–1, read by its own litVertex only) moved clear of this tessellator's groups
    // (to 3, 10–11: group 3 bindings 0–1 are an ACC surface's).
    const lit = rebind(RENDER_SHADERS.lit.join('\n'), { '0,0': [2, 0], '1,0': [2, 1], '1,1': [2, 2], '2,0': [3, 10], '2,1': [3, 11] });
    const layout = (label: string, g: GPUBindGroupLayout) =>
      device.createPipelineLayout({ label, bindGroupLayouts: this.withSurface([this.layouts.mesh, this.layouts.bucket, g]) });
    this.inRenderer = {
      res,
      module: device.createShaderModule({ label: 'instanced in the renderer', code: this.code(drawWgsl, lit, renderInstancedWgsl) }),
      sceneGroup: device.createBindGroup({
        label: 'instanced renderer scene',
        layout: sceneBgl,
        entries: [{ binding: 0, resource: { buffer: res.scene } }],
      }),
      litGroup: device.createBindGroup({
        label: 'instanced renderer scene + shading',
        layout: litBgl,
        entries: [
          { binding: 0, resource: { buffer: res.scene } },
          { binding: 1, resource: res.shadowMap },
          { binding: 2, resource: res.shadowSampler },
        ],
      }),
      sceneLayout: layout('instanced renderer (scene)', sceneBgl),
      litLayout: layout('instanced renderer (lit)', litBgl),
      pipelines: new Map(),
    };
  }

  /** The renderer-pass pipelines, made on first use, with the renderer's states: the faces
   * towards the light are culled in a closed cage's shadow pass; the lit pass draws the front
   * faces, or with `back` an open cage's back faces, depth-biased behind them (renderer.ts
   * meshFaceStates). */
  private rendererPipeline(kind: 'lit' | 'shadow' | 'wire', closed: boolean, back: boolean): GPURenderPipeline {
    const r = this.inRenderer!;
    const key = kind === 'lit' ? `lit ${back ? 'back' : 'front'} faces` : `${kind} ${closed ? 'closed' : 'open'}`;
    let p = r.pipelines.get(key);
    if (p) return p;
    const { module, res } = r;
    const device = this.device;
    const multisample = { count: res.sampleCount };
    if (kind === 'shadow')
      p = device.createRenderPipeline({
        label: `instanced shadow (${key})`,
        layout: r.sceneLayout,
        vertex: { module, entryPoint: 'instancedShadowVertex' },
        primitive: { topology: 'triangle-list', cullMode: closed ? 'front' : 'none', frontFace: 'ccw' },
        depthStencil: { format: res.depthFormat, depthWriteEnabled: true, depthCompare: 'less', depthBias: 2, depthBiasSlopeScale: 2.0 },
      });
    else if (kind === 'lit')
      p = device.createRenderPipeline({
        label: `instanced lit (${key})`,
        layout: r.litLayout,
        vertex: { module, entryPoint: 'instancedLitVertex' },
        fragment: { module, entryPoint: 'litFragment', targets: [{ format: res.colorFormat }] },
        ...meshFaceStates(back, res.depthFormat),
        multisample,
      });
    else
      p = device.createRenderPipeline({
        label: 'instanced wireframe',
        layout: r.sceneLayout,
        vertex: { module, entryPoint: 'instancedWireVertex' },
        fragment: {
          module,
          entryPoint: 'instancedWireFragment',
          targets: [
            {
              format: res.colorFormat,
              blend: {
                color: { srcFactor: 'src-alpha', dstFactor: 'one-minus-src-alpha', operation: 'add' },
                alpha: { srcFactor: 'one', dstFactor: 'one-minus-src-alpha', operation: 'add' },
              },
            },
          ],
        },
        primitive: { topology: 'line-list' },
        depthStencil: { format: res.depthFormat, depthWriteEnabled: false, depthCompare: 'less-equal' },
        multisample,
      });
    r.pipelines.set(key, p);
    return p;
  }

  private drawBuckets(pass: GPURenderPassEncoder, kind: 'lit' | 'shadow' | 'wire', closed: boolean, back = false): void {
    const m = this.mesh,
      r = this.inRenderer;
    if (!m || !r) return;
    pass.setPipeline(this.rendererPipeline(kind, closed, back));
    pass.setBindGroup(0, m.meshGroup);
    pass.setBindGroup(2, kind === 'lit' ? r.litGroup : r.sceneGroup);
    this.bindSurface(pass);
    if (kind !== 'wire') pass.setIndexBuffer(this.indexBuffer, 'uint32');
    for (let b = 0; b < BUCKETS; b++) {
      pass.setBindGroup(1, this.bucketGroup, [BUCKET_STRIDE * b]);
      if (kind === 'wire') pass.drawIndirect(this.drawArgs, WIRE_ARGS_OFFSET + 16 * b);
      else pass.drawIndexedIndirect(this.drawArgs, 20 * b);
    }
  }

  /** SurfaceDrawer: the shadow map pass (the surface evaluated again, from the light). */
  drawShadow(pass: GPURenderPassEncoder, closed: boolean): void {
    this.drawBuckets(pass, 'shadow', closed);
  }

  /** SurfaceDrawer: the lit pass (evaluated again, shaded as the renderer's stored mesh): the
   * front faces, then on an open cage its back faces (render/pipelines.ts meshFaceStates). */
  drawLit(pass: GPURenderPassEncoder, closed: boolean): void {
    this.drawBuckets(pass, 'lit', closed);
    if (!closed) this.drawBuckets(pass, 'lit', closed, true);
  }

  /** SurfaceDrawer: the wireframe overlay (every pattern triangle's edges, evaluated again). */
  drawWire(pass: GPURenderPassEncoder): void {
    this.drawBuckets(pass, 'wire', false);
  }

  /**
   * Run the vertex function over every instance of every bucket in compute and read the result
   * back (checks, `npm run tessellate -- --tessellator instanced`). Encodes the level passes
   * itself; reads the 14 bucket counts back first to size the outputs (a tool may read back; the
   * draw path never does).
   */
  async headless(lp: LevelParams): Promise<HeadlessInstanced> {
    const device = this.device;
    const m = this.requireMesh();
    device.pushErrorScope('validation');
    // GPU timestamps of the two passes (levels, evaluation), where the device has them.
    const timed = device.features.has('timestamp-query');
    const querySet = timed ? device.createQuerySet({ label: 'instanced headless timestamps', type: 'timestamp', count: 4 }) : undefined;
    let enc = device.createCommandEncoder({ label: 'instanced headless levels' });
    this.encodeLevels(enc, lp, querySet && { querySet, beginningOfPassWriteIndex: 0, endOfPassWriteIndex: 1 });
    device.queue.submit([enc.finish()]);
    const records = new Uint32Array(await readBuffer(device, this.drawArgs, 20 * BUCKETS));
    const counts = Uint32Array.from({ length: BUCKETS }, (_, b) => records[5 * b + 1]);

    const bases: { v: number; t: number }[] = [];
    let nv = 0,
      nt = 0;
    this.patterns.entries.forEach((e, b) => {
      bases.push({ v: nv, t: nt });
      nv += counts[b] * e.vertexCount;
      nt += (counts[b] * e.indexCount) / 3;
    });
    const limit = device.limits.maxStorageBufferBindingSize;
    const words = 9 * nv + 3 * nt;
    if (4 * words > limit) {
      throw new Error(
        `the headless output (${nv} vertices, ${nt} triangles) exceeds the device's storage binding limit (${limit} bytes): lower the levels`,
      );
    }
    const S = GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC;
    // One buffer (wgsl/instanced/headless.wgsl): 8 words per vertex (f32 bits), a patch per
    // vertex, then the indices.
    const out = device.createBuffer({ label: 'instanced headless output', size: Math.max(16, 4 * words), usage: S });
    const outGroup = device.createBindGroup({
      label: 'instanced headless output',
      layout: this.layouts.out,
      entries: [{ binding: 1, resource: { buffer: out } }],
    });
    // This run's bucket uniforms: the draw's, plus where each bucket's output goes.
    const bytes = new ArrayBuffer(BUCKET_STRIDE * BUCKETS);
    const uniform = device.createBuffer({
      label: 'instanced headless buckets',
      size: bytes.byteLength,
      usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
    });
    const group = device.createBindGroup({
      label: 'instanced headless bucket',
      layout: this.layouts.bucket,
      entries: [{ binding: 0, resource: { buffer: uniform, size: INST_BUCKET.size } }],
    });
    const lists = this.listBases();
    this.patterns.entries.forEach((_, b) => {
      INST_BUCKET.write(new DataView(bytes, BUCKET_STRIDE * b), {
        ...this.bucketFields(b, lists),
        outVertexBase: bases[b].v,
        outTriangleBase: bases[b].t,
        instances: counts[b],
        outVertexTotal: nv,
      });
    });
    device.queue.writeBuffer(uniform, 0, bytes);
    enc = device.createCommandEncoder({ label: 'instanced headless' });
    const cp = enc.beginComputePass({
      label: 'instanced headless',
      timestampWrites: querySet && { querySet, beginningOfPassWriteIndex: 2, endOfPassWriteIndex: 3 },
    });
    cp.setPipeline(this.headlessPipeline);
    cp.setBindGroup(0, m.meshGroup);
    this.bindSurface(cp);
    cp.setBindGroup(2, outGroup);
    this.patterns.entries.forEach((e, b) => {
      const threads = counts[b] * Math.max(e.vertexCount, e.indexCount / 3);
      if (!threads) return;
      cp.setBindGroup(1, group, [BUCKET_STRIDE * b]);
      cp.dispatchWorkgroups(...grid2d(Math.ceil(threads / WORKGROUP_SIZE)));
    });
    cp.end();
    const resolve = querySet
      ? device.createBuffer({
          label: 'instanced headless timestamps',
          size: 32,
          usage: GPUBufferUsage.QUERY_RESOLVE | GPUBufferUsage.COPY_SRC,
        })
      : undefined;
    if (querySet && resolve) enc.resolveQuerySet(querySet, 0, 4, resolve, 0);
    device.queue.submit([enc.finish()]);
    const error = await device.popErrorScope();
    if (error) throw new Error(`WebGPU validation error: ${error.message}`);
    const bytesOut = await readBuffer(device, out, 4 * words);
    const fv = new Float32Array(bytesOut, 0, 8 * nv),
      uw = new Uint32Array(bytesOut, 32 * nv);
    const positions = new Float32Array(3 * nv),
      normals = new Float32Array(3 * nv),
      uv = new Float32Array(2 * nv);
    for (let v = 0; v < nv; v++) {
      positions.set(fv.subarray(8 * v, 8 * v + 3), 3 * v);
      normals.set(fv.subarray(8 * v + 3, 8 * v + 6), 3 * v);
      uv.set(fv.subarray(8 * v + 6, 8 * v + 8), 2 * v);
    }
    const levels = await this.readLevels();
    const timings: Record<string, number> = {};
    if (resolve) {
      const ticks = new BigInt64Array(await readBuffer(device, resolve, 32));
      const span = (k: number) => Number(ticks[2 * k + 1] - ticks[2 * k]) / 1e6;
      if (span(0) >= 0) timings.levels = span(0);
      if (span(1) >= 0) timings.evaluate = span(1);
      resolve.destroy();
    }
    querySet?.destroy();
    for (const b of [out, uniform]) b.destroy();
    return {
      vertexCount: nv,
      triangleCount: nt,
      positions,
      normals,
      patch: uw.slice(0, nv),
      uv,
      indices: uw.slice(nv, nv + 3 * nt),
      counts,
      records,
      edgeLevels: levels.edgeLevels,
      patchLevels: levels.patchLevels,
      timings,
    };
  }

  /** Bucket b's pattern and patch list (INST_BUCKET fields shared by the draws and the headless pass). */
  private bucketFields(b: number, lists: number[]) {
    const e = this.patterns.entries[b];
    return {
      listBase: lists[b],
      level: e.level,
      domain: e.domain === 'tri' ? 1 : 0,
      baseVertex: e.baseVertex,
      firstIndex: e.firstIndex,
      vertexCount: e.vertexCount,
      triangleCount: e.indexCount / 3,
    };
  }

  private listBases(): number[] {
    const m = this.requireMesh();
    return Array.from({ length: BUCKETS }, (_, b) => {
      const lg = b % POW2_LEVEL_COUNT;
      return m.layout.lists + (b >= POW2_LEVEL_COUNT ? POW2_LEVEL_COUNT * m.m.quadCount + lg * m.m.triCount : lg * m.m.quadCount);
    });
  }

  private requireMesh() {
    if (!this.mesh) throw new Error('InstancedTessellator.setMesh must be called first');
    return this.mesh;
  }

  private releaseMesh(): void {
    if (!this.mesh) return;
    for (const b of [this.mesh.staticBuf, this.mesh.cageBuf, this.mesh.work]) b.destroy();
    this.levelGroups.clear();
    this.edgeViewSurface = undefined;
    this.factorRuleSurface = undefined;
    this.surfaceGroup = undefined;
    this.accPatches = undefined;
    this.ccSource = undefined;
    this.dispSource = undefined;
    this.mesh = undefined;
  }

  destroy(): void {
    this.releaseMesh();
    for (const b of [this.params, this.drawArgs, this.indexBuffer, this.bucketUniform, this.frame]) b.destroy();
  }
}

/**
 * The CLI's entry point (`npm run tessellate -- --tessellator instanced --level L | --adaptive`):
 * cage in, the headless output of the draw's own vertex function out. `--level L` is
 * { mode: 'static', level: L }; `--adaptive` is factorRuleLevels of the CLI's camera
 * (src/gpu/tess/headless.ts headlessCamera). Pass `tess` to reuse
 * compiled pipelines across calls, `instancedMesh` to reuse (or time) the CPU preparation;
 * `lender`: the displacement lender on Phong and ACC (src/gpu/instanced/displace-vertex.ts).
 */
export async function tessellateInstanced(
  device: GPUDevice,
  cage: Cage,
  prepared: PreparedMesh,
  lp: LevelParams,
  tess?: InstancedTessellator,
  instancedMesh?: InstancedMesh,
  surface?: AccPatches | Tessellator,
  lender?: Tessellator,
): Promise<{ mesh: InstancedMesh; out: HeadlessInstanced }> {
  const own = !tess;
  const t = tess ?? new InstancedTessellator(device);
  try {
    const mesh = instancedMesh ?? prepareInstanced(cage, prepared);
    t.setMesh(mesh, surface, lender);
    return { mesh, out: await t.headless(lp) };
  } finally {
    if (own) t.destroy();
  }
}
