/**
 * The compute tessellator (Hable, "Part 2: The Mesh"): whole meshes tessellated adaptively
 * into big flat buffers, welded, stored once and drawn by every pass. Takes a GPUDevice and
 * never touches the DOM, so the same code runs in the browser, in headless tests and in Node.
 *
 * Passes, in one command encoder (direct dispatches, sizes known on the CPU, except emit):
 *   budget loop, up to 3 attempts (scale 1, a scale that fits, then factor 1 everywhere):
 *     factors    one thread per edge: tess factor, line state, segments    wgsl/tess-factors.wgsl
 *     count      one thread per triangle: interior vertices and triangles   wgsl/tess-count.wgsl
 *     scan       prefix sums of the three counts                           wgsl/scan.wgsl
 *     budget     accept (and write the indirect draw args) or rescale      wgsl/tess-budget.wgsl
 *   weld         corner and edge vertices, evaluated once each              wgsl/tess-weld.wgsl
 *   tessellate   plan: one thread per triangle writes its pattern's rows   wgsl/tess-plan.wgsl
 *                emit: one thread per interior vertex, one per triangle    wgsl/tess-emit.wgsl
 *                (the only indirect dispatches: sized by the budget pass)
 * This is the talk's predict → scan → plan → emit → weld: no workgroup memory and no barriers,
 * so every output element costs the same whatever the factors (wgsl/tess-pattern.wgsl holds the
 * pattern reading shared by count, plan and emit).
 * With the Catmull-Clark surface (options.surface), a patch-build pass comes first:
 *   subdivision  refined points level by level (rule per point), the slices round
 *                extraordinary vertices (workgroup memory), their limits, and the cage
 *                vertices' limit positions and normals for the factor rule  wgsl/cc-build.wgsl
 * Attempts after the accepted one are no-ops on the GPU (they test a flag), so no readback is
 * ever needed.
 */
import commonWgsl from '../../wgsl/tess-common.wgsl?raw';
import outputsWgsl from '../../wgsl/tess-outputs.wgsl?raw';
import factorsWgsl from '../../wgsl/tess-factors.wgsl?raw';
import countWgsl from '../../wgsl/tess-count.wgsl?raw';
import budgetWgsl from '../../wgsl/tess-budget.wgsl?raw';
import weldWgsl from '../../wgsl/tess-weld.wgsl?raw';
import patternWgsl from '../../wgsl/tess-pattern.wgsl?raw';
import planWgsl from '../../wgsl/tess-plan.wgsl?raw';
import emitWgsl from '../../wgsl/tess-emit.wgsl?raw';
import scanWgsl from '../../wgsl/scan.wgsl?raw';
import phongSurfaceWgsl from '../../wgsl/surface-phong.wgsl?raw';
import { CC_SURFACE_WGSL as ccSurfaceWgsl, CC_BUILD_WGSL as ccBuildWgsl } from './cc/shaders.ts';
import type { CatmullClarkData } from './cc/build.ts';
import { defineStruct } from './layout.ts';
import { outputCapacity } from './factors.ts';
import type { PreparedMesh } from './prepare.ts';
import type { FactorParams, TessellatedMesh } from './types.ts';
import { PatternTables } from '../pattern/tables.ts';

export { prepareMesh, type PreparedMesh } from './prepare.ts';

