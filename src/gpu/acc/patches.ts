/**
 * ACC patches on the GPU (Bezier, Gregory and Pm ACC): the buffers and the compute pass that builds
 * every patch's control points from the current cage positions (wgsl/acc/build.wgsl), and what the
 * surface evaluator (wgsl/acc/surface.wgsl, evalAccPatch) needs to read them.
 *
 * The CPU half (src/subdiv/acc.ts buildAccTopology, once per topology, linear time) derives the
 * construction topology; the layouts are written down at the top of that file. Buffers:
 *
 *   accPatches (storage, 2 u32 per patch = cage face)   kind, first control point     [build: read; surface: read]
 *   accPoints  (storage, vec4<f32> per control point)   xyz, w unused                 [build: write; surface: read]
 *   accStatic  (storage, u32)                           the sections of ACC_STATIC (src/gpu/contract/acc.ts), at the offsets of accParams:
 *     corners   8 per patch: (cage vertex, rotation in its ring) × 4
 *     ringOffs  nVerts + 1;  ringData: per vertex e_0..e_{n−1}, d_0..d_{n−1} (d = TRI_FACE for triangles)
 *     valOffs   per valence n ≤ max valence: start of its constants in valData
 *     valData   f32 bits, per valence: cos(2π/n), sin(2π/n), λ_n, s_n, α[n], β[n], cos(2πk/n)[n]
 *     sectors   4 per patch: each corner's sector (crease / corner / cone; src/subdiv/acc.ts)
 *     secOffs   per crease/corner sector size k: start of its constants in secData (2k + corner?)
 *     secData   f32 bits, per sector kind: cos θ, sin θ, n', ca[0..k], cb[0..k], crease mask
 *     order     nPatches: the patch each build thread takes (patches sorted by kind)
 *   accParams  (uniform, ACC_BUILD_PARAMS)              nPatches and the section offsets
 *
 * encode(encoder, cageBuffer): the cage buffer holds xyz f32 per cage vertex from offset 0 (the
 * tessellator's cage buffer starts so); one thread per patch. Nothing else has to re-run when the
 * cage deforms.
 */
import buildWgsl from '../../../wgsl/acc/build.wgsl?raw';
import surfaceWgsl from '../../../wgsl/acc/surface.wgsl?raw';
import type { Cage, Topology } from '../../mesh/index.ts';
import {
  ACC_DEGENERATE_SIN,
  ACC_DEGENERATE_STEP,
  type AccOptions,
  type AccScheme,
  type AccTopology,
  KIND_POINTS,
  buildAccTopology,
  sectorTable,
  valenceTable,
} from '../../subdiv/acc.ts';
import { readBuffer } from '../device/readback.ts';
import { constantsWgsl, groupsFor } from '../contract/constants.ts';
import { ACC_BUILD_GROUP, ACC_BUILD_PARAMS, ACC_SAMPLE_GROUP, ACC_STATIC, accSurfaceGroup, type AccSection } from '../contract/acc.ts';
import { accBuildPrelude } from '../contract/contract.ts';
import { wgslF32 } from '../contract/define.ts';
import { faceParam } from '../tess/face-params.ts';
import type { PreparedMesh } from '../tess/prepare.ts';

/** Declarations of the two buffers wgsl/acc/surface.wgsl reads, at the includer's group from binding `first` (contract/acc.ts accSurfaceGroup),
 * and the two accessors it reads them through (the compute tessellator defines the accessors over
 * its own buffers instead: wgsl/acc/surface-tess.wgsl). */
export function accBindingsWgsl(group: number, first: number): string {
  return accSurfaceGroup(group, first).wgsl() + ACC_ACCESSORS_WGSL;
}

/** The two accessors wgsl/acc/surface.wgsl reads its buffers through, over `accPatches` and
 * `accPoints` however they are bound. */
export const ACC_ACCESSORS_WGSL = `fn accPatchWord(i: u32) -> u32 { return accPatches[i]; }
fn accPt(i: u32) -> vec3<f32> { return accPoints[i].xyz; }
`;

