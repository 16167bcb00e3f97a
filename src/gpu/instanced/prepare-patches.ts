/**
 * The instanced tessellator's CPU preparation of a cage: its patches (a quad face one quad patch,
 * any other face its prepared triangles as triangle patches), their edges and each edge's owner
 * (InstancedMesh, prepareInstanced), and the readers of a patch record (domain, edges, which
 * sides run canonically), and the check of a cage's buffers against a device's binding limit from
 * its face sizes, before any of that preparation (instancedBytesAtLeast, refuseInstancedOverLimit).
 */
import { INST_OWNER_WORD, INST_STATIC, INST_WORK, PATCH_WORDS } from './buffer-layouts.ts';
import { fannedRoundCentre, type PreparedMesh } from '../tess/prepare.ts';
import { LimitError } from '../../mesh/errors.ts';
import type { Cage } from '../../mesh/types.ts';
import { packPatterns, patternTriangleCount, patternVertexCount, type PatchDomain } from '../../pattern/pow2.ts';

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

/** Patches and their edges from a cage and its prepared triangulation (src/gpu/tess/prepare.ts). */
export function prepareInstanced(cage: Cage, prepared: PreparedMesh): InstancedMesh {
  const quads: { tri: number; face: number; c: number[] }[] = [];
  const tris: { tri: number; face: number; c: number[] }[] = [];
  // A quad is one patch (its first prepared triangle's id); every other face gives its prepared
  // triangles (a triangle itself, or the fan round an n-gon's centre) as triangle patches.
  let t = 0;
  for (let f = 0; f + 1 < cage.faceOffsets.length; f++) {
    const s = cage.faceOffsets[f],
      n = cage.faceOffsets[f + 1] - s;
    if (n < 3) continue;
    // A face without triangles: one the prepared mesh dropped (a hole, tagged or made by boundary
    // mode 'none': its triangles are in face order, so the next one is a later face's).
    if (t >= prepared.triangleCount || prepared.triFace[t] > f) continue;
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

/** The packed patterns' sizes in words (the same for every cage): made once, when first asked for. */
let patternWords: { ij: number; indices: number } | undefined;

/** Lower bounds, in bytes, of the instanced tessellator's buffers that grow with a cage. */
export interface InstancedBytes {
  /** staticBuf: the prepared triangles, the patch records, the edge owners, the patterns. */
  static: number;
  /** The work buffer: per patch its levels and a place in every level's list, per edge a code. */
  work: number;
  /** The headless output at a static level (9 words a vertex, 3 a triangle), 0 without a level. */
  output: number;
}

/**
 * Lower bounds of the instanced tessellator's buffers for `cage`, from its face sizes alone: a
 * quad is one patch (two prepared triangles), any other face its prepared triangles (n − 2, or n
 * round a centre), each a triangle patch; a patch has 3 or 4 edges and an edge borders at most two
 * patches. `level` (the CLI's --level, a power of two) gives every patch that pattern, so the
 * headless output is known too. Computed before prepareMesh and prepareInstanced, which for
 * millions of faces take most of a minute and gigabytes before the exact sizes are known.
 */
export function instancedBytesAtLeast(cage: Cage, level?: number): InstancedBytes {
  const holes = new Set(cage.holes);
  let quads = 0,
    tris = 0,
    triangles = 0;
  for (let f = 0; f + 1 < cage.faceOffsets.length; f++) {
    const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
    if (holes.has(f) || n < 3) continue;
    const cut = fannedRoundCentre(n) ? n : n - 2;
    triangles += cut;
    if (n === 4) quads++;
    else tris += cut;
  }
  const patches = quads + tris;
  const edges = Math.ceil((4 * quads + 3 * tris) / 2);
  patternWords ??= (({ ij, indices }) => ({ ij: ij.length, indices: indices.length }))(packPatterns());
  const staticWords = INST_STATIC.layout({
    triangles,
    patches,
    edges,
    patternIJWords: patternWords.ij,
    patternIndices: patternWords.indices,
  }).words;
  const workWords = INST_WORK.layout({ patches, edges }).words;
  let outputWords = 0;
  if (level !== undefined)
    for (const [domain, count] of [
      ['quad', quads],
      ['tri', tris],
    ] as [PatchDomain, number][])
      outputWords += count * (9 * patternVertexCount(domain, level) + 3 * patternTriangleCount(domain, level));
  return { static: 4 * staticWords, work: 4 * workWords, output: 4 * outputWords };
}

const mib = (bytes: number) => `${(bytes / 1024 / 1024).toFixed(1)} MiB`;

/** Throws a LimitError when one of the instanced tessellator's buffers for `cage` (at `level`,
 * when static) would exceed `bindingLimit` (the device's maxStorageBufferBindingSize): every one
 * is bound whole, so such a cage cannot be drawn on this device at all. Cheap: face sizes only. */
export function refuseInstancedOverLimit(cage: Cage, bindingLimit: number, level?: number): void {
  const least = instancedBytesAtLeast(cage, level);
  const faces = cage.faceOffsets.length - 1;
  const over = (bytes: number, what: string, todo: string) => {
    if (bytes > bindingLimit)
      throw new LimitError(
        `${faces} faces need at least ${mib(bytes)} for the instanced tessellator's ${what}, more than this device's ${mib(bindingLimit)} binding limit: ${todo}`,
      );
  };
  over(least.static, 'patch records', 'the cage is too large for this GPU');
  over(least.work, 'level lists', 'the cage is too large for this GPU');
  over(least.output, `output at --level ${level}`, 'lower --level');
}
