/**
 * Displacement in the instanced tessellator (src/gpu/instanced/instanced.ts; issue 12): every vertex the
 * draw evaluates is moved along its normal by the height map in the same vertex function, on every
 * surface (Phong, the ACC schemes, the exact Catmull-Clark limit).
 *
 * Design.
 * 1. Data: nothing is packed twice. A LENDING compute Tessellator holds the displacement arenas
 *    (src/gpu/tess/displacement-map.ts: TESS_STATIC heightTexels, dispTri, TESS_CAGE cornerUvs, Params
 *    dispOn, dispScale, …) exactly as the compute tessellator uses them, plus the owners of every
 *    edge and vertex (TESS_STATIC triEdges, edgeOwner, vertexOwner). On the exact limit
 *    ('lent-limit') the lender is the borrowed Catmull-Clark tessellator itself
 *    (src/gpu/instanced/surface-cc.ts ccSurfaceTessellator(device, prepared, cc, displacement)); on Phong and ACC a
 *    minimal Phong tessellator (displacementLender: the smallest tables and output). Group 3 then
 *    holds: Phong, the lender's Params (uniform), static and cage (bindings 0–2); ACC, its patches
 *    and control points (0, 1) and the lender's three (2–4); Catmull-Clark, unchanged (0–3).
 *    Storage buffers per stage (InstancedTessellator's constructor refuses a device with fewer):
 *    vertex stage Phong 3 + 2 = 5, ACC 3 + 2 + 2 = 7, Catmull-Clark 6; the headless compute pass
 *    one more (its single output buffer): 6, 8, 7, within core WebGPU's 8.
 * 2. WGSL: wgsl/tess/displace.wgsl (the compute tessellator's own displacePoint, unchanged) appended to
 *    the instanced modules with params → ccParams, staticBuf → ccStatic, cageBuf → ccCage (the
 *    rename helper of src/gpu/instanced/surface-cc.ts, renameBorrowed, one list for both borrowers), so it reads
 *    the lender's arenas. The vertex function (and the headless compute pass, which runs the same
 *    function) evaluates wgsl/instanced/displace.wgsl vertexSurface: pattern point → cage triangle
 *    and 16.16 weights (patchTriangle) → the OWNER of the point (below) → the surface there
 *    (triSurface: Phong's evalSurface, the Catmull-Clark evaluator, or on ACC the face's patch at
 *    the triangle's (u, v) with its tangents carried to the triangle's w-space by the fan:
 *    wgsl/instanced/displace-acc.wgsl) → displacePoint when the lender's dispOn is set.
 * 3. Seam rule (crack-free by construction, as the compute tessellator's weld,
 *    wgsl/tess/weld.wgsl): a pattern point on a cage edge (one weight 0) or at a cage vertex (one
 *    weight ONE) is evaluated through the owner triangle of that edge or vertex (the lender's
 *    edgeOwner / vertexOwner: the first triangle that has it, prepare.ts), the weights rebuilt
 *    from the same integers (on an edge, the weight of its higher vertex). Both patches sharing
 *    the point compute the identical function of identical integer inputs, so the two copies of
 *    every boundary point are bit-identical with or without displacement, and UV seams and sharp
 *    creases (where the two faces' uvs or normals differ) cannot crack. The point is also the one
 *    the compute tessellator writes there (its weld uses the same owner and weights).
 *    ownerPoint below is the CPU twin (for checks).
 */
import displaceWgsl from '../../../wgsl/tess/displace.wgsl?raw';
import vertexWgsl from '../../../wgsl/instanced/displace.wgsl?raw';
import accTriWgsl from '../../../wgsl/instanced/displace-acc.wgsl?raw';
import { DISP_TRI_WORD, OWNER_WORD, TESS_PARAMS } from '../contract/tess.ts';
import { renameBorrowed, uploadLenderParams } from './surface-cc.ts';
import { ONE } from '../../pattern/fixed.ts';
import { Tessellator } from '../tess/tessellator.ts';
import { bakeTables } from '../../pattern/tables.ts';
import type { DisplacementData, DisplacementSettings } from '../tess/displacement-map.ts';
import type { PreparedMesh } from '../tess/prepare.ts';

import type { InstancedSurfaceKind } from './instanced-options.ts';

