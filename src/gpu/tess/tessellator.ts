/**
 * The compute tessellator (Hable, "Part 2: The Mesh"): whole meshes tessellated adaptively
 * into big flat buffers, welded, stored once and drawn by every pass. Takes a GPUDevice and
 * never touches the DOM, so the same code runs in the browser, in headless tests and in Node.
 *
 * Passes, in one command encoder (direct dispatches, sizes known on the CPU, except emit's), the
 * same chain of seven dispatches whatever the camera and the budget:
 *   bulge        one thread per triangle: the factor its surface's bulge    wgsl/tess/factor-bulge.wgsl
 *                asks for (the surface at four points against the flat triangle)
 *   count        one thread per triangle: its three edges' tess factor,     wgsl/tess/count.wgsl
 *                line state and segments (wgsl/tess/factors.wgsl; the
 *                edge's owner stores them), its interior vertices and
 *                triangles, at every budget candidate (contract/tess.ts
 *                BUDGET_SCALES)
 *   scan         two dispatches: every lane summed by block; then each      wgsl/tess/scan.wgsl
 *                workgroup takes the first candidate that fits from the
 *                block sums (one writes the draw and dispatch arguments)
 *                and scans its block of the chosen lanes
 *   plan         one thread per triangle writes its pattern's rows         wgsl/tess/plan.wgsl
 *   emit         two indirect dispatches sized by the budget: one thread   wgsl/tess/emit.wgsl
 *                per output vertex (the weld's corner and edge vertices,    wgsl/tess/weld.wgsl
 *                evaluated once each whoever uses them, on Catmull-Clark
 *                once per side of an infinitely sharp crease: prepare.ts
 *                splitCreases; then the triangles' interior vertices), then
 *                one per output triangle
 * This is the talk's predict → scan → plan → emit → weld: no workgroup memory and no barriers
 * outside the scan, so every output element costs the same whatever the factors
 * (wgsl/tess/pattern.wgsl holds the pattern reading shared by count, plan and emit); no readback
 * is ever needed. tests/gpu/tess/tessellator.gpu.test.ts counts the dispatches.
 * With the Catmull-Clark surface (options.surface), a patch-build pass comes first:
 *   subdivision  refined points, one dispatch a level (rule per point), the slices round
 *                extraordinary vertices (workgroup memory), then in one dispatch their
 *                limits and the cage vertices' limit positions and normals for the factor
 *                rule                                                       wgsl/cc/build.wgsl
 *
 * What the TypeScript and the WGSL agree on (the buffers' arenas, Params, the bindings, the
 * budget's candidates, the constants, the packed words) is declared in contract/tess.ts; which code each pass
 * compiles and which bindings its entry point uses is src/gpu/tess/passes.ts; the timestamps are
 * pass-timer.ts; the pipelines are created by src/gpu/tess/pipelines.ts, and the arenas' words
 * and the Params fields of a mesh are packed by src/gpu/tess/arenas.ts. This file uploads a mesh
 * (setMesh: validate, pack, bind) and records the passes (encode).
 */
import { LimitError } from '../../mesh/errors.ts';
import type { CatmullClarkData } from '../cc/build.ts';
import type { AccSurface } from '../acc/surface.ts';
import type { DisplacementData, DisplacementSettings } from './displacement-map.ts';
import type { PassName, Surface } from './passes.ts';
import { surfaceScheme } from '../surface/registry.ts';
import { createTessPipelines, type Pipeline, type TessPipelines } from './pipelines.ts';
import { type CageName, meshParams, type PackInput, packArenas, type WorkName } from './arenas.ts';
import { PassTimer } from '../device/pass-timer.ts';
import type { ArenaLayout } from '../contract/define.ts';
import { grid2d, groupsFor } from '../contract/constants.ts';
import { BUDGET_CANDIDATES, SCAN_BLOCK, SCANS, TESS_FIXED_WORDS, TESS_PARAMS, type TessBinding } from '../contract/tess.ts';
import { CC_RANGE, type CcBuildBinding } from '../contract/cc.ts';
import { outputCapacity } from './factors.ts';
import { phongTriAlphas } from '../surface/phong-alpha.ts';
import type { CreaseSplit, PreparedMesh } from './prepare.ts';
import type { FactorParams, TessellatedMesh } from '../contract/tessellated-mesh.ts';
import { PatternTables } from '../../pattern/tables.ts';