export const PARAMS = defineStruct('Params', [
  ['viewProj', 'mat4x4<f32>'],
  ['nVerts', 'u32'],
  ['nTris', 'u32'],
  ['nEdges', 'u32'],
  ['maxFactor', 'u32'],
  ['offTriVerts', 'u32'],
  ['offTriEdges', 'u32'],
  ['offTriFrame', 'u32'],
  ['offEdgeVerts', 'u32'],
  ['offEdgeOwner', 'u32'],
  ['offVertexOwner', 'u32'],
  ['offNormals', 'u32'],
  ['offEdgeF', 'u32'],
  ['offEdgeState', 'u32'],
  ['offEdgeSegs', 'u32'],
  ['offEdgeInterior', 'u32'],
  ['offEdgeBase', 'u32'],
  ['offTriVertCount', 'u32'],
  ['offTriVertBase', 'u32'],
  ['offTriTriCount', 'u32'],
  ['offTriTriBase', 'u32'],
  ['offTriRowCount', 'u32'],
  ['offTriRowBase', 'u32'],
  ['offRows', 'u32'],
  ['offBudget', 'u32'],
  ['vertexCapacity', 'u32'],
  ['triangleCapacity', 'u32'],
  ['mode', 'u32'],
  ['fixedFactor', 'f32'],
  ['lodScale', 'f32'],
  ['pixelAngle', 'f32'],
  ['eye', 'vec4<f32>'],
  // What the factor rule reads (cageBuf offsets): the cage, or the limit surface at its vertices.
  ['offFactorPos', 'u32'],
  ['offFactorNormal', 'u32'],
  // Catmull-Clark (src/gpu/cc/build.ts): staticBuf word offsets of its tables; offCtrl: cageBuf
  // offset of the refined points (point p ≥ nVerts at offCtrl + 3(p − nVerts)).
  ['ccTri', 'u32'],
  ['ccPoly', 'u32'],
  ['ccRegions', 'u32'],
  ['ccPatchIdx', 'u32'],
  ['ccFans', 'u32'],
  ['ccSectors', 'u32'],
  ['ccThreads', 'u32'],
  ['ccCos', 'u32'],
  ['ccRules', 'u32'],
  ['ccInputs', 'u32'],
  ['ccVertexFan', 'u32'],
  ['nFans', 'u32'],
  ['ccSliceGroups', 'u32'],
  ['ccMaxDepth', 'u32'],
  ['offCtrl', 'u32'],
  ['ccFlat', 'u32'],
] as const);

const SCAN_PARAMS = defineStruct('ScanParams', [
  ['inOff', 'u32'],
  ['outOff', 'u32'],
  ['n', 'u32'],
  ['sumsOff', 'u32'],
  ['skipOff', 'u32'],
] as const);
/** Values one scan workgroup covers (wgsl/scan.wgsl BLOCK). */
const SCAN_BLOCK = 256 * 16;

const GRID_X = 65535;
const ATTEMPTS = 3;

/** Workgroup counts as a 2D grid: WebGPU caps each dimension at 65535 (an over-limit
 * indirect dispatch silently does nothing; a direct one is a validation error). */
export function grid2d(groups: number): [number, number] {
  if (groups <= GRID_X) return [Math.max(groups, 1), 1];
  return [GRID_X, Math.ceil(groups / GRID_X)];
}

interface WorkLayout {
  edgeF: number;
  edgeState: number;
  edgeSegs: number;
  edgeInterior: number;
  edgeBase: number;
  triVertCount: number;
  triVertBase: number;
  triTriCount: number;
  triTriBase: number;
  triRowCount: number;
  triRowBase: number;
  rows: number;
  sums: number;
  budget: number;
  words: number;
}

const SCANS = 4;

/** Scratch words: per edge and per triangle counts and their prefix sums, the planned rows (a
 * triangle has at most maxFactor + 1 rows, two words each), scan block sums, budget state. */
function workLayout(nE: number, nT: number, maxFactor: number): WorkLayout {
  let at = 0;
  const take = (n: number) => {
    const o = at;
    at += n;
    return o;
  };
  const sumsPerScan = Math.ceil(Math.max(nE, nT, 1) / SCAN_BLOCK) + 1;
  return {
    edgeF: take(nE),
    edgeState: take(nE),
    edgeSegs: take(nE),
    edgeInterior: take(nE),
    edgeBase: take(nE + 1),
    triVertCount: take(nT),
    triVertBase: take(nT + 1),
    triTriCount: take(nT),
    triTriBase: take(nT + 1),
    triRowCount: take(nT),
    triRowBase: take(nT + 1),
    rows: take(2 * (maxFactor + 1) * nT),
    sums: take(SCANS * sumsPerScan),
    budget: take(4),
    words: at,
  };
}

type PassName =
  | 'factors'
  | 'count'
  | 'budget'
  | 'corners'
  | 'edges'
  | 'plan'
  | 'emitVertices'
  | 'emitTriangles'
  | 'ccPoints'
  | 'ccSlices'
  | 'ccLimits'
  | 'ccVertexLimits';