/** What an InstancedTessellator with displacement appends to its modules on `surface`. */
export function instancedDisplaceWgsl(surface: InstancedSurfaceKind): string {
  const parts: string[] = [];
  // The lender's Params struct (the Catmull-Clark surface module already has it). Its buffers are
  // bound in the surface group as ccParams, ccStatic and ccCage (src/gpu/instanced/buffer-layouts.ts
  // INST_SURFACE_GROUP), the names the exact surface's borrowed buffers have, so one rename list
  // (surface-cc.ts RENAMES) serves both.
  if (surface !== 'lent-limit') parts.push(TESS_PARAMS.wgsl);
  parts.push(
    OWNER_WORD.wgsl,
    DISP_TRI_WORD.wgsl,
    renameBorrowed(displaceWgsl, ['params', 'staticBuf', 'cageBuf'], 'instancedDisplaceWgsl'),
    vertexWgsl,
  );
  if (surface === 'acc') parts.push(accTriWgsl);
  return parts.join('\n');
}

/** Throws unless `tess` can lend displacement arenas for `prepared`'s triangles. */
export function checkLender(tess: Tessellator, prepared: PreparedMesh): void {
  const own = tess.prepared;
  if (!own) throw new Error('instanced displacement needs a lending Tessellator with the mesh set');
  const same =
    own === prepared ||
    (own.vertexCount === prepared.vertexCount &&
      own.triangleCount === prepared.triangleCount &&
      own.triVerts.every((v, i) => v === prepared.triVerts[i]));
  if (!same) throw new Error('the lending Tessellator holds another mesh than the instanced one');
}

/**
 * A compute Tessellator (Phong) that only lends its displacement arenas to an instanced
 * tessellator on Phong or ACC: the smallest tables and output, one rebuild at factor 1 to upload
 * its Params. `displacement`: prepareDisplacement(cage, prepared, map, wrap); without it the
 * lender gives the owners only (dispOn off: the seam rule still holds, nothing moves). Caller owns it.
 */
export function displacementLender(
  device: GPUDevice,
  prepared: PreparedMesh,
  displacement: DisplacementData | undefined,
  settings?: Partial<DisplacementSettings>,
): Tessellator {
  const tess = Tessellator.create(device, bakeTables(2), {
    surface: 'phong',
    vertexCapacity: prepared.vertexCount + prepared.edgeCount,
    triangleCapacity: prepared.triangleCount,
  });
  tess.setMesh(prepared, undefined, undefined, displacement);
  if (settings) tess.setDisplacement(settings);
  uploadLenderParams(tess);
  return tess;
}

/** New displacement settings on a lender (Tessellator.setDisplacement uploads its uniforms; no rebuild). */
export function setLenderDisplacement(tess: Tessellator, settings: Partial<DisplacementSettings>): void {
  tess.setDisplacement(settings);
}

/** The CPU twin of wgsl/instanced/displace.wgsl ownerPoint: the triangle and 16.16 weights a
 * pattern point at (t, w) is evaluated at. */
export function ownerPoint(prepared: PreparedMesh, t: number, w: readonly number[]): { t: number; w: [number, number, number] } {
  const tv = (tri: number, i: number) => prepared.triVerts[3 * tri + i];
  for (let k = 0; k < 3; k++) {
    if (w[k] !== ONE) continue;
    const o = OWNER_WORD.unpack(prepared.vertexOwner[tv(t, k)]);
    const ow: [number, number, number] = [0, 0, 0];
    ow[o.corner] = ONE;
    return { t: o.tri, w: ow };
  }
  for (let k = 0; k < 3; k++) {
    if (w[k] !== 0) continue;
    const i = (k + 1) % 3,
      j = (i + 1) % 3;
    const a = tv(t, i),
      b = tv(t, j);
    const x = b > a ? w[j] : w[i];
    const hi = Math.max(a, b);
    const o = OWNER_WORD.unpack(prepared.edgeOwner[prepared.triEdges[3 * t + i]]);
    const oi = o.corner,
      oj = (oi + 1) % 3;
    const ow: [number, number, number] = [0, 0, 0];
    const atI = tv(o.tri, oi) === hi;
    ow[oi] = atI ? x : ONE - x;
    ow[oj] = atI ? ONE - x : x;
    return { t: o.tri, w: ow };
  }
  return { t, w: [w[0], w[1], w[2]] };
}