/** The evaluator's WGSL (append after accBindingsWgsl). */
export const ACC_SURFACE_WGSL: string = [
  `const ACC_DEGENERATE_SIN: f32 = ${wgslF32(ACC_DEGENERATE_SIN)};`,
  `const ACC_DEGENERATE_STEP: f32 = ${wgslF32(ACC_DEGENERATE_STEP)};`,
  surfaceWgsl,
].join('\n');

/**
 * The ACC parameter (face, u, v) of the tessellator's point (triangle t, weights w): quads as
 * face-params.ts (the 0–2 diagonal split), triangles (u, v) = the weights of face corners 1 and 2.
 * The exact reference takes the same point through faceParam, so errors are measured at one parameter.
 */
export function accFaceParam(mesh: PreparedMesh, cage: Cage, t: number, w: readonly [number, number, number]): [number, number, number] {
  const face = mesh.triFace[t];
  const start = cage.faceOffsets[face],
    m = cage.faceOffsets[face + 1] - start;
  if (m === 4) {
    const fp = faceParam(mesh, cage, t, w);
    if (!('u' in fp)) throw new Error('quad without (u, v)');
    return [face, fp.u, fp.v];
  }
  if (m !== 3) throw new Error(`face ${face} has ${m} corners: no ACC patch`);
  const W = [0, 0, 0];
  for (let i = 0; i < 3; i++) {
    const v = mesh.triVerts[3 * t + i];
    const k = [0, 1, 2].find((j) => cage.faceIndices[start + j] === v);
    if (k === undefined) throw new Error(`triangle ${t} is not on face ${face}`);
    W[k] += w[i];
  }
  return [face, W[1], W[2]];
}

const buildPipelines = new WeakMap<GPUDevice, GPUComputePipeline>();
const samplePipelines = new WeakMap<GPUDevice, GPUComputePipeline>();

export class AccPatches {
  readonly topology: AccTopology;
  readonly patchBuffer: GPUBuffer;
  readonly pointBuffer: GPUBuffer;
  readonly staticBuffer: GPUBuffer;
  readonly paramsBuffer: GPUBuffer;
  private readonly pipeline: GPUComputePipeline;
  private group: GPUBindGroup | undefined;
  private groupCage: GPUBuffer | undefined;

