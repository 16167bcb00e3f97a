/**
 * The ACC error views of the demo (issue 10; the NVIDIA sample's "Geometry Error" and "Normal
 * Error"), on the GPU: every time the compute tessellator rebuilds its output on an ACC surface,
 * one pass over its output vertices (wgsl/acc/heat.wgsl) evaluates, at each vertex's own cage
 * parameter (srcTri, bary), the ACC patch and the exact Catmull-Clark limit, and stores per vertex
 * the distance (a fraction of the cage's bounding-box diagonal) and the normal angle (degrees),
 * then folds them into max and RMS. The lit pass reads the values by vertex index
 * (wgsl/render/heat.wgsl, Renderer.setHeat) and colours the surface with HEAT_RAMP; the totals
 * are copied to a readback buffer only when it is idle and read asynchronously (never a stall).
 *
 * The exact side is a Catmull-Clark Tessellator of the same cage used only for its patch build
 * and uniforms (evalSurface reads them): encode it once (any factors, flatBaseline off) after
 * setMesh, and again after a cage deformation, before encode() here. The ACC side is the ACC
 * tessellator's own AccPatches, current after its encode.
 *
 * Bindings: 8 storage buffers in the error pass (WebGPU's default per-stage limit), so the
 * per-triangle table, the partials, the totals and the per-vertex values share one buffer (aux).
 */
import { cageDiagonal } from '../../mesh/range.ts';
import commonWgsl from '../../../wgsl/tess/common.wgsl?raw';
import heatWgsl from '../../../wgsl/acc/heat.wgsl?raw';
import type { Cage } from '../../mesh/index.ts';
import { KIND_REGULAR } from '../../subdiv/acc.ts';
import { ACC_SURFACE_WGSL, type AccPatches, accBindingsWgsl } from './patches.ts';
import { accTriangleWords } from './surface.ts';
import { CC_SURFACE_WGSL } from '../cc/shaders.ts';
import { defineArena, STAGE, usedBindings, wgslConstants, wgslF32 } from '../contract/define.ts';
import { WORKGROUP_SIZE } from '../contract/constants.ts';
import { TESS_GROUP, TESS_INPUTS } from '../contract/tess.ts';
import { accSurfaceGroup, HEAT_BINDINGS, HEAT_GROUP } from '../contract/acc.ts';
import { tessPrelude } from '../contract/contract.ts';
import { defineStruct } from '../contract/layout.ts';
import type { PreparedMesh } from '../tess/prepare.ts';
import type { Tessellator } from '../tess/tessellator.ts';
import type { TessellatedMesh } from '../contract/tessellated-mesh.ts';
import { surfaceScheme } from '../surface/registry.ts';

/** What the heat map shows: the position error or the normal error. */
export type HeatView = 'geometry' | 'normal';
export const HEAT_VIEWS: readonly HeatView[] = ['geometry', 'normal'];

/** The colour of 0 (blue), the middle of the range (green) and the range and above (red): the
 * sample's ramp, sRGB. The lit shader's (HEAT_SRGB) and the legend's. */
export const HEAT_RAMP: readonly (readonly [number, number, number])[] = [
  [0.16, 0.32, 0.95],
  [0.2, 0.82, 0.3],
  [0.95, 0.18, 0.12],
];

/** Default top of the colour bar: 0.5 % of the diagonal, 5°, about the worst of the ACC table in
 * BENCHMARKS.md on the test cages. */
export const HEAT_DEFAULT_RANGE: Readonly<Record<HeatView, number>> = { geometry: 0.005, normal: 5 };

/** The heat colours' uniforms in the lit pass (wgsl/render/heat.wgsl `heat`). */
export const HEAT_UNIFORMS = defineStruct('HeatUniforms', [
  ['view', 'u32', '0: geometry (distance / diagonal), 1: normal (degrees): the value of each vertex read.'],
  ['range', 'f32', 'The value drawn in the last colour of the ramp (and everything above it).'],
] as const);

/** What wgsl/render/heat.wgsl starts with (after the scene prelude). */
export const heatRenderWgsl = [
  HEAT_UNIFORMS.wgsl,
  `const HEAT_SRGB = array<vec3f, ${HEAT_RAMP.length}>(${HEAT_RAMP.map((c) => `vec3f(${c.map(wgslF32).join(', ')})`).join(', ')});`,
  '',
].join('\n');