export { prepareMesh, type PreparedMesh } from './prepare.ts';
export { type PassName, type PassSpec, passBindings, type Surface, tessellatorPasses } from './passes.ts';

export { grid2d } from '../contract/constants.ts';

/** Compute passes one rebuild records (the patch build, the bulge term, factors + count + scan,
 * plan, emit), each timed by a pair of timestamps. */
const TIMED_PASSES = 5;

export interface TessellatorOptions {
  vertexCapacity?: number;
  triangleCapacity?: number;
  /** 'catmull-clark': the exact Catmull-Clark limit surface (wgsl/cc/surface.wgsl); setMesh then
   * needs the tables of src/gpu/cc/build.ts buildCatmullClark. 'bezier-acc', 'gregory-acc',
   * 'pm-acc': an approximation of it (wgsl/acc/surface.wgsl); setMesh then needs the ACC patches
   * of src/gpu/acc/surface.ts prepareAccSurface. Default 'phong' (wgsl/surface/phong.wgsl). */
  surface?: Surface;
  /** Catmull-Clark: blend from the flat triangle (corner limit positions) to the surface as the
   * tess factor rises from 1 to 4, so nothing pops (default true; off for exact checks). */
  flatBaseline?: boolean;
  /** Compile the passes that evaluate the surface for what each mesh has (SurfaceScheme.specialise;
   * default true); false: the general evaluator, which the specialised ones must equal. */
  specialise?: boolean;
  /** The pipelines, made before for this device and surface (pipelines.ts createTessPipelinesAsync);
   * made now when absent. */
  pipelines?: TessPipelines;
}

/** What setMesh packs before it binds. */
interface Packed {
  staticWords: Uint32Array;
  cageWords: Float32Array;
  workLayout: ArenaLayout<WorkName>;
  cageLayout: ArenaLayout<CageName>;
}

interface MeshState {
  prepared: PreparedMesh;
  staticBuf: GPUBuffer;
  cageBuf: GPUBuffer;
  work: GPUBuffer;
  /** Where the work arrays (TESS_WORK) and the cage arrays (TESS_CAGE) lie. */
  workLayout: ArenaLayout<WorkName>;
  cageLayout: ArenaLayout<CageName>;
  groups: Partial<Record<PassName, GPUBindGroup>>;
  cc?: CatmullClarkData;
  ccRanges: { group: GPUBindGroup; count: number }[];
  /** The ACC patches (owned by the caller), built before every tessellation (cageBuf keeps a copy
   * of their control points at cageLayout's accPoints). */
  acc?: AccSurface;
  uniforms: GPUBuffer[];
  /** The surface's override values for this mesh (SurfaceScheme.specialise): what the passes
   * that evaluate it run with. */
  constants: Record<string, number>;
}

export class Tessellator {
  readonly output: TessellatedMesh;
  readonly maxFactor: number;
  readonly surface: Surface;
  /** Catmull-Clark flat-baseline blend by tess factor (see TessellatorOptions.flatBaseline). */
  flatBaseline: boolean;
  private readonly specialise: boolean;
  private readonly params: GPUBuffer;
  private readonly paramsBytes: ArrayBuffer;
  /** Indirect dispatch arguments of the emit passes, written with the budget's choice (wgsl/tess/scan.wgsl scanDown). */
  private readonly emitArgs: GPUBuffer;
  private readonly pipelineSet: TessPipelines;
  private readonly pipelines: Partial<Record<PassName, Pipeline>>;
  private mesh?: MeshState;
  private hasDisplacement = false;
  private displacement: DisplacementSettings = { scale: 0, midLevel: 0, enabled: true };
  private readonly timer?: PassTimer;
  /** The edges' turn terms (work edgeTurn, wgsl/tess/factor-bulge.wgsl) depend on the surface
   * alone: computed by the first adaptive rebuild after the mesh or the cage changed. */
  private turnStale = true;

  static create(device: GPUDevice, tables: Uint32Array, opts: TessellatorOptions = {}): Tessellator {
    return new Tessellator(device, tables, opts);
  }

