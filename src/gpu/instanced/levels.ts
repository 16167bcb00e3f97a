/**
 * InstancedLevels: what the instanced tessellator holds and computes before any draw (the base of
 * InstancedTessellator, src/gpu/instanced/instanced.ts, which draws it): the pipelines, bind group
 * layouts and uniforms made once, a cage's topology, patterns, cage and work buffers (setMesh,
 * updateCage), and the level passes (encodeLevels: wgsl/instanced/levels.wgsl) that leave each
 * edge's and patch's level, each bucket's patch list and its draw record on the GPU.
 */
import commonWgsl from '../../../wgsl/instanced/common.wgsl?raw';
import levelsWgsl from '../../../wgsl/instanced/levels.wgsl?raw';
import factorRuleWgsl from '../../../wgsl/tess/factor-rule.wgsl?raw';
import triSurfaceWgsl from '../../../wgsl/instanced/surface-tri.wgsl?raw';
import accSurfaceWgsl from '../../../wgsl/instanced/surface-acc.wgsl?raw';
import plainVertexWgsl from '../../../wgsl/instanced/vertex-plain.wgsl?raw';
import phongSurfaceWgsl from '../../../wgsl/surface/phong.wgsl?raw';
import { ACC_ACCESSORS_WGSL, ACC_SURFACE_WGSL, type AccPatches } from '../acc/patches.ts';
import { checkCCSource, instancedCCSurfaceWgsl } from './surface-cc.ts';
import type { Tessellator } from '../tess/tessellator.ts';
import { checkLender, instancedDisplaceWgsl, setLenderDisplacement } from './displace-vertex.ts';
import type { DisplacementSettings } from '../tess/displacement-map.ts';
import { constantsWgsl, grid2d, WORKGROUP_SIZE } from '../contract/constants.ts';
import { wgslConstants, wgslF32 } from '../contract/define.ts';
import { createLevelPipelines, type LevelPass, type LevelPipeline } from './level-pipelines.ts';
import { PHONG_ALPHA } from '../contract/constants.ts';
import { ONE } from '../../pattern/fixed.ts';
import type { ArenaLayout } from '../contract/define.ts';
import { readBuffer } from '../device/readback.ts';
import { phongTriAlphas } from '../surface/phong-alpha.ts';
import { packPatterns, POW2_LEVEL_COUNT, POW2_LEVELS } from '../../pattern/pow2.ts';
import {
  INST_CAGE,
  INST_PARAMS,
  INST_BUCKET,
  INST_OWNER_WORD,
  INST_FRAME,
  BUCKETS,
  RECORD_THREADS,
  BUCKET_STRIDE,
  DRAW_ARGS_BYTES,
  INST_BUCKET_GROUP,
  INST_DRAW_MESH_GROUP,
  INST_FRAME_GROUP,
  INST_HEADLESS_GROUP,
  INST_LEVELS_GROUP,
  INST_STATIC,
  INST_SURFACE_GROUP,
  INST_WORK,
  type InstSurfaceBinding,
  PATCH_WORDS,
} from './buffer-layouts.ts';
import type { InstancedMesh } from './prepare-patches.ts';
import { LEVEL_DEFAULTS, LEVEL_MODE, type InstancedOptions, type LevelParams } from './instanced-options.ts';

