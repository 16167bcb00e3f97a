/**
 * Instanced power-of-two tessellation (NVIDIA's 2009 "Instanced Tessellation" sample, with the
 * T-junction snap of Dyken, Reimers and Seland 2009): one precomputed pattern per level 1, 2, 4,
 * … 64 and domain (src/pattern/pow2.ts), patches bucketed by level on the GPU, one indirect instanced draw per
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
/*
 * The folder, src/gpu/instanced/:
 *   instanced.ts          InstancedTessellator: the draws (its own lit and shadow passes, inside the
 *                         demo renderer's passes, headless in compute) and tessellateInstanced (CLI)
 *   levels.ts             InstancedLevels, its base: pipelines, the cage upload, the level passes
 *   level-pipelines.ts    the level passes' pipelines on explicit layouts (usedBindings)
 *   instanced-options.ts  InstancedOptions, LevelParams (their defaults, mode codes), factorRuleLevels
 *   buffer-layouts.ts     uniform structs and packed layouts shared with wgsl/instanced/
 *   prepare-patches.ts    the CPU preparation: InstancedMesh, prepareInstanced, patch readers
 *   cpu-twin.ts           the CPU reference of the level passes and the snap, for checks
 *   headless-output.ts    HeadlessInstanced, its welding (weldInstanced) and OBJ writers
 *   surface-cc.ts         the exact Catmull-Clark surface through a lending compute Tessellator
 *   displace-vertex.ts    displacement in the vertex function, from a lender's arenas
 */
import { LimitError } from '../../mesh/errors.ts';
import drawWgsl from '../../../wgsl/instanced/draw.wgsl?raw';
import frameWgsl from '../../../wgsl/instanced/frame.wgsl?raw';
import headlessWgsl from '../../../wgsl/instanced/headless.wgsl?raw';
import renderInstancedWgsl from '../../../wgsl/render/instanced.wgsl?raw';
import type { AccPatches } from '../acc/patches.ts';
import type { Tessellator } from '../tess/tessellator.ts';
import { litShader, meshFaceStates } from '../render/pipelines.ts';
import { PATCH_KIND_GROUP, SCENE_GROUP, SHADING_GROUP } from '../contract/render.ts';
import type { ShadingResources, SurfaceDrawer } from '../render/renderer.ts';
import { grid2d, WORKGROUP_SIZE } from '../contract/constants.ts';
import { readBuffer } from '../device/readback.ts';
import type { PreparedMesh } from '../tess/prepare.ts';
import type { Cage } from '../../mesh/types.ts';
import {
  INST_BUCKET,
  INST_BUCKET_GROUP,
  INST_DRAW_MESH_GROUP,
  INST_FRAME,
  INST_FRAME_GROUP,
  INST_HEADLESS_GROUP,
  BUCKETS,
  BUCKET_STRIDE,
  WIRE_ARGS_OFFSET,
} from './buffer-layouts.ts';
import { InstancedLevels } from './levels.ts';
import type { LevelParams } from './instanced-options.ts';
import { prepareInstanced, type InstancedMesh } from './prepare-patches.ts';
import type { HeadlessInstanced } from './headless-output.ts';

/** The vertex function's module text (wgsl/instanced/draw.wgsl) with its groups 0 and 1. */
const DRAW_WGSL = [INST_DRAW_MESH_GROUP.wgsl(), INST_BUCKET_GROUP.wgsl(), drawWgsl].join('\n');

/** The renderer's lit shading, its groups moved clear of this tessellator's: scene (0, 0) to
 * (2, 0), shadow map and sampler (1, 0–1) to (2, 1–2), and its patch colours' buffers (2, 0–1, read
 * by its own litVertex only) to (3, 10–11), past the surface group's bindings. */
const RENDERER_SCENE = SCENE_GROUP.moved(2, 0);
const RENDERER_SHADING = SHADING_GROUP.moved(2, RENDERER_SCENE.binding.scene + 1);
const RENDERER_LIT = litShader({ scene: RENDERER_SCENE, shading: RENDERER_SHADING, patchKind: PATCH_KIND_GROUP.moved(3, 10) });

export class InstancedTessellator extends InstancedLevels implements SurfaceDrawer {
  private headlessPipelineMade?: GPUComputePipeline;
  private frameModule?: GPUShaderModule;
  private litPipeline?: GPURenderPipeline;
  private shadowPipeline?: GPURenderPipeline;

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
        module: this.device.createShaderModule({
          label: 'instanced headless',
          code: this.code(DRAW_WGSL, INST_HEADLESS_GROUP.wgsl(), headlessWgsl),
        }),
        entryPoint: 'headless',
      },
    });
    return this.headlessPipelineMade;
  }

  private drawFrameModule(): GPUShaderModule {
    this.frameModule ??= this.device.createShaderModule({
      label: 'instanced draw',
      code: this.code(DRAW_WGSL, INST_FRAME.wgsl, INST_FRAME_GROUP.wgsl(), frameWgsl),
    });
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
    const sceneBgl = device.createBindGroupLayout({ label: 'instanced renderer scene', entries: RENDERER_SCENE.layoutEntries() });
    const litBgl = device.createBindGroupLayout({
      label: 'instanced renderer scene + shading',
      entries: [...RENDERER_SCENE.layoutEntries(), ...RENDERER_SHADING.layoutEntries()],
    });
    const layout = (label: string, g: GPUBindGroupLayout) =>
      device.createPipelineLayout({ label, bindGroupLayouts: this.withSurface([this.layouts.mesh, this.layouts.bucket, g]) });
    this.inRenderer = {
      res,
      module: device.createShaderModule({
        label: 'instanced in the renderer',
        code: this.code(DRAW_WGSL, RENDERER_LIT.join('\n'), renderInstancedWgsl),
      }),
      sceneGroup: device.createBindGroup({
        label: 'instanced renderer scene',
        layout: sceneBgl,
        entries: [{ binding: RENDERER_SCENE.binding.scene, resource: { buffer: res.scene } }],
      }),
      litGroup: device.createBindGroup({
        label: 'instanced renderer scene + shading',
        layout: litBgl,
        entries: [
          { binding: RENDERER_SCENE.binding.scene, resource: { buffer: res.scene } },
          { binding: RENDERER_SHADING.binding.shadowMap, resource: res.shadowMap },
          { binding: RENDERER_SHADING.binding.shadowSampler, resource: res.shadowSampler },
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
      throw new LimitError(
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
      entries: [{ binding: INST_HEADLESS_GROUP.binding.outWords, resource: { buffer: out } }],
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
      entries: [{ binding: INST_BUCKET_GROUP.binding.bucket, resource: { buffer: uniform, size: INST_BUCKET.size } }],
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