  private constructor(
    readonly device: GPUDevice,
    private readonly tables: Uint32Array,
    opts: TessellatorOptions,
  ) {
    this.maxFactor = new PatternTables(tables).maxFactor;
    this.surface = opts.surface ?? 'phong';
    this.flatBaseline = opts.flatBaseline ?? true;
    this.specialise = opts.specialise ?? true;
    const cap = outputCapacity(device.limits, opts);
    const buffer = (label: string, size: number, usage: number) => device.createBuffer({ label, size: Math.max(16, size), usage });
    const S = GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST;
    this.output = {
      positions: buffer('tess positions', 12 * cap.vertexCapacity, S | GPUBufferUsage.VERTEX),
      normals: buffer('tess normals', 12 * cap.vertexCapacity, S | GPUBufferUsage.VERTEX),
      bary: buffer('tess barycentrics', 4 * cap.vertexCapacity, S | GPUBufferUsage.VERTEX),
      srcTri: buffer('tess source triangles', 4 * cap.vertexCapacity, S | GPUBufferUsage.VERTEX),
      indices: buffer('tess indices', 12 * cap.triangleCapacity, S | GPUBufferUsage.INDEX),
      drawArgs: buffer('tess draw args', 4 * TESS_FIXED_WORDS.drawArgs, S | GPUBufferUsage.INDIRECT),
      counts: buffer('tess counts', 4 * TESS_FIXED_WORDS.counts, S),
      vertexCapacity: cap.vertexCapacity,
      triangleCapacity: cap.triangleCapacity,
    };
    this.emitArgs = buffer('tess emit dispatch args', 4 * TESS_FIXED_WORDS.emitArgs, GPUBufferUsage.STORAGE | GPUBufferUsage.INDIRECT);
    this.paramsBytes = new ArrayBuffer(TESS_PARAMS.size);
    this.params = device.createBuffer({
      label: 'tess params',
      size: TESS_PARAMS.size,
      usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
    });

    if (opts.pipelines && opts.pipelines.surface !== this.surface)
      throw new Error(`pipelines for ${opts.pipelines.surface} handed to a ${this.surface} tessellator`);
    this.pipelineSet = opts.pipelines ?? createTessPipelines(device, this.surface);
    this.pipelines = this.pipelineSet.pipelines;

    if (device.features.has('timestamp-query')) this.timer = new PassTimer(device, 'tess', TIMED_PASSES);
  }

  /**
   * Displacement settings (uniforms only: the map and uvs came with setMesh), uploaded now;
   * without displacement data in the mesh, `enabled` has no effect.
   */
  setDisplacement(settings: Partial<DisplacementSettings>): void {
    this.displacement = { ...this.displacement, ...settings };
    this.writeDisplacementParams();
    // Up at once: a tessellator that only lends its arenas (src/gpu/instanced/displace-vertex.ts) is
    // never encoded again, and encode() rewrites the rest before it reads them.
    if (this.mesh) this.device.queue.writeBuffer(this.params, 0, this.paramsBytes);
  }

  /** Whether output vertices are displaced now (data in the mesh and enabled). */
  get displaced(): boolean {
    return this.hasDisplacement && this.displacement.enabled;
  }

  private writeDisplacementParams(): void {
    TESS_PARAMS.write(new DataView(this.paramsBytes), {
      dispOn: this.displaced ? 1 : 0,
      dispScale: this.displacement.scale,
      dispMid: this.displacement.midLevel,
    });
  }

  /** Upload a prepared mesh: topology once; positions may be updated later (updateCage). The
   * Catmull-Clark surface also needs the mesh's tables (src/gpu/cc/build.ts buildCatmullClark). */
  setMesh(prepared: PreparedMesh, cc?: CatmullClarkData, acc?: AccSurface, displacement?: DisplacementData): void {
    const ccData = this.validate(prepared, cc, acc);
    const accData = surfaceScheme(this.surface).patchBuild === 'acc-patches' ? acc : undefined;
    const packed = this.pack(prepared, ccData, accData, displacement);
    this.releaseMesh();
    this.mesh = this.bind(prepared, ccData, packed, accData);
    this.turnStale = true;
    // The passes that evaluate the surface, compiled now for this mesh (not at its first frame).
    for (const name of Object.keys(this.pipelines) as PassName[]) if (this.pipelines[name]!.specialised) this.pipelineOf(name, this.mesh);
  }