/** Bindings each pass uses (its pipeline layout is derived from the WGSL: 'auto'). */
const PASS_BINDINGS: Record<PassName, number[]> = {
  factors: [0, 1, 2, 3],
  count: [0, 1, 3],
  budget: [0, 3, 9, 10, 11],
  corners: [0, 1, 2, 3, 4, 5, 6, 7],
  edges: [0, 1, 2, 3, 4, 5, 6, 7],
  plan: [0, 1, 3],
  emitVertices: [0, 1, 2, 3, 4, 5, 6, 7],
  emitTriangles: [0, 1, 3, 8],
  // ccPoints: its binding 3 is a per-dispatch range (one bind group per level range, setMesh).
  ccPoints: [],
  ccSlices: [0, 1, 2],
  ccLimits: [0, 1, 2],
  ccVertexLimits: [0, 1, 2],
};

export interface TessellatorOptions {
  vertexCapacity?: number;
  triangleCapacity?: number;
  /** WGSL that defines `fn evalSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint` for the emit
   * passes (see wgsl/tess-common.wgsl). Default: Phong tessellation (wgsl/surface-phong.wgsl). */
  surfaceWgsl?: string;
  /** 'catmull-clark': the exact Catmull-Clark limit surface (wgsl/surface-cc.wgsl); setMesh then
   * needs the tables of src/gpu/cc/build.ts buildCatmullClark. Default 'phong'. */
  surface?: 'phong' | 'catmull-clark';
  /** Catmull-Clark: blend from the flat triangle (corner limit positions) to the surface as the
   * tess factor rises from 1 to 4, so nothing pops (default true; off for exact checks). */
  flatBaseline?: boolean;
}

/** Timing categories reported by readTimings (ms). */
export const TIMED_STAGES = ['subdivision', 'factors', 'count+budget', 'weld', 'tessellate'] as const;

export class Tessellator {
  readonly output: TessellatedMesh;
  readonly maxFactor: number;
  readonly surface: 'phong' | 'catmull-clark';
  /** Catmull-Clark flat-baseline blend by tess factor (see TessellatorOptions.flatBaseline). */
  flatBaseline: boolean;
  private readonly params: GPUBuffer;
  private readonly paramsBytes: ArrayBuffer;
  /** Indirect dispatch arguments of the emit passes, written by the budget pass. */
  private readonly emitArgs: GPUBuffer;
  private readonly pipelines: Record<PassName, GPUComputePipeline>;
  private readonly scanPipelines: { blocks: GPUComputePipeline; sums: GPUComputePipeline; add: GPUComputePipeline };
  private readonly scanLayout: GPUBindGroupLayout;
  private mesh?: {
    prepared: PreparedMesh;
    staticBuf: GPUBuffer;
    cageBuf: GPUBuffer;
    work: GPUBuffer;
    layout: WorkLayout;
    groups: Record<PassName, GPUBindGroup>;
    scans: { group: GPUBindGroup; n: number }[];
    cc?: CatmullClarkData;
    ccRanges: { group: GPUBindGroup; count: number }[];
  };
  private readonly timing?: {
    set: GPUQuerySet;
    resolve: GPUBuffer;
    read: GPUBuffer;
    pending: boolean;
    stages: string[];
    reading?: Promise<Record<string, number>>;
  };

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
    const cap = outputCapacity(device.limits, opts);
    const buffer = (label: string, size: number, usage: number) => device.createBuffer({ label, size: Math.max(16, size), usage });
    const S = GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST;
    this.output = {
      positions: buffer('tess positions', 12 * cap.vertexCapacity, S | GPUBufferUsage.VERTEX),
      normals: buffer('tess normals', 12 * cap.vertexCapacity, S | GPUBufferUsage.VERTEX),
      bary: buffer('tess barycentrics', 4 * cap.vertexCapacity, S | GPUBufferUsage.VERTEX),
      srcTri: buffer('tess source triangles', 4 * cap.vertexCapacity, S | GPUBufferUsage.VERTEX),
      indices: buffer('tess indices', 12 * cap.triangleCapacity, S | GPUBufferUsage.INDEX),
      drawArgs: buffer('tess draw args', 20, S | GPUBufferUsage.INDIRECT),
      counts: buffer('tess counts', 16, S),
      vertexCapacity: cap.vertexCapacity,
      triangleCapacity: cap.triangleCapacity,
    };
    this.emitArgs = buffer('tess emit dispatch args', 24, GPUBufferUsage.STORAGE | GPUBufferUsage.INDIRECT);
    this.paramsBytes = new ArrayBuffer(PARAMS.size);
    this.params = device.createBuffer({ label: 'tess params', size: PARAMS.size, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });

    const module = (label: string, ...parts: string[]) =>
      device.createShaderModule({ label, code: [PARAMS.wgsl, commonWgsl, ...parts].join('\n') });
    const pipeline = (label: string, mod: GPUShaderModule, entryPoint = 'main') =>
      device.createComputePipeline({ label, layout: 'auto', compute: { module: mod, entryPoint } });
    const cc = this.surface === 'catmull-clark';
    const surface = opts.surfaceWgsl ?? (cc ? ccSurfaceWgsl : phongSurfaceWgsl);
    const weld = module('tess weld', surface, outputsWgsl, weldWgsl);
    this.pipelines = {
      factors: pipeline('tess factors', module('tess factors', factorsWgsl)),
      count: pipeline('tess count', module('tess count', patternWgsl, countWgsl)),
      budget: pipeline('tess budget', module('tess budget', budgetWgsl)),
      corners: pipeline('tess weld corners', weld, 'corners'),
      edges: pipeline('tess weld edges', weld, 'edges'),
      plan: pipeline('tess plan', module('tess plan', patternWgsl, planWgsl)),
    } as Record<PassName, GPUComputePipeline>;
    const emit = module('tess emit', surface, outputsWgsl, patternWgsl, emitWgsl);
    this.pipelines.emitVertices = pipeline('tess emit vertices', emit, 'vertices');
    this.pipelines.emitTriangles = pipeline('tess emit triangles', emit, 'triangles');
    if (cc) {
      const build = device.createShaderModule({ label: 'cc patch build', code: [PARAMS.wgsl, ccBuildWgsl].join('\n') });
      this.pipelines.ccPoints = pipeline('cc level points', build, 'points');
      this.pipelines.ccSlices = pipeline('cc ev slices', build, 'slices');
      this.pipelines.ccLimits = pipeline('cc fan limits', build, 'limits');
      this.pipelines.ccVertexLimits = pipeline('cc vertex limits', build, 'vlimits');
    }
    // The three scan steps share one bind group, so they share an explicit layout.
    this.scanLayout = device.createBindGroupLayout({
      label: 'scan',
      entries: [
        { binding: 0, visibility: GPUShaderStage.COMPUTE, buffer: { type: 'uniform' } },
        { binding: 1, visibility: GPUShaderStage.COMPUTE, buffer: { type: 'storage' } },
      ],
    });
    const scanModule = device.createShaderModule({ label: 'scan', code: scanWgsl });
    const scanPipelineLayout = device.createPipelineLayout({ label: 'scan', bindGroupLayouts: [this.scanLayout] });
    const scanPipeline = (label: string, entryPoint: string) =>
      device.createComputePipeline({ label, layout: scanPipelineLayout, compute: { module: scanModule, entryPoint } });
    this.scanPipelines = {
      blocks: scanPipeline('scan blocks', 'scanBlocks'),
      sums: scanPipeline('scan sums', 'scanSums'),
      add: scanPipeline('scan add', 'addSums'),
    };

