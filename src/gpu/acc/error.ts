/**
 * The data of the ACC "error view" (issue 10): per point of the tessellator's kind (cage triangle t,
 * fixed-point barycentric weights w1, w2 of its corners 1 and 2, w0 = 65536 − w1 − w2: what every
 * output vertex carries), the distance from the ACC surface (wgsl/acc/surface.wgsl evalAccPatch)
 * to the exact Catmull-Clark limit (wgsl/cc/surface.wgsl evalSurface, called, not changed) at the
 * same cage parameter, and the angle between their normals, both on the GPU in one compute pass.
 *
 * The ACC parameter of (t, w) is linear in w (src/gpu/acc/patches.ts accFaceParam): a per-triangle table
 * holds the triangle's face and the ACC (u, v) of its three corners (0 or 1 each), so the pass maps
 * (t, w) → (face, u, v) itself and can run over the tessellator's output vertices as they are.
 *
 * Needs a Catmull-Clark tessellator whose encode() has been submitted for the same cage (its
 * uniforms and patch build current) and an AccPatches whose build has run from the same positions.
 * Output: 2 f32 per point, distance (model units) and angle (degrees; 0 where either normal is 0).
 */
import commonWgsl from '../../../wgsl/tess/common.wgsl?raw';
import { CC_SURFACE_WGSL as ccSurfaceWgsl } from '../cc/shaders.ts';
import { groupsFor } from '../contract/constants.ts';
import { TESS_INPUTS } from '../contract/tess.ts';
import { tessPrelude } from '../contract/contract.ts';
import type { Cage } from '../../mesh/index.ts';
import { ACC_SURFACE_WGSL, type AccPatches, accBindingsWgsl } from './patches.ts';
import { accTriangleWords } from './surface.ts';
import type { PreparedMesh } from '../tess/prepare.ts';
import { readBuffer } from '../device/readback.ts';
import type { Tessellator } from '../tess/tessellator.ts';
import { surfaceScheme } from '../surface/registry.ts';
import { tessInputEntries } from '../tess/sample-surface.ts';
import { ACC_ERROR_GROUP, accSurfaceGroup } from '../contract/acc.ts';

// Its own bindings: ACC_ERROR_GROUP (errIn, errOut, accTriMap), beside the tessellator's inputs.
const KERNEL = /* wgsl */ `
@compute @workgroup_size(WORKGROUP_SIZE)
fn accErrors(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let i = (wid.y * GRID_X + wid.x) * WORKGROUP_SIZE + lid;
  if (i >= arrayLength(&errIn) / 3u) { return; }
  let t = errIn[3u * i];
  let w1 = errIn[3u * i + 1u];
  let w2 = errIn[3u * i + 2u];
  let exact = evalSurface(t, vec3<u32>(ONE - w1 - w2, w1, w2));
  let m = accTriMap[t];
  let w = vec3<f32>(f32(ONE - w1 - w2), f32(w1), f32(w2)) / 65536.0;
  let c = accTriWord_corners(m);
  let uc = vec3<f32>(f32(accTriCorners_u0(c)), f32(accTriCorners_u1(c)), f32(accTriCorners_u2(c)));
  let vc = vec3<f32>(f32(accTriCorners_v0(c)), f32(accTriCorners_v1(c)), f32(accTriCorners_v2(c)));
  let a = evalAccPatch(accTriWord_face(m), dot(w, uc), dot(w, vc));
  errOut[2u * i] = length(a.pos - exact.pos);
  // atan2(|n × m|, n · m): accurate near 0 (acos is not in f32).
  errOut[2u * i + 1u] = degrees(atan2(length(cross(a.normal, exact.normal)), dot(a.normal, exact.normal)));
}
`;

const pipelines = new WeakMap<GPUDevice, GPUComputePipeline>();

/** Per cage triangle: its face and the ACC (u, v) of its corners (contract/tess.ts ACC_TRI_WORD:
 * face << 6 | bit 2i: u_i, bit 2i + 1: v_i), as the compute tessellator's ACC surface reads them. */