  /** A pass's pipeline for the mesh: the surface's override values where the pass evaluates it,
   * the flat baseline and the displacement compiled in only when they are on (the surface's
   * FLAT_BASELINE, wgsl/tess/outputs.wgsl DISPLACED); every
   * variant binds with its pass's layout, so the mesh's bind group serves it. */
  private pipelineOf(name: PassName, m: MeshState): GPUComputePipeline {
    const p = this.pipelines[name]!;
    if (!p.specialised) return p.pipeline();
    const constants: Record<string, number> = { ...m.constants };
    if (surfaceScheme(this.surface).flatBaseline) constants.FLAT_BASELINE = +this.flatBaseline;
    if (name === 'emitVertices') constants.DISPLACED = +this.displaced;
    return p.pipeline(constants);
  }

  /** The three arenas' contents, their layouts, and the Params that say where their arrays lie
   * (into paramsBytes; encode() uploads them). Throws when the scratch buffer would not bind. */
  private pack(
    prepared: PreparedMesh,
    cc: CatmullClarkData | undefined,
    acc: AccSurface | undefined,
    disp: DisplacementData | undefined,
  ): Packed {
    const input: PackInput = {
      prepared,
      cc,
      acc,
      disp,
      tables: this.tables,
      maxFactor: this.maxFactor,
      split: this.creaseSplit(prepared),
      extraSlots: this.extraSlots(prepared),
    };
    const packed = packArenas(input);
    const { staticWords, cageLayout, cageWords, workLayout } = packed;
    if (4 * workLayout.words > this.device.limits.maxStorageBufferBindingSize) {
      throw new LimitError(
        `the cage is too large for this GPU: its scratch buffer (${4 * workLayout.words} bytes) exceeds the device's storage binding limit (${this.device.limits.maxStorageBufferBindingSize} bytes)`,
      );
    }
    TESS_PARAMS.write(new DataView(this.paramsBytes), meshParams(input, packed, this.output));
    this.hasDisplacement = disp !== undefined;
    this.writeDisplacementParams();

    return { staticWords, cageWords, workLayout, cageLayout };
  }

