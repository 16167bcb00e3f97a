/**
 * An ACC scheme as the compute tessellator's surface (Tessellator surface 'bezier-acc',
 * 'gregory-acc' or 'pm-acc'): the patches and their per-frame build (src/gpu/acc/patches.ts AccPatches)
 * and, per prepared triangle, its patch and its corners' patch parameters (contract/tess.ts
 * ACC_TRI_WORD), which wgsl/acc/surface-tess.wgsl interpolates by the point's weights.
 */
import type { Cage } from '../../mesh/types.ts';
import { KIND_REGULAR, type AccOptions, type AccScheme } from '../../subdiv/acc.ts';
import { AccPatches, accFaceParam } from './patches.ts';
import { ACC_TRI_CORNERS, ACC_TRI_WORD } from '../contract/tess.ts';
import type { PreparedMesh } from '../tess/prepare.ts';

export interface AccSurface {
  patches: AccPatches;
  /** ACC_TRI_WORD per prepared triangle. */
  triangles: Uint32Array;
}

/** Throws AccError (src/subdiv/acc.ts) for cages the scheme does not take (e.g. n-gons). */
export function prepareAccSurface(device: GPUDevice, cage: Cage, mesh: PreparedMesh, scheme: AccScheme, options?: AccOptions): AccSurface {
  const patches = new AccPatches(device, cage, scheme, undefined, options);
  return { patches, triangles: accTriangleWords(mesh, cage) };
}

/** ACC_TRI_WORD per prepared triangle: its face and the (u, v) of its corners (accFaceParam). */
export function accTriangleWords(mesh: PreparedMesh, cage: Cage): Uint32Array {
  const out = new Uint32Array(mesh.triangleCount);
  for (let t = 0; t < mesh.triangleCount; t++) {
    let face = 0;
    const uv: number[] = [];
    for (let i = 0; i < 3; i++) {
      const w: [number, number, number] = [0, 0, 0];
      w[i] = 1;
      const [f, u, v] = accFaceParam(mesh, cage, t, w);
      face = f;
      uv.push(u, v);
    }
    const corners = ACC_TRI_CORNERS.pack({ u0: uv[0], v0: uv[1], u1: uv[2], v1: uv[3], u2: uv[4], v2: uv[5] });
    out[t] = ACC_TRI_WORD.pack({ corners, face });
  }
  return out;
}

/**
 * The patch colours' kind (src/gpu/contract/render.ts PATCH_COLOURS: 0 regular, 1 irregular quad,
 * 2 triangle) of every prepared triangle on an ACC surface, the NVIDIA sample's "show irregular
 * patches": a regular patch is the plain bicubic (KIND_REGULAR), every other quad an irregular
 * one, and triangles (Gregory or Pm triangles) their own colour.
 */
export function accPatchKinds(acc: AccSurface, mesh: PreparedMesh): Uint8Array {
  const topo = acc.patches.topology;
  const out = new Uint8Array(mesh.triangleCount);
  for (let t = 0; t < mesh.triangleCount; t++) {
    const f = mesh.triFace[t];
    out[t] = topo.faceSize[f] === 3 ? 2 : topo.patches[2 * f] === KIND_REGULAR ? 0 : 1;
  }
  return out;
}