  /** Throws AccError (src/subdiv/acc.ts) for cages the schemes do not support (n-gons, holes). */
  constructor(
    readonly device: GPUDevice,
    cage: Cage,
    readonly scheme: AccScheme,
    topology?: Topology,
    options: AccOptions = {},
  ) {
    const T = (this.topology = buildAccTopology(cage, scheme, topology, options));
    const vt = valenceTable(T.maxValence);
    const st = sectorTable(T.maxSector);
    // Threads take the patches grouped by kind, so a workgroup runs one construction (no divergence).
    const order = Uint32Array.from([...Array(T.nPatches).keys()].sort((a, b) => T.patches[2 * a] - T.patches[2 * b] || a - b));
    const sections: Record<AccSection, Uint32Array> = {
      corners: T.corners,
      ringOffs: T.ringOffs,
      ringData: T.ringData,
      valOffs: vt.offsets,
      valData: new Uint32Array(vt.values.buffer),
      sectors: T.sectors,
      secOffs: st.offsets,
      secData: new Uint32Array(st.values.buffer),
      order,
    };
    const layout = ACC_STATIC.layout(
      Object.fromEntries(ACC_STATIC.names.map((k) => [k, sections[k].length])) as Record<AccSection, number>,
    );
    const words = new Uint32Array(Math.max(1, layout.words));
    for (const k of ACC_STATIC.names) words.set(sections[k], layout.offset[k]);
    const storage = GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST | GPUBufferUsage.COPY_SRC;
    this.staticBuffer = device.createBuffer({ label: `acc ${scheme} build topology`, size: words.byteLength, usage: storage });
    device.queue.writeBuffer(this.staticBuffer, 0, words);
    this.patchBuffer = device.createBuffer({ label: `acc ${scheme} patches`, size: Math.max(8, T.patches.byteLength), usage: storage });
    device.queue.writeBuffer(this.patchBuffer, 0, T.patches);
    this.pointBuffer = device.createBuffer({ label: `acc ${scheme} control points`, size: Math.max(16, 16 * T.nPoints), usage: storage });
    const params = new Uint8Array(ACC_BUILD_PARAMS.size);
    ACC_BUILD_PARAMS.write(new DataView(params.buffer), { nPatches: T.nPatches, ...ACC_STATIC.offsets(layout) });
    this.paramsBuffer = device.createBuffer({
      label: `acc ${scheme} build params`,
      size: params.byteLength,
      usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
    });
    device.queue.writeBuffer(this.paramsBuffer, 0, params);
    let pipe = buildPipelines.get(device);
    if (!pipe) {
      const module = device.createShaderModule({ label: 'acc build', code: [accBuildPrelude(), buildWgsl].join('\n') });
      const groupLayout = device.createBindGroupLayout({ label: 'acc build', entries: ACC_BUILD_GROUP.layoutEntries() });
      const layout = device.createPipelineLayout({ label: 'acc build', bindGroupLayouts: [groupLayout] });
      pipe = device.createComputePipeline({ label: 'acc build', layout, compute: { module, entryPoint: 'buildPatches' } });
      buildPipelines.set(device, pipe);
    }
    this.pipeline = pipe;
  }

  /** Control points in all, and per patch kind (KIND_POINTS), for the stats. */
  get pointCount(): number {
    return this.topology.nPoints;
  }
  static readonly pointsPerKind: readonly number[] = KIND_POINTS;

  /** Record the patch build from `cageBuffer` (xyz f32 per vertex at offset 0). */
  encode(encoder: GPUCommandEncoder, cageBuffer: GPUBuffer): void {
    if (this.groupCage !== cageBuffer || !this.group) {
      this.group = this.device.createBindGroup({
        label: `acc ${this.scheme} build`,
        layout: this.pipeline.getBindGroupLayout(0),
        entries: [
          { binding: ACC_BUILD_GROUP.binding.bp, resource: { buffer: this.paramsBuffer } },
          { binding: ACC_BUILD_GROUP.binding.accStatic, resource: { buffer: this.staticBuffer } },
          { binding: ACC_BUILD_GROUP.binding.cagePos, resource: { buffer: cageBuffer } },
          { binding: ACC_BUILD_GROUP.binding.accPatchesB, resource: { buffer: this.patchBuffer } },
          { binding: ACC_BUILD_GROUP.binding.accPointsB, resource: { buffer: this.pointBuffer } },
        ],
      });
      this.groupCage = cageBuffer;
    }
    const pass = encoder.beginComputePass({ label: `acc ${this.scheme} build` });
    pass.setPipeline(this.pipeline);
    pass.setBindGroup(0, this.group);
    pass.dispatchWorkgroups(...groupsFor(this.topology.nPatches));
    pass.end();
  }

  /** Bind group entries of the evaluator's two buffers, at the given binding numbers. */
  /** Its two buffers as `group` binds them (accSurfaceGroup, or a group with the same names). */
  surfaceEntries(group: { binding: Readonly<Record<'accPatches' | 'accPoints', number>> }): GPUBindGroupEntry[] {
    return [
      { binding: group.binding.accPatches, resource: { buffer: this.patchBuffer } },
      { binding: group.binding.accPoints, resource: { buffer: this.pointBuffer } },
    ];
  }