  /** The buffers, written; each pass's bind group from the bindings its entry point uses; the
   * scans' and the patch build's small uniforms. */
  private bind(prepared: PreparedMesh, cc: CatmullClarkData | undefined, packed: Packed, acc: AccSurface | undefined): MeshState {
    const device = this.device;
    const { staticWords, cageWords, workLayout, cageLayout } = packed;
    const storage = GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST;
    const staticBuf = device.createBuffer({ label: 'tess tables + topology', size: staticWords.byteLength, usage: storage });
    device.queue.writeBuffer(staticBuf, 0, staticWords);
    const cageBuf = device.createBuffer({
      label: 'tess cage',
      size: Math.max(16, cageWords.byteLength),
      usage: storage | GPUBufferUsage.COPY_SRC,
    });
    // Only the arrays packed here: the refined points, the limits and the ACC points are the patch
    // build's to write, and a new buffer is zeros (6 of a 40,000-face cage's 6.3 MB, copied to the
    // GPU process for nothing on the page's thread).
    for (const [first, end] of [
      [0, cageLayout.offset.ctrl],
      [cageLayout.offset.cornerUvs, cageLayout.words],
    ])
      if (end > first) device.queue.writeBuffer(cageBuf, 4 * first, cageWords, first, end - first);
    const work = device.createBuffer({ label: 'tess work', size: 4 * workLayout.words, usage: storage | GPUBufferUsage.COPY_SRC });

    const resources: Record<TessBinding, GPUBuffer> = {
      params: this.params,
      staticBuf,
      cageBuf,
      work,
      outPositions: this.output.positions,
      outNormals: this.output.normals,
      outBary: this.output.bary,
      outSrcTri: this.output.srcTri,
      outIndices: this.output.indices,
      drawArgs: this.output.drawArgs,
      counts: this.output.counts,
      emitArgs: this.emitArgs,
    };
    const uniforms: GPUBuffer[] = [];
    const rangeBytes = (first: number, count: number, faceFirst: number) => {
      const bytes = new ArrayBuffer(CC_RANGE.size);
      CC_RANGE.write(new DataView(bytes), { first, count, faceFirst });
      return bytes;
    };
    const uniform = (label: string, bytes: ArrayBuffer | Uint32Array) => {
      const u = device.createBuffer({ label, size: bytes.byteLength, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
      device.queue.writeBuffer(u, 0, bytes);
      uniforms.push(u);
      return u;
    };
    const bindGroup = (name: PassName, extra: Partial<Record<CcBuildBinding, GPUBuffer>> = {}) => {
      const p = this.pipelines[name]!;
      const byName: Record<string, GPUBuffer> = { ...resources, ...extra };
      return device.createBindGroup({
        label: p.label,
        layout: p.layout,
        entries: p.bindings.map((n) => ({ binding: p.binding[n], resource: { buffer: byName[n] } })),
      });
    };
    const groups: Partial<Record<PassName, GPUBindGroup>> = {};
    for (const name of Object.keys(this.pipelines) as PassName[]) if (name !== 'ccPoints') groups[name] = bindGroup(name);

    // Catmull-Clark level dispatches: one per level over its edge and vertex points, then its
    // face points (contiguous: src/gpu/cc/levels.ts), each level's range in a small uniform.
    const ccRanges = (cc?.levelRanges ?? []).map(([faceFirst, faceCount, first, veCount]) => ({
      count: veCount + faceCount,
      group: bindGroup('ccPoints', { range: uniform('cc level range', rangeBytes(first, veCount + faceCount, faceFirst)) }),
    }));
    return {
      prepared,
      staticBuf,
      cageBuf,
      work,
      workLayout,
      cageLayout,
      groups,
      cc,
      ccRanges,
      uniforms,
      acc,
      constants: this.specialise ? surfaceScheme(this.surface).specialise({ cc, acc }) : {},
    };
  }

  /** Where normals split per side (prepare.ts splitCreases): at the creases the surface has (its
   * SurfaceScheme says which: the limit's infinitely sharp ones, or the ACC schemes'). */
  private creaseSplit(prepared: PreparedMesh): CreaseSplit | undefined {
    const at = surfaceScheme(this.surface).splitsCreases;
    return at === 'infinitely-sharp' ? prepared : at === 'sharpness-1' ? prepared.accSplit : undefined;
  }

  /** Output vertices of the extra sectors: after the vertices, before the edge points. */
  private extraSlots(prepared: PreparedMesh): number {
    return this.creaseSplit(prepared)?.slotOwner.length ?? 0;
  }

  /** Throws on a mesh this tessellator cannot take; the Catmull-Clark tables it will use. */
  private validate(prepared: PreparedMesh, cc?: CatmullClarkData, acc?: AccSurface): CatmullClarkData | undefined {
    const scheme = surfaceScheme(this.surface);
    if (prepared.triangleCount === 0) throw new LimitError('the model has no faces to tessellate (every face is a hole)');
    if (scheme.patchBuild === 'refinement' && !cc)
      throw new Error(`the ${scheme.name} surface needs the tables of buildCatmullClark(cage, prepared)`);
    if (scheme.patchBuild === 'acc-patches') {
      if (!acc) throw new Error(`the ${this.surface} surface needs its patches (prepareAccSurface)`);
      if (acc.patches.scheme !== this.surface) throw new Error(`${acc.patches.scheme} patches given to a ${this.surface} tessellator`);
      if (acc.triangles.length !== prepared.triangleCount) throw new Error('the ACC patches were prepared for another mesh');
    }
    if (
      prepared.triangleCount > this.output.triangleCapacity ||
      prepared.vertexCount + this.extraSlots(prepared) + prepared.edgeCount > this.output.vertexCapacity
    ) {
      throw new Error(
        `the cage is too large for the output buffers even at factor 1 (${prepared.triangleCount} triangles, capacity ${this.output.triangleCapacity})`,
      );
    }
    return scheme.patchBuild === 'refinement' ? cc : undefined;
  }

  /** New cage positions (and normals) for the same topology, e.g. an animated cage. */
  updateCage(positions: Float32Array, normals: Float32Array): void {
    const m = this.requireMesh();
    this.turnStale = true;
    this.device.queue.writeBuffer(m.cageBuf, 0, positions);
    this.device.queue.writeBuffer(m.cageBuf, 4 * m.cageLayout.offset.normals, normals);
    // The Phong surface's α per edge follows the normals (phong.ts phongTriAlphas).
    this.device.queue.writeBuffer(m.cageBuf, 4 * m.cageLayout.offset.phongAlpha, phongTriAlphas(m.prepared, positions, normals));
  }

  /** The uniform and static buffers (for extra passes over the same mesh, e.g. surface sampling). */
  get paramsBuffer(): GPUBuffer {
    return this.params;
  }

  get staticBuffer(): GPUBuffer {
    return this.requireMesh().staticBuf;
  }

  /** The cage buffer (positions, normals; Catmull-Clark control points and vertex limits): for checks. */
  get cageBuffer(): GPUBuffer {
    return this.requireMesh().cageBuf;
  }

  get prepared(): PreparedMesh | undefined {
    return this.mesh?.prepared;
  }

  /** The scratch buffer (edge factors, counts, prefix sums): for checks. */
  get workBuffer(): GPUBuffer {
    return this.requireMesh().work;
  }

  /** Word offsets of the scratch buffer's arrays (contract/tess.ts TESS_WORK), e.g. `.edgeF`. */
  get workLayout(): Readonly<Record<WorkName, number>> {
    return this.requireMesh().workLayout.offset;
  }

  /** Float offsets of the cage buffer's arrays (contract/tess.ts TESS_CAGE), e.g. `.limitPositions`. */
  get cageLayout(): Readonly<Record<CageName, number>> {
    return this.requireMesh().cageLayout.offset;
  }

  private requireMesh(): MeshState {
    if (!this.mesh) throw new Error('Tessellator.setMesh must be called first');
    return this.mesh;
  }

  /** Record every pass of a rebuild into `encoder`. */
  encode(encoder: GPUCommandEncoder, p: FactorParams): void {
    const m = this.requireMesh();
    TESS_PARAMS.write(new DataView(this.paramsBytes), {
      viewProj: p.viewProj,
      mode: p.mode === 'fixed' ? 0 : 1,
      fixedFactor: p.fixedFactor,
      lodScale: p.lodScale,
      pixelAngle: p.fovY / Math.max(1, p.viewportHeight),
      eye: [p.eye[0], p.eye[1], p.eye[2], 0],
      turnRefresh: this.turnStale && p.mode === 'adaptive' ? 1 : 0,
    });
    if (p.mode === 'adaptive') this.turnStale = false;
    this.device.queue.writeBuffer(this.params, 0, this.paramsBytes);
    this.record(encoder, m);
  }

  private record(encoder: GPUCommandEncoder, m: MeshState): void {
    encoder.clearBuffer(m.work, 4 * m.workLayout.offset.budget, 4 * m.workLayout.length.budget);

    const pass = (label: string, stage: string) => this.timer?.beginPass(encoder, label, stage) ?? encoder.beginComputePass({ label });
    const { edgeCount: nE, triangleCount: nT } = m.prepared;
    const run = (cp: GPUComputePassEncoder, name: PassName, groups: [number, number]) => {
      cp.setPipeline(this.pipelineOf(name, m));
      cp.setBindGroup(0, m.groups[name]!);
      cp.dispatchWorkgroups(...groups);
    };

    if (m.cc) {
      const cp = pass('cc patch build', 'subdivision');
      this.recordPatchBuild(cp, m);
      cp.end();
    }
    this.recordAccBuild(encoder, m);
    {
      const cp = pass('tess bulge', 'factors');
      run(cp, 'bulge', groupsFor(nT));
      cp.end();
    }
    {
      // The edges' factors and the counts at every budget candidate, their lanes summed by
      // block, the budget's choice, and the chosen lanes' prefix sums (wgsl/tess/scan.wgsl).
      const cp = pass('tess factors + count + scan', 'count+budget');
      run(cp, 'count', groupsFor(nT));
      const blocks = Math.ceil(Math.max(nE, nT, 1) / SCAN_BLOCK);
      run(cp, 'scanReduce', [blocks, SCANS * BUDGET_CANDIDATES]);
      run(cp, 'scanDown', [blocks, SCANS]);
      cp.end();
    }
    {
      const cp = pass('tess plan', 'plan');
      run(cp, 'plan', groupsFor(nT));
      cp.end();
    }
    {
      // Every output vertex (the welded corners and edge points, then the triangles' interior
      // vertices: an indirect dispatch sized by the budget), then every output triangle (a
      // workgroup per cage triangle).
      const cp = pass('tess emit', 'tessellate');
      cp.setPipeline(this.pipelineOf('emitVertices', m));
      cp.setBindGroup(0, m.groups.emitVertices!);
      cp.dispatchWorkgroupsIndirect(this.emitArgs, 0);
      cp.setPipeline(this.pipelineOf('emitTriangles', m));
      cp.setBindGroup(0, m.groups.emitTriangles!);
      cp.dispatchWorkgroups(...grid2d(nT));
      cp.end();
    }

    this.timer?.resolve(encoder);
  }

  /** The ACC patch build (its own pass, src/gpu/acc/patches.ts): control points from the cage positions,
   * then copied into cageBuf, where the emit passes read them. */
  private recordAccBuild(encoder: GPUCommandEncoder, m: MeshState): void {
    if (!m.acc) return;
    m.acc.patches.encode(encoder, m.cageBuf);
    const bytes = 16 * m.acc.patches.topology.nPoints;
    if (bytes) encoder.copyBufferToBuffer(m.acc.patches.pointBuffer, 0, m.cageBuf, 4 * m.cageLayout.offset.accPoints, bytes);
  }

  private recordPatchBuild(cp: GPUComputePassEncoder, m: MeshState): void {
    const cc = m.cc!;
    cp.setPipeline(this.pipelineOf('ccPoints', m));
    for (const r of m.ccRanges) {
      if (!r.count) continue;
      cp.setBindGroup(0, r.group);
      cp.dispatchWorkgroups(...groupsFor(r.count));
    }
    const run = (name: PassName, groups: [number, number]) => {
      cp.setBindGroup(0, m.groups[name]!);
      cp.setPipeline(this.pipelineOf(name, m));
      cp.dispatchWorkgroups(...groups);
    };
    if (cc.sliceWorkgroups) run('ccSlices', grid2d(cc.sliceWorkgroups));
    // The fans' limits, then every prepared vertex's (one dispatch: wgsl/cc/build.wgsl limits).
    run('ccLimits', groupsFor(cc.fanCount + m.prepared.vertexCount));
  }

  /** Record only the Catmull-Clark patch build (control points and vertex limits from the
   * current cage positions): what a deforming cage needs before the next tessellation. encode()
   * runs it too. */
  encodePatchBuild(encoder: GPUCommandEncoder): void {
    const m = this.requireMesh();
    this.recordAccBuild(encoder, m);
    if (!m.cc) return;
    const cp = encoder.beginComputePass({ label: 'cc patch build' });
    this.recordPatchBuild(cp, m);
    cp.end();
  }

  /** GPU milliseconds per stage of the newest submitted rebuild ({} without timestamp queries);
   * a second call while one read is in flight gets the same answer (then `timingUnread` says
   * whether a newer rebuild waits to be read). */
  readTimings(): Promise<Record<string, number>> {
    return this.timer?.read() ?? Promise.resolve({});
  }

  /** A rebuild's timestamps wait to be read (it was submitted while a read was in flight). */
  get timingUnread(): boolean {
    return this.timer?.unread ?? false;
  }

  /** The timestamps' readback never settled (src/gpu/device/map-within.ts): rebuilds go untimed. */
  get timingStalled(): boolean {
    return this.timer?.stalled ?? false;
  }

  private releaseMesh(): void {
    if (!this.mesh) return;
    this.mesh.staticBuf.destroy();
    this.mesh.cageBuf.destroy();
    this.mesh.work.destroy();
    for (const u of this.mesh.uniforms) u.destroy();
    this.mesh = undefined;
  }

  destroy(): void {
    this.releaseMesh();
    for (const b of [
      this.output.positions,
      this.output.normals,
      this.output.bary,
      this.output.srcTri,
      this.output.indices,
      this.output.drawArgs,
      this.output.counts,
      this.params,
      this.emitArgs,
    ])
      b.destroy();
    this.timer?.destroy();
  }
}