/** Words of aux's header: the vertex count, the workgroups, then the totals (max distance, Σ d²,
 * max angle, Σ angle², the vertices counted). */
const HEADER = { HEADER_COUNT: 0, HEADER_GROUPS: 1, HEADER_TOTALS: 2 } as const;
const HEADER_WORDS = 8;
const PARTIAL_WORDS = 8;
/** Storage-buffer offsets must be multiples of this (minStorageBufferOffsetAlignment, at most 256). */
const ALIGN_WORDS = 64;

interface AuxSizes {
  triangles: number;
  capacity: number;
}

const groupsOf = (capacity: number) => Math.ceil(Math.max(1, capacity) / WORKGROUP_SIZE);
const beforeErrors = (s: AuxSizes) => HEADER_WORDS + Math.max(1, s.triangles) + PARTIAL_WORDS * groupsOf(s.capacity);

/** aux: header, ACC_TRI_WORD per cage triangle, partials per workgroup, padding to an aligned
 * offset, and the per-vertex values (2 words each). */
export const HEAT_AUX = defineArena<'header' | 'triMap' | 'partials' | 'pad' | 'errors', AuxSizes>([
  ['header', () => HEADER_WORDS],
  ['triMap', (s) => Math.max(1, s.triangles)],
  ['partials', (s) => PARTIAL_WORDS * groupsOf(s.capacity)],
  ['pad', (s) => (ALIGN_WORDS - (beforeErrors(s) % ALIGN_WORDS)) % ALIGN_WORDS],
  ['errors', (s) => 2 * Math.max(1, s.capacity)],
]);

/** The error pass's own uniforms (`heatPass` in wgsl/acc/heat.wgsl). */
export const HEAT_PASS = defineStruct('HeatPass', [
  ['invDiag', 'f32', "1 / the cage's bounding-box diagonal: distances are fractions of it."],
  ['capacity', 'u32', 'Output vertices the values have room for.'],
  ...HEAT_AUX.offsetFields,
] as const);

/** Max and RMS of both errors over the output vertices of the last pass read back. */
export interface HeatTotals {
  /** Fractions of the diagonal. */
  maxDistance: number;
  rmsDistance: number;
  /** Degrees. */
  maxAngle: number;
  rmsAngle: number;
  /** Output vertices counted (those of a cage triangle). */
  vertices: number;
}

/** The error pass's WGSL: the reference's inputs and exact surface, the ACC evaluator (group 1), its
 * uniforms and constants, its bindings (HEAT_GROUP), then wgsl/acc/heat.wgsl. */
export function heatComputeCode(): string {
  return [
    tessPrelude(TESS_INPUTS),
    commonWgsl,
    CC_SURFACE_WGSL,
    accBindingsWgsl(1, 0),
    ACC_SURFACE_WGSL,
    HEAT_PASS.wgsl,
    wgslConstants({ ...HEADER, PARTIAL_WORDS, KIND_REGULAR }),
    HEAT_GROUP.wgsl(),
    heatWgsl,
  ].join('\n');
}

const modules = new WeakMap<GPUDevice, Record<'args' | 'errors' | 'totals', GPUComputePipeline>>();

function pipelinesFor(device: GPUDevice): Record<'args' | 'errors' | 'totals', GPUComputePipeline> {
  let p = modules.get(device);
  if (!p) {
    const code = heatComputeCode();
    const module = device.createShaderModule({ label: 'acc heat', code });
    // Group 0: the reference's inputs and this pass's bindings that the entry point uses; group 1
    // (heatErrors only): the ACC patches, read-only.
    const accGroup = device.createBindGroupLayout({
      label: 'acc heat patches',
      entries: [0, 1].map((binding) => ({ binding, visibility: STAGE.COMPUTE, buffer: { type: 'read-only-storage' as const } })),
    });
    const make = (entryPoint: string) => {
      const entries = [
        ...TESS_GROUP.layoutEntries(usedBindings(code, entryPoint, TESS_INPUTS)),
        ...HEAT_GROUP.layoutEntries(usedBindings(code, entryPoint, HEAT_BINDINGS)),
      ];
      const group0 = device.createBindGroupLayout({ label: `acc heat ${entryPoint}`, entries });
      const bindGroupLayouts = entryPoint === 'heatErrors' ? [group0, accGroup] : [group0];
      const layout = device.createPipelineLayout({ label: `acc heat ${entryPoint}`, bindGroupLayouts });
      return device.createComputePipeline({ label: `acc heat ${entryPoint}`, layout, compute: { module, entryPoint } });
    };
    p = { args: make('heatArgs'), errors: make('heatErrors'), totals: make('heatTotals') };
    modules.set(device, p);
  }
  return p;
}