  /**
   * Evaluate evalAccPatch at (patch, u, v) points on the GPU (checks, the CLI): positions and unit
   * normals, 3 f32 each. Call after an encode() has been submitted.
   */
  async sample(points: ArrayLike<[number, number, number]>): Promise<{ pos: Float32Array; normal: Float32Array }> {
    const device = this.device,
      n = points.length;
    let pipe = samplePipelines.get(device);
    if (!pipe) {
      const code = constantsWgsl + accBindingsWgsl(0, 0) + ACC_SAMPLE_GROUP.wgsl() + ACC_SURFACE_WGSL + SAMPLE_KERNEL;
      const module = device.createShaderModule({ label: 'acc samples', code });
      pipe = device.createComputePipeline({ label: 'acc samples', layout: 'auto', compute: { module, entryPoint: 'main' } });
      samplePipelines.set(device, pipe);
    }
    const data = new ArrayBuffer(12 * Math.max(1, n));
    const u32 = new Uint32Array(data),
      f32 = new Float32Array(data);
    for (let i = 0; i < n; i++) {
      u32[3 * i] = points[i][0];
      f32[3 * i + 1] = points[i][1];
      f32[3 * i + 2] = points[i][2];
    }
    const input = device.createBuffer({
      label: 'acc sample params',
      size: data.byteLength,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
    });
    device.queue.writeBuffer(input, 0, data);
    const output = device.createBuffer({
      label: 'acc sample results',
      size: 24 * Math.max(1, n),
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC,
    });
    const group = device.createBindGroup({
      label: 'acc samples',
      layout: pipe.getBindGroupLayout(0),
      entries: [
        ...this.surfaceEntries(accSurfaceGroup(0, 0)),
        { binding: ACC_SAMPLE_GROUP.binding.sampleIn, resource: { buffer: input } },
        { binding: ACC_SAMPLE_GROUP.binding.sampleOut, resource: { buffer: output } },
      ],
    });
    const enc = device.createCommandEncoder({ label: 'acc samples' });
    const pass = enc.beginComputePass({ label: 'acc samples' });
    pass.setPipeline(pipe);
    pass.setBindGroup(0, group);
    pass.dispatchWorkgroups(...groupsFor(n));
    pass.end();
    device.queue.submit([enc.finish()]);
    const r = new Float32Array(await readBuffer(device, output, 24 * n));
    input.destroy();
    output.destroy();
    const pos = new Float32Array(3 * n),
      normal = new Float32Array(3 * n);
    for (let i = 0; i < n; i++) {
      pos.set(r.subarray(6 * i, 6 * i + 3), 3 * i);
      normal.set(r.subarray(6 * i + 3, 6 * i + 6), 3 * i);
    }
    return { pos, normal };
  }

  /** The control points as built on the GPU (xyz per point). */
  async readPoints(): Promise<Float32Array> {
    const r = new Float32Array(await readBuffer(this.device, this.pointBuffer, 16 * this.topology.nPoints));
    const out = new Float32Array(3 * this.topology.nPoints);
    for (let i = 0; i < this.topology.nPoints; i++) out.set(r.subarray(4 * i, 4 * i + 3), 3 * i);
    return out;
  }

  destroy(): void {
    this.patchBuffer.destroy();
    this.pointBuffer.destroy();
    this.staticBuffer.destroy();
    this.paramsBuffer.destroy();
  }
}

// Its bindings: accBindingsWgsl(0, 0) and ACC_SAMPLE_GROUP (sampleIn, sampleOut).
const SAMPLE_KERNEL = /* wgsl */ `
@compute @workgroup_size(WORKGROUP_SIZE)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let i = (wid.y * GRID_X + wid.x) * WORKGROUP_SIZE + lid;
  if (i >= arrayLength(&sampleIn) / 3u) { return; }
  let s = evalAccPatch(sampleIn[3u * i], bitcast<f32>(sampleIn[3u * i + 1u]), bitcast<f32>(sampleIn[3u * i + 2u]));
  for (var c = 0u; c < 3u; c++) {
    sampleOut[6u * i + c] = s.pos[c];
    sampleOut[6u * i + 3u + c] = s.normal[c];
  }
}
`;