export class InstancedLevels {
  readonly patterns = packPatterns();
  /** 14 drawIndexedIndirect records (5 u32 each), rewritten by every encodeLevels. */
  readonly drawArgs: GPUBuffer;
  /** The patterns' local indices (all levels), bound by encodeDraw. */
  readonly indexBuffer: GPUBuffer;
  private readonly params: GPUBuffer;
  private readonly paramsBytes = new ArrayBuffer(INST_PARAMS.size);
  private readonly bucketUniform: GPUBuffer;
  protected readonly frame: GPUBuffer;
  /** The level passes: each with the explicit layouts of what its entry point reads (usedBindings)
   * in group 0 and, where it evaluates the surface, group 3. */
  private readonly levelPipelines: Record<LevelPass, LevelPipeline>;
  /** What group 3 binds for this surface (INST_SURFACE_GROUP's names): nothing on plain Phong. */
  private readonly surfaceNames: InstSurfaceBinding[];
  protected readonly layouts: {
    mesh: GPUBindGroupLayout;
    bucket: GPUBindGroupLayout;
    frame: GPUBindGroupLayout;
    out: GPUBindGroupLayout;
    /** Group 3 of an ACC surface: its patches and control points. */
    surface: GPUBindGroupLayout;
  };
  protected readonly code: (...parts: string[]) => string;
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
  protected readonly renderLayout: GPUPipelineLayout;
  protected readonly colorFormat: GPUTextureFormat;
  protected readonly depthFormat: GPUTextureFormat;
  protected readonly sampleCount: number;
  protected readonly bucketGroup: GPUBindGroup;
  protected readonly frameGroup: GPUBindGroup;
  protected mesh?: {
    m: InstancedMesh;
    staticBuf: GPUBuffer;
    cageBuf: GPUBuffer;
    /** Float offsets of the cage buffer's arrays (INST_CAGE). */
    cageLayout: ArenaLayout<(typeof INST_CAGE.names)[number]>;
    work: GPUBuffer;
    layout: ArenaLayout<(typeof INST_WORK.names)[number]>;
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
    this.cc = opts.surface === 'lent-limit';
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
    // Group 3 (INST_SURFACE_GROUP): the exact surface's borrowed buffers; an ACC surface's patches
    // and points; a displacement lender's three (the exact surface's source lends its own).
    this.surfaceNames = this.cc
      ? ['ccParams', 'ccStatic', 'ccCage', 'ccWork']
      : [
          ...(this.acc ? (['accPatches', 'accPoints'] as const) : []),
          ...(this.displaced ? (['ccParams', 'ccStatic', 'ccCage'] as const) : []),
        ];
    const surfaceDeclarations = this.surfaceNames.length ? INST_SURFACE_GROUP.wgsl(this.surfaceNames) : '';
    const surface = this.acc
      ? [ACC_ACCESSORS_WGSL, ACC_SURFACE_WGSL, accSurfaceWgsl].join('\n')
      : this.cc
        ? instancedCCSurfaceWgsl()
        : [triSurfaceWgsl, opts.surfaceWgsl ?? phongSurfaceWgsl].join('\n');
    const kind = this.acc ? 'acc' : this.cc ? 'lent-limit' : 'evalSurface';
    const vertexSurface = this.displaced ? instancedDisplaceWgsl(kind) : plainVertexWgsl;
    const code = (...parts: string[]) =>
      [
        constantsWgsl,
        wgslConstants({ ONE, RECORD_THREADS, PATCH_WORDS, LEVELS: POW2_LEVEL_COUNT, MAX_LEVEL: POW2_LEVELS[POW2_LEVEL_COUNT - 1] }),
        `const PHONG_ALPHA: f32 = ${wgslF32(PHONG_ALPHA)};`,
        INST_OWNER_WORD.wgsl,
        INST_PARAMS.wgsl,
        INST_BUCKET.wgsl,
        commonWgsl,
        surfaceDeclarations,
        ...parts,
        surface,
        vertexSurface,
      ].join('\n');
    this.code = code;
    const levelsCode = code(INST_LEVELS_GROUP.wgsl(), factorRuleWgsl, levelsWgsl);
    this.levelPipelines = createLevelPipelines(device, levelsCode, this.surfaceNames);

    // Explicit layouts, from the bind group declarations: one bucket bind group with a dynamic
    // offset, shared by the lit, shadow and headless pipelines.
    this.layouts = {
      mesh: device.createBindGroupLayout({ label: 'instanced mesh', entries: INST_DRAW_MESH_GROUP.layoutEntries() }),
      bucket: device.createBindGroupLayout({ label: 'instanced bucket', entries: INST_BUCKET_GROUP.layoutEntries() }),
      frame: device.createBindGroupLayout({ label: 'instanced frame', entries: INST_FRAME_GROUP.layoutEntries() }),
      out: device.createBindGroupLayout({ label: 'instanced headless outputs', entries: INST_HEADLESS_GROUP.layoutEntries() }),
      surface: device.createBindGroupLayout({
        label: this.cc ? 'instanced Catmull-Clark surface' : this.acc ? 'instanced ACC surface' : 'instanced displacement lender',
        entries: INST_SURFACE_GROUP.layoutEntries(this.surfaceNames),
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
      entries: [{ binding: INST_BUCKET_GROUP.binding.bucket, resource: { buffer: this.bucketUniform, size: INST_BUCKET.size } }],
    });
    this.frame = device.createBuffer({
      label: 'instanced frame',
      size: INST_FRAME.size,
      usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
    });
    this.frameGroup = device.createBindGroup({
      label: 'instanced frame',
      layout: this.layouts.frame,
      entries: [{ binding: INST_FRAME_GROUP.binding.frame, resource: { buffer: this.frame } }],
    });
  }

  /** A pipeline's bind group layouts, with the ACC or Catmull-Clark surface's at group 3. */
  protected withSurface(groups: GPUBindGroupLayout[]): GPUBindGroupLayout[] {
    return this.acc || this.cc || this.displaced ? [...groups, this.layouts.surface] : groups;
  }

  /** Bind the ACC or Catmull-Clark surface's buffers (group 3), where there is one. */
  protected bindSurface(pass: GPURenderPassEncoder | GPUComputePassEncoder): void {
    if (this.surfaceGroup) pass.setBindGroup(3, this.surfaceGroup);
  }

  /** Group 3's entries for the current mesh (ACC patches, or the lending tessellator's buffers;
   * with displacement on Phong and ACC, the lender's). */
  private surfaceEntries(names: readonly InstSurfaceBinding[] = this.surfaceNames): GPUBindGroupEntry[] {
    // The exact surface's source lends its own arenas; a lender lends three of the same names.
    const lender = this.ccSource ?? this.dispSource;
    const buffers: Partial<Record<InstSurfaceBinding, GPUBuffer>> = {
      ccParams: lender?.paramsBuffer,
      ccStatic: lender?.staticBuffer,
      ccCage: lender?.cageBuffer,
      ccWork: this.ccSource?.workBuffer,
      accPatches: this.accPatches?.patchBuffer,
      accPoints: this.accPatches?.pointBuffer,
    };
    return names.map((name) => {
      const buffer = buffers[name];
      if (!buffer) throw new Error(`instanced surface: nothing to bind as ${name}`);
      return { binding: INST_SURFACE_GROUP.binding[name], resource: { buffer } };
    });
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
    const staticLayout = INST_STATIC.layout({
      triangles: pr.triangleCount,
      patches: m.patchCount,
      edges: m.edgeCount,
      patternIJWords: this.patterns.ij.length,
      patternIndices: this.patterns.indices.length,
    });
    const words = new Uint32Array(staticLayout.words);
    const put = (k: (typeof INST_STATIC.names)[number], data: Uint32Array) => {
      if (data.length !== staticLayout.length[k])
        throw new Error(`instanced staticBuf ${k}: ${data.length} words for ${staticLayout.length[k]}`);
      words.set(data, staticLayout.offset[k]);
    };
    put('triVerts', pr.triVerts);
    put('patches', m.patches);
    put('edgeOwner', m.edgeOwner);
    put('patternIJ', this.patterns.ij);
    put('patternIdx', this.patterns.indices);
    put('entries', entries);
    const staticBuf = device.createBuffer({
      label: 'instanced topology + patterns',
      size: words.byteLength,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
    });
    device.queue.writeBuffer(staticBuf, 0, words);
    // Positions, normals, then the Phong surface's α per triangle edge (INST_CAGE).
    const cageLayout = INST_CAGE.layout({ vertices: pr.vertexCount, triangles: pr.triangleCount });
    const cage = new Float32Array(cageLayout.words);
    cage.set(pr.positions, cageLayout.offset.positions);
    cage.set(pr.normals, cageLayout.offset.normals);
    cage.set(pr.triPhongAlpha, cageLayout.offset.phongAlpha);
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

    const layout = INST_WORK.layout({ patches: m.patchCount, edges: m.edgeCount });
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
      ...INST_STATIC.offsets(staticLayout),
      ...INST_CAGE.offsets(cageLayout),
      ...INST_WORK.offsets(layout),
    });