export class AccHeatPass {
  readonly aux: GPUBuffer;
  readonly capacity: number;
  readonly #device: GPUDevice;
  readonly #uniforms: GPUBuffer;
  readonly #args: GPUBuffer;
  readonly #read: GPUBuffer;
  readonly #layout: ReturnType<typeof HEAT_AUX.layout>;
  readonly #pipelines: Record<'args' | 'errors' | 'totals', GPUComputePipeline>;
  #readState: 'idle' | 'copied' | 'mapping' = 'idle';
  /** The last pass's totals are not copied yet (the readback buffer was busy). */
  #copyOwed = false;
  #last: HeatTotals | null = null;

  /**
   * `acc`: the ACC patches the drawn surface evaluates (built from the same cage positions as
   * the reference's); `mesh`, `cage`: the prepared cage of both; `capacity`: the output's
   * vertexCapacity.
   */
  constructor(
    device: GPUDevice,
    readonly acc: AccPatches,
    mesh: PreparedMesh,
    cage: Cage,
    capacity: number,
  ) {
    this.#device = device;
    this.capacity = capacity;
    this.#pipelines = pipelinesFor(device);
    const layout = (this.#layout = HEAT_AUX.layout({ triangles: mesh.triangleCount, capacity }));
    this.aux = device.createBuffer({
      label: 'acc heat values and totals',
      size: 4 * layout.words,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST | GPUBufferUsage.COPY_SRC,
    });
    if (mesh.triangleCount) device.queue.writeBuffer(this.aux, 4 * layout.offset.triMap, accTriangleWords(mesh, cage));
    const bytes = new DataView(new ArrayBuffer(HEAT_PASS.size));
    HEAT_PASS.write(bytes, { invDiag: 1 / cageDiagonal(cage.positions), capacity, ...HEAT_AUX.offsets(layout) });
    this.#uniforms = device.createBuffer({
      label: 'acc heat pass uniforms',
      size: HEAT_PASS.size,
      usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
    });
    device.queue.writeBuffer(this.#uniforms, 0, bytes.buffer);
    this.#args = device.createBuffer({
      label: 'acc heat dispatch args',
      size: 12,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.INDIRECT,
    });
    this.#read = device.createBuffer({
      label: 'acc heat totals readback',
      size: 4 * HEADER_WORDS,
      usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
    });
  }

  /** The per-vertex values (2 f32 per output vertex: distance / diagonal, degrees) as a binding. */
  get values(): GPUBufferBinding {
    return { buffer: this.aux, offset: 4 * this.#layout.offset.errors, size: 4 * this.#layout.length.errors };
  }

  /**
   * Record the pass over the vertices `out` holds now (after the ACC tessellator's encode into
   * the same encoder, and the reference's encode at least once since its setMesh), and the copy
   * of the totals when the readback buffer is free.
   */
  encode(encoder: GPUCommandEncoder, reference: Tessellator, out: TessellatedMesh): void {
    if (!surfaceScheme(reference.surface).exactLimit)
      throw new Error('the error view needs a Catmull-Clark tessellator (the exact surface)');
    const device = this.#device,
      p = this.#pipelines;
    const group = (pipe: GPUComputePipeline, label: string, entries: [number, GPUBuffer][]) =>
      device.createBindGroup({
        label,
        layout: pipe.getBindGroupLayout(0),
        entries: entries.map(([binding, buffer]) => ({ binding, resource: { buffer } })),
      });
    const pass = encoder.beginComputePass({ label: 'acc heat' });
    pass.setPipeline(p.args);
    pass.setBindGroup(
      0,
      group(p.args, 'acc heat args', [
        [HEAT_GROUP.binding.aux, this.aux],
        [HEAT_GROUP.binding.heatPass, this.#uniforms],
        [HEAT_GROUP.binding.outCounts, out.counts],
        [HEAT_GROUP.binding.dispatchArgs, this.#args],
      ]),
    );
    pass.dispatchWorkgroups(1);
    pass.end();

    const errors = encoder.beginComputePass({ label: 'acc heat errors' });
    errors.setPipeline(p.errors);
    errors.setBindGroup(
      0,
      group(p.errors, 'acc heat errors', [
        [TESS_GROUP.binding.params, reference.paramsBuffer],
        [TESS_GROUP.binding.staticBuf, reference.staticBuffer],
        [TESS_GROUP.binding.cageBuf, reference.cageBuffer],
        [TESS_GROUP.binding.work, reference.workBuffer],
        [HEAT_GROUP.binding.srcTri, out.srcTri],
        [HEAT_GROUP.binding.bary, out.bary],
        [HEAT_GROUP.binding.aux, this.aux],
        [HEAT_GROUP.binding.heatPass, this.#uniforms],
      ]),
    );
    errors.setBindGroup(
      1,
      device.createBindGroup({
        label: 'acc heat patches',
        layout: p.errors.getBindGroupLayout(1),
        entries: this.acc.surfaceEntries(accSurfaceGroup(1, 0)),
      }),
    );
    errors.dispatchWorkgroupsIndirect(this.#args, 0);
    errors.setPipeline(p.totals);
    errors.setBindGroup(
      0,
      group(p.totals, 'acc heat totals', [
        [HEAT_GROUP.binding.aux, this.aux],
        [HEAT_GROUP.binding.heatPass, this.#uniforms],
      ]),
    );
    errors.dispatchWorkgroups(1);
    errors.end();

    this.#copyOwed = true;
    this.copyIfOwed(encoder);
  }

  /** Whether the last pass's totals still wait for the readback buffer (copyIfOwed in a later frame). */
  get copyOwed(): boolean {
    return this.#copyOwed;
  }

  /** Copy the last pass's totals for reading if they are owed and the readback buffer is free. */
  copyIfOwed(encoder: GPUCommandEncoder): void {
    if (!this.#copyOwed || this.#readState !== 'idle') return;
    encoder.copyBufferToBuffer(this.aux, 4 * this.#layout.offset.header, this.#read, 0, 4 * HEADER_WORDS);
    this.#readState = 'copied';
    this.#copyOwed = false;
  }

  /** Whether totals are waiting to be read (a frame submitted after encode() copied them). */
  get owed(): boolean {
    return this.#readState === 'copied';
  }

  /**
   * The totals of the latest pass whose copy has come back (null before the first). Call after
   * submitting the encoder; a read already mapping answers with the last totals.
   */
  async read(): Promise<HeatTotals | null> {
    if (this.#readState !== 'copied') return this.#last;
    this.#readState = 'mapping';
    try {
      await this.#read.mapAsync(GPUMapMode.READ);
      const words = new Uint32Array(this.#read.getMappedRange().slice(0));
      this.#read.unmap();
      this.#last = totalsFromHeader(words);
    } catch {
      // Destroyed or device lost while mapping: keep the last totals.
    } finally {
      if (this.#readState === 'mapping') this.#readState = 'idle';
    }
    return this.#last;
  }

  destroy(): void {
    this.aux.destroy();
    this.#uniforms.destroy();
    this.#args.destroy();
    this.#read.destroy();
  }
}

/** The totals from the header words (HEADER_TOTALS onwards: max d, Σ d², max angle, Σ angle², n). */
export function totalsFromHeader(words: Uint32Array): HeatTotals {
  const f = new Float32Array(words.buffer, words.byteOffset, words.length);
  const o = HEADER.HEADER_TOTALS;
  const n = words[o + 4];
  return {
    maxDistance: f[o],
    rmsDistance: n ? Math.sqrt(f[o + 1] / n) : 0,
    maxAngle: f[o + 2],
    rmsAngle: n ? Math.sqrt(f[o + 3] / n) : 0,
    vertices: n,
  };
}