    if (device.features.has('timestamp-query')) {
      const count = 2 * 3 * ATTEMPTS + 6;
      this.timing = {
        set: device.createQuerySet({ label: 'tess timestamps', type: 'timestamp', count }),
        resolve: device.createBuffer({
          label: 'tess timestamps resolve',
          size: 8 * count,
          usage: GPUBufferUsage.QUERY_RESOLVE | GPUBufferUsage.COPY_SRC,
        }),
        read: device.createBuffer({
          label: 'tess timestamps read',
          size: 8 * count,
          usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
        }),
        pending: false,
        stages: [],
      };
    }
  }

  /** Upload a prepared mesh: topology once; positions may be updated later (updateCage). The
   * Catmull-Clark surface also needs the mesh's tables (src/gpu/cc/build.ts buildCatmullClark). */
  setMesh(prepared: PreparedMesh, cc?: CatmullClarkData): void {
    const device = this.device;
    if (prepared.triangleCount === 0) throw new Error('the mesh has no faces to tessellate');
    if (this.surface === 'catmull-clark' && !cc)
      throw new Error('the Catmull-Clark surface needs the tables of buildCatmullClark(cage, prepared)');
    if (this.surface !== 'catmull-clark') cc = undefined;
    if (prepared.triangleCount > this.output.triangleCapacity || prepared.vertexCount + prepared.edgeCount > this.output.vertexCapacity) {
      throw new Error(
        `the cage is too large for the output buffers even at factor 1 (${prepared.triangleCount} triangles, capacity ${this.output.triangleCapacity})`,
      );
    }
    this.releaseMesh();
    const parts = [prepared.triVerts, prepared.triEdges, prepared.triFrame, prepared.edgeVerts, prepared.edgeOwner, prepared.vertexOwner];
    const offsets: number[] = [];
    let at = this.tables.length;
    for (const p of parts) {
      offsets.push(at);
      at += p.length;
    }
    const ccBase = at;
    if (cc) at += cc.words.length;
    const staticWords = new Uint32Array(at);
    staticWords.set(this.tables, 0);
    parts.forEach((p, i) => staticWords.set(p, offsets[i]));
    if (cc) staticWords.set(cc.words, ccBase);
    const staticBuf = device.createBuffer({
      label: 'tess tables + topology',
      size: staticWords.byteLength,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
    });
    device.queue.writeBuffer(staticBuf, 0, staticWords);

    const nV = prepared.vertexCount;
    // Catmull-Clark: refined points (levels, slices, fan limits), then limit positions and
    // normals of the cage vertices.
    const offCtrl = 6 * nV;
    const offLimits = offCtrl + 3 * (cc?.pointCount ?? 0);
    const cageWords = new Float32Array(cc ? offLimits + 6 * nV : 6 * nV);
    cageWords.set(prepared.positions, 0);
    cageWords.set(prepared.normals, 3 * prepared.vertexCount);
    const cageBuf = device.createBuffer({
      label: 'tess cage',
      size: Math.max(16, cageWords.byteLength),
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST | GPUBufferUsage.COPY_SRC,
    });
    device.queue.writeBuffer(cageBuf, 0, cageWords);

    const layout = workLayout(prepared.edgeCount, prepared.triangleCount, this.maxFactor);
    if (4 * layout.words > device.limits.maxStorageBufferBindingSize) {
      throw new Error(`the cage is too large: its scratch buffer (${4 * layout.words} bytes) exceeds the device's storage binding limit`);
    }
    const work = device.createBuffer({
      label: 'tess work',
      size: 4 * layout.words,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST,
    });

    const view = new DataView(this.paramsBytes);
    PARAMS.write(view, {
      nVerts: prepared.vertexCount,
      nTris: prepared.triangleCount,
      nEdges: prepared.edgeCount,
      maxFactor: this.maxFactor,
      offTriVerts: offsets[0],
      offTriEdges: offsets[1],
      offTriFrame: offsets[2],
      offEdgeVerts: offsets[3],
      offEdgeOwner: offsets[4],
      offVertexOwner: offsets[5],
      offNormals: 3 * prepared.vertexCount,
      offEdgeF: layout.edgeF,
      offEdgeState: layout.edgeState,
      offEdgeSegs: layout.edgeSegs,
      offEdgeInterior: layout.edgeInterior,
      offEdgeBase: layout.edgeBase,
      offTriVertCount: layout.triVertCount,
      offTriVertBase: layout.triVertBase,
      offTriTriCount: layout.triTriCount,
      offTriTriBase: layout.triTriBase,
      offTriRowCount: layout.triRowCount,
      offTriRowBase: layout.triRowBase,
      offRows: layout.rows,
      offBudget: layout.budget,
      vertexCapacity: this.output.vertexCapacity,
      triangleCapacity: this.output.triangleCapacity,
      offFactorPos: cc ? offLimits : 0,
      offFactorNormal: cc ? offLimits + 3 * nV : 3 * nV,
      ccTri: ccBase + (cc?.offTri ?? 0),
      ccPoly: ccBase + (cc?.offPoly ?? 0),
      ccRegions: ccBase + (cc?.offRegions ?? 0),
      ccPatchIdx: ccBase + (cc?.offPatchIdx ?? 0),
      ccFans: ccBase + (cc?.offFans ?? 0),
      ccSectors: ccBase + (cc?.offSectors ?? 0),
      ccThreads: ccBase + (cc?.offThreads ?? 0),
      ccCos: ccBase + (cc?.offCos ?? 0),
      ccRules: ccBase + (cc?.offRules ?? 0),
      ccInputs: ccBase + (cc?.offInputs ?? 0),
      ccVertexFan: ccBase + (cc?.offVertexFan ?? 0),
      nFans: cc?.fanCount ?? 0,
      ccSliceGroups: cc?.sliceWorkgroups ?? 0,
      ccMaxDepth: cc?.maxDepth ?? 0,
      offCtrl,
    });

    const resources: Record<number, GPUBindingResource> = {
      0: { buffer: this.params },
      1: { buffer: staticBuf },
      2: { buffer: cageBuf },
      3: { buffer: work },
      4: { buffer: this.output.positions },
      5: { buffer: this.output.normals },
      6: { buffer: this.output.bary },
      7: { buffer: this.output.srcTri },
      8: { buffer: this.output.indices },
      9: { buffer: this.output.drawArgs },
      10: { buffer: this.output.counts },
      11: { buffer: this.emitArgs },
    };
    const groups = {} as Record<PassName, GPUBindGroup>;
    for (const name of Object.keys(PASS_BINDINGS) as PassName[]) {
      if (!this.pipelines[name] || !PASS_BINDINGS[name].length) continue;
      groups[name] = device.createBindGroup({
        label: `tess ${name}`,
        layout: this.pipelines[name].getBindGroupLayout(0),
        entries: PASS_BINDINGS[name].map((binding) => ({ binding, resource: resources[binding] })),
      });
    }
    const sumsPerScan = Math.ceil(Math.max(prepared.edgeCount, prepared.triangleCount, 1) / SCAN_BLOCK) + 1;
    const scanDefs = [
      { inOff: layout.edgeInterior, outOff: layout.edgeBase, n: prepared.edgeCount },
      { inOff: layout.triVertCount, outOff: layout.triVertBase, n: prepared.triangleCount },
      { inOff: layout.triTriCount, outOff: layout.triTriBase, n: prepared.triangleCount },
      { inOff: layout.triRowCount, outOff: layout.triRowBase, n: prepared.triangleCount },
    ];
    const scans = scanDefs.map((s, i) => {
      const bytes = new ArrayBuffer(SCAN_PARAMS.size);
      // Skip the scan once the budget has accepted an attempt (its "accepted" word).
      SCAN_PARAMS.write(new DataView(bytes), { ...s, sumsOff: layout.sums + i * sumsPerScan, skipOff: layout.budget });
      const uniform = device.createBuffer({
        label: `scan params ${i}`,
        size: SCAN_PARAMS.size,
        usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
      });
      device.queue.writeBuffer(uniform, 0, bytes);
      const group = device.createBindGroup({
        label: `scan ${i}`,
        layout: this.scanLayout,
        entries: [
          { binding: 0, resource: { buffer: uniform } },
          { binding: 1, resource: { buffer: work } },
        ],
      });
      return { group, n: s.n, uniform };
    });
    // Catmull-Clark level dispatches: per level, its face points, then its edge and vertex
    // points (which read the new face points); each with its range in a small uniform.
    const ccRanges: { group: GPUBindGroup; count: number }[] = [];
    const rangeUniforms: GPUBuffer[] = [];
    for (const [ff, fc, vf, vc] of cc?.levelRanges ?? []) {
      for (const [first, count] of [
        [ff, fc],
        [vf, vc],
      ]) {
        const u = device.createBuffer({ label: 'cc level range', size: 16, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
        device.queue.writeBuffer(u, 0, Uint32Array.of(first, count, 0, 0));
        rangeUniforms.push(u);
        ccRanges.push({
          count,
          group: device.createBindGroup({
            label: 'cc level points',
            layout: this.pipelines.ccPoints.getBindGroupLayout(0),
            entries: [resources[0], resources[1], resources[2]]
              .map((resource, binding) => ({ binding, resource }))
              .concat([{ binding: 3, resource: { buffer: u } }]),
          }),
        });
      }
    }
    this.mesh = { prepared, staticBuf, cageBuf, work, layout, groups, scans: scans.map(({ group, n }) => ({ group, n })), cc, ccRanges };
    this.scanUniforms = [...scans.map((s) => s.uniform), ...rangeUniforms];
  }

  private scanUniforms: GPUBuffer[] = [];

  /** New cage positions (and normals) for the same topology, e.g. an animated cage. */
  updateCage(positions: Float32Array, normals: Float32Array): void {
    const m = this.requireMesh();
    this.device.queue.writeBuffer(m.cageBuf, 0, positions);
    this.device.queue.writeBuffer(m.cageBuf, 4 * 3 * m.prepared.vertexCount, normals);
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

  get workLayout(): WorkLayout {
    return this.requireMesh().layout;
  }

  private requireMesh() {
    if (!this.mesh) throw new Error('Tessellator.setMesh must be called first');
    return this.mesh;
  }

  /** Record every pass of a rebuild into `encoder`. */
  encode(encoder: GPUCommandEncoder, p: FactorParams): void {
    const m = this.requireMesh();
    this.writeParams(p);
    this.record(encoder, m);
  }

  private writeParams(p: FactorParams): void {
    const view = new DataView(this.paramsBytes);
    PARAMS.write(view, {
      viewProj: p.viewProj,
      mode: p.mode === 'fixed' ? 0 : 1,
      fixedFactor: p.fixedFactor,
      lodScale: p.lodScale,
      pixelAngle: p.fovY / Math.max(1, p.viewportHeight),
      eye: [p.eye[0], p.eye[1], p.eye[2], 0],
      ccFlat: this.flatBaseline ? 1 : 0,
    });
    this.device.queue.writeBuffer(this.params, 0, this.paramsBytes);
  }

  private record(encoder: GPUCommandEncoder, m: NonNullable<Tessellator['mesh']>): void {
    encoder.clearBuffer(m.work, 4 * m.layout.budget, 16);

    const stages: string[] = [];
    let query = 0;
    const pass = (label: string, stage: string) => {
      const t = this.timing && !this.timing.pending && query + 2 <= this.timing.set.count ? this.timing : undefined;
      const desc: GPUComputePassDescriptor = { label };
      if (t) {
        desc.timestampWrites = { querySet: t.set, beginningOfPassWriteIndex: query, endOfPassWriteIndex: query + 1 };
        stages.push(stage);
        query += 2;
      }
      return encoder.beginComputePass(desc);
    };
    const nE = m.prepared.edgeCount,
      nT = m.prepared.triangleCount,
      nV = m.prepared.vertexCount;
    const run = (cp: GPUComputePassEncoder, name: PassName, groups: number) => {
      cp.setPipeline(this.pipelines[name]);
      cp.setBindGroup(0, m.groups[name]);
      cp.dispatchWorkgroups(...grid2d(groups));
    };

    if (m.cc) {
      const cp = pass('cc patch build', 'subdivision');
      this.recordPatchBuild(cp, m);
      cp.end();
    }
    for (let attempt = 0; attempt < ATTEMPTS; attempt++) {
      let cp = pass(`tess factors ${attempt}`, 'factors');
      run(cp, 'factors', Math.ceil(nE / 64));
      cp.end();
      cp = pass(`tess count + budget ${attempt}`, 'count+budget');
      run(cp, 'count', Math.ceil(nT / 64));
      for (const s of m.scans) {
        const blocks = Math.ceil(Math.max(s.n, 1) / SCAN_BLOCK);
        cp.setBindGroup(0, s.group);
        cp.setPipeline(this.scanPipelines.blocks);
        cp.dispatchWorkgroups(blocks);
        cp.setPipeline(this.scanPipelines.sums);
        cp.dispatchWorkgroups(1);
        cp.setPipeline(this.scanPipelines.add);
        cp.dispatchWorkgroups(blocks);
      }
      run(cp, 'budget', 1);
      cp.end();
    }
    let cp = pass('tess weld', 'weld');
    run(cp, 'corners', Math.ceil(nV / 64));
    run(cp, 'edges', Math.ceil(nE / 64));
    cp.end();
    cp = pass('tess plan + emit', 'tessellate');
    run(cp, 'plan', Math.ceil(nT / 64));
    cp.setBindGroup(0, m.groups.emitVertices);
    cp.setPipeline(this.pipelines.emitVertices);
    cp.dispatchWorkgroupsIndirect(this.emitArgs, 0);
    cp.setBindGroup(0, m.groups.emitTriangles);
    cp.setPipeline(this.pipelines.emitTriangles);
    cp.dispatchWorkgroupsIndirect(this.emitArgs, 12);
    cp.end();

    if (this.timing && stages.length) {
      encoder.resolveQuerySet(this.timing.set, 0, query, this.timing.resolve, 0);
      encoder.copyBufferToBuffer(this.timing.resolve, 0, this.timing.read, 0, 8 * query);
      this.timing.stages = stages;
      this.timing.pending = true;
    }
  }

  private recordPatchBuild(cp: GPUComputePassEncoder, m: NonNullable<Tessellator['mesh']>): void {
    const cc = m.cc!;
    cp.setPipeline(this.pipelines.ccPoints);
    for (const r of m.ccRanges) {
      if (!r.count) continue;
      cp.setBindGroup(0, r.group);
      cp.dispatchWorkgroups(...grid2d(Math.ceil(r.count / 64)));
    }
    if (cc.sliceWorkgroups) {
      cp.setBindGroup(0, m.groups.ccSlices);
      cp.setPipeline(this.pipelines.ccSlices);
      cp.dispatchWorkgroups(...grid2d(cc.sliceWorkgroups));
    }
    if (cc.fanCount) {
      cp.setBindGroup(0, m.groups.ccLimits);
      cp.setPipeline(this.pipelines.ccLimits);
      cp.dispatchWorkgroups(...grid2d(Math.ceil(cc.fanCount / 64)));
    }
    cp.setBindGroup(0, m.groups.ccVertexLimits);
    cp.setPipeline(this.pipelines.ccVertexLimits);
    cp.dispatchWorkgroups(...grid2d(Math.ceil(m.prepared.vertexCount / 64)));
  }

  /** Record only the Catmull-Clark patch build (control points and vertex limits from the
   * current cage positions): what a deforming cage needs before the next tessellation. encode()
   * runs it too. */
  encodePatchBuild(encoder: GPUCommandEncoder): void {
    const m = this.requireMesh();
    if (!m.cc) return;
    const cp = encoder.beginComputePass({ label: 'cc patch build' });
    this.recordPatchBuild(cp, m);
    cp.end();
  }

  /** GPU milliseconds per stage of the last encoded rebuild ({} without timestamp queries).
   * Rebuilds encoded while a read is in flight are not timed; a second call while one read is
   * in flight gets the same answer. */
  readTimings(): Promise<Record<string, number>> {
    const t = this.timing;
    if (!t || !t.pending) return Promise.resolve({});
    t.reading ??= this.mapTimings(t).finally(() => {
      t.reading = undefined;
    });
    return t.reading;
  }

  private async mapTimings(t: NonNullable<Tessellator['timing']>): Promise<Record<string, number>> {
    await t.read.mapAsync(GPUMapMode.READ);
    const ticks = new BigUint64Array(t.read.getMappedRange().slice(0));
    t.read.unmap();
    t.pending = false;
    const out: Record<string, number> = {};
    t.stages.forEach((stage, i) => {
      const ns = Number(ticks[2 * i + 1] - ticks[2 * i]);
      out[stage] = (out[stage] ?? 0) + ns / 1e6;
    });
    return out;
  }

  private releaseMesh(): void {
    if (!this.mesh) return;
    this.mesh.staticBuf.destroy();
    this.mesh.cageBuf.destroy();
    this.mesh.work.destroy();
    for (const u of this.scanUniforms) u.destroy();
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
    this.timing?.set.destroy();
    this.timing?.resolve.destroy();
    this.timing?.read.destroy();
  }
}