export function accTriangleMap(mesh: PreparedMesh, cage: Cage): Uint32Array {
  return mesh.triangleCount ? accTriangleWords(mesh, cage) : new Uint32Array(1);
}

export class AccErrorView {
  readonly triMap: GPUBuffer;
  private readonly pipeline: GPUComputePipeline;

  constructor(
    readonly device: GPUDevice,
    readonly acc: AccPatches,
    mesh: PreparedMesh,
    cage: Cage,
  ) {
    const map = accTriangleMap(mesh, cage);
    this.triMap = device.createBuffer({
      label: 'acc error triangle map',
      size: map.byteLength,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
    });
    device.queue.writeBuffer(this.triMap, 0, map);
    let pipe = pipelines.get(device);
    if (!pipe) {
      const code = [
        tessPrelude(TESS_INPUTS),
        commonWgsl,
        ccSurfaceWgsl,
        accBindingsWgsl(1, 0),
        ACC_ERROR_GROUP.wgsl(),
        ACC_SURFACE_WGSL,
        KERNEL,
      ].join('\n');
      const module = device.createShaderModule({ label: 'acc errors', code });
      pipe = device.createComputePipeline({ label: 'acc errors', layout: 'auto', compute: { module, entryPoint: 'accErrors' } });
      pipelines.set(device, pipe);
    }
    this.pipeline = pipe;
  }

  /** Record the pass over `count` points of `input` ((t, w1, w2) u32 each) into `output` (2 f32 each). */
  encode(encoder: GPUCommandEncoder, tess: Tessellator, input: GPUBuffer, output: GPUBuffer, count: number): void {
    if (!surfaceScheme(tess.surface).exactLimit) throw new Error('the error view needs the Catmull-Clark tessellator (the exact surface)');
    const g0 = this.device.createBindGroup({
      label: 'acc errors',
      layout: this.pipeline.getBindGroupLayout(0),
      entries: [
        ...tessInputEntries(tess, TESS_INPUTS),
        { binding: ACC_ERROR_GROUP.binding.errIn, resource: { buffer: input } },
        { binding: ACC_ERROR_GROUP.binding.errOut, resource: { buffer: output } },
        { binding: ACC_ERROR_GROUP.binding.accTriMap, resource: { buffer: this.triMap } },
      ],
    });
    const g1 = this.device.createBindGroup({
      label: 'acc errors (patches)',
      layout: this.pipeline.getBindGroupLayout(1),
      entries: this.acc.surfaceEntries(accSurfaceGroup(1, 0)),
    });
    const pass = encoder.beginComputePass({ label: 'acc errors' });
    pass.setPipeline(this.pipeline);
    pass.setBindGroup(0, g0);
    pass.setBindGroup(1, g1);
    pass.dispatchWorkgroups(...groupsFor(count));
    pass.end();
  }

  /** Distances and angles (degrees) at the given points (checks, the CLI). */
  async measure(
    tess: Tessellator,
    points: { t: number; w1: number; w2: number }[],
  ): Promise<{ dist: Float32Array; angleDeg: Float32Array }> {
    const n = points.length,
      device = this.device;
    const words = new Uint32Array(3 * Math.max(1, n));
    points.forEach((p, i) => words.set([p.t, p.w1, p.w2], 3 * i));
    const input = device.createBuffer({
      label: 'acc error points',
      size: words.byteLength,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
    });
    device.queue.writeBuffer(input, 0, words);
    const output = device.createBuffer({
      label: 'acc error results',
      size: 8 * Math.max(1, n),
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC,
    });
    const enc = device.createCommandEncoder({ label: 'acc errors' });
    this.encode(enc, tess, input, output, n);
    device.queue.submit([enc.finish()]);
    const r = new Float32Array(await readBuffer(device, output, 8 * n));
    input.destroy();
    output.destroy();
    const dist = new Float32Array(n),
      angleDeg = new Float32Array(n);
    for (let i = 0; i < n; i++) {
      dist[i] = r[2 * i];
      angleDeg[i] = r[2 * i + 1];
    }
    return { dist, angleDeg };
  }

  destroy(): void {
    this.triMap.destroy();
  }
}