    // Each bucket's uniform: where its list starts and its pattern.

    const meshGroup = device.createBindGroup({
      label: 'instanced mesh',
      layout: this.layouts.mesh,
      entries: (
        [
          ['params', this.params],
          ['staticBuf', staticBuf],
          ['cageBuf', cageBuf],
          ['work', work],
        ] as const
      ).map(([name, buffer]) => ({ binding: INST_DRAW_MESH_GROUP.binding[name], resource: { buffer } })),
    });
    this.mesh = { m, staticBuf, cageBuf, cageLayout, work, layout, meshGroup };
    const buckets = new ArrayBuffer(BUCKET_STRIDE * BUCKETS);
    const lists = this.listBases();
    this.patterns.entries.forEach((_, b) => INST_BUCKET.write(new DataView(buckets, BUCKET_STRIDE * b), this.bucketFields(b, lists)));
    device.queue.writeBuffer(this.bucketUniform, 0, buckets);
  }

  /** New cage positions and vertex normals for the same topology (the Catmull-Clark surface's
   * lending tessellator gets them too; the next encodeLevels runs its patch build). */
  updateCage(positions: Float32Array, normals: Float32Array): void {
    const m = this.requireMesh();
    this.device.queue.writeBuffer(m.cageBuf, 4 * m.cageLayout.offset.positions, positions);
    this.device.queue.writeBuffer(m.cageBuf, 4 * m.cageLayout.offset.normals, normals);
    // The Phong surface's α per edge follows the normals (phong.ts phongTriAlphas).
    this.device.queue.writeBuffer(m.cageBuf, 4 * m.cageLayout.offset.phongAlpha, phongTriAlphas(m.m.prepared, positions, normals));
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
    this.device.queue.writeBuffer(m.work, 4 * m.layout.offset.wanted, levels);
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
      mode: LEVEL_MODE[lp.mode],
      staticLevel: lp.level ?? LEVEL_DEFAULTS.level,
      lodScale: lp.lodScale ?? LEVEL_DEFAULTS.lodScale,
      targetPixels: lp.targetPixels ?? LEVEL_DEFAULTS.targetPixels,
      pixelError: lp.pixelError ?? LEVEL_DEFAULTS.pixelError,
    });
    this.device.queue.writeBuffer(this.params, 0, this.paramsBytes);
    // Edge codes and bucket counts start at 0 (atomicMax / atomicAdd).
    encoder.clearBuffer(m.work, 4 * m.layout.offset.edgeCode, 4 * m.m.edgeCount);
    encoder.clearBuffer(m.work, 4 * m.layout.offset.counts, 4 * BUCKETS);
    const cp = encoder.beginComputePass({ label: 'instanced levels', timestampWrites });
    const run = (name: LevelPass, groups: number, group: GPUBindGroup) => {
      cp.setPipeline(this.levelPipelines[name].pipeline);
      cp.setBindGroup(0, group);
      // A pass that evaluates the surface (the dynamic rule; the factor rule on Catmull-Clark, at
      // the cage vertices' limits) binds what it reads of group 3.
      const surface = this.levelSurfaceGroupFor(name);
      if (surface) cp.setBindGroup(3, surface);
      cp.dispatchWorkgroups(...grid2d(groups));
    };
    const nP = m.m.patchCount;
    if (lp.mode === 'dynamic') run('edgeView', Math.ceil(m.m.edgeCount / WORKGROUP_SIZE), this.levelGroupFor('edgeView'));
    else if (lp.mode === 'factor-rule')
      run('edgeFactorRule', Math.ceil(m.m.edgeCount / WORKGROUP_SIZE), this.levelGroupFor('edgeFactorRule'));
    else run('patchEdges', Math.ceil(nP / WORKGROUP_SIZE), this.levelGroupFor('patchEdges'));
    run('bucketPatches', Math.ceil(nP / WORKGROUP_SIZE), this.levelGroupFor('bucketPatches'));
    run('records', 1, this.levelGroupFor('records'));
    cp.end();
  }

  // Each level pass's groups, from its own layouts, made once per mesh (releaseMesh clears them).
  private levelGroups = new Map<string, GPUBindGroup>();
  private levelGroupFor(name: LevelPass): GPUBindGroup {
    const m = this.requireMesh();
    let g = this.levelGroups.get(name);
    if (!g) {
      const buffers: Record<keyof typeof INST_LEVELS_GROUP.binding, GPUBuffer> = {
        params: this.params,
        staticBuf: m.staticBuf,
        cageBuf: m.cageBuf,
        work: m.work,
        drawArgs: this.drawArgs,
      };
      const p = this.levelPipelines[name];
      g = this.device.createBindGroup({
        label: `instanced ${name}`,
        layout: p.layout,
        entries: p.used.map((b) => ({ binding: INST_LEVELS_GROUP.binding[b], resource: { buffer: buffers[b] } })),
      });
      this.levelGroups.set(name, g);
    }
    return g;
  }

  private levelSurfaceGroups = new Map<string, GPUBindGroup>();
  private levelSurfaceGroupFor(name: LevelPass): GPUBindGroup | undefined {
    const p = this.levelPipelines[name];
    if (!p.surfaceLayout) return undefined;
    let g = this.levelSurfaceGroups.get(name);
    if (!g) {
      g = this.device.createBindGroup({
        label: `instanced ${name} surface`,
        layout: p.surfaceLayout,
        entries: this.surfaceEntries(p.usedSurface),
      });
      this.levelSurfaceGroups.set(name, g);
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
    const counts = Uint32Array.from({ length: BUCKETS }, (_, b) => w[m.layout.offset.counts + b]);
    return {
      records,
      counts,
      edgeLevels: Uint32Array.from(
        w.subarray(m.layout.offset.edgeCode, m.layout.offset.edgeCode + m.m.edgeCount),
        (c) => 1 << (POW2_LEVEL_COUNT - c),
      ),
      patchLevels: Uint32Array.from(w.subarray(m.layout.offset.patchLevel, m.layout.offset.patchLevel + m.m.patchCount), (lg) => 1 << lg),
      lists: this.listBases().map((base, b) => w.slice(base, base + counts[b])),
    };
  }

  /** Bucket b's pattern and patch list (INST_BUCKET fields shared by the draws and the headless pass). */
  protected bucketFields(b: number, lists: number[]) {
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

  protected listBases(): number[] {
    const m = this.requireMesh();
    return Array.from({ length: BUCKETS }, (_, b) => {
      const lg = b % POW2_LEVEL_COUNT;
      return m.layout.offset.lists + (b >= POW2_LEVEL_COUNT ? POW2_LEVEL_COUNT * m.m.quadCount + lg * m.m.triCount : lg * m.m.quadCount);
    });
  }

  protected requireMesh() {
    if (!this.mesh) throw new Error('InstancedTessellator.setMesh must be called first');
    return this.mesh;
  }

  private releaseMesh(): void {
    if (!this.mesh) return;
    for (const b of [this.mesh.staticBuf, this.mesh.cageBuf, this.mesh.work]) b.destroy();
    this.levelGroups.clear();
    this.levelSurfaceGroups.clear();
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
