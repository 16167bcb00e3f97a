/**
 * The demo's instanced tessellator (src/gpu/instanced/instanced.ts, `?tessellator=instanced`): the shown
 * model's patches on the GPU, drawn inside the renderer's shadow, lit and wireframe passes (it
 * evaluates the surface again in each: the comparison with the compute tessellator, which draws
 * its stored mesh), the level pass encoded before a frame's draws when the levels may have
 * changed, and the bucket draw records read back after it for the stats and the e2e hook (the
 * draws themselves never wait on a readback). A model with a height map is drawn displaced
 * (src/gpu/instanced/displace-vertex.ts): the view is then made with `displaced`, and holds the compute
 * Tessellator that lends the displacement arenas (on Catmull-Clark, the surface's own lender).
 */
import { InstancedTessellator } from '../gpu/instanced/instanced.ts';
import type { LevelParams } from '../gpu/instanced/instanced-options.ts';
import { BUCKETS } from '../gpu/instanced/buffer-layouts.ts';
import { prepareInstanced, type InstancedMesh } from '../gpu/instanced/prepare-patches.ts';
import { cpuLevels } from '../gpu/instanced/cpu-twin.ts';
import { prepareMesh } from '../gpu/tess/prepare.ts';
import type { ShadingResources } from '../gpu/render/renderer.ts';
import type { PackedPatterns } from '../pattern/pow2.ts';
import type { Cage } from '../mesh/types.ts';
import { AccPatches } from '../gpu/acc/patches.ts';
import { AccError } from '../subdiv/acc.ts';
import { buildCatmullClark, type CatmullClarkData } from '../gpu/cc/build.ts';
import { CC_TRI_WORD } from '../gpu/cc/words.ts';
import { ccSurfaceTessellator } from '../gpu/instanced/surface-cc.ts';
import { displacementLender, setLenderDisplacement } from '../gpu/instanced/displace-vertex.ts';
import { prepareDisplacement, type DisplacementData, type DisplacementSettings } from '../gpu/tess/displacement-map.ts';
import type { CageHeightMap } from './geometry.ts';
import type { Tessellator } from '../gpu/tess/tessellator.ts';
import type { InstancedSurface } from './params.ts';
import { surfaceScheme } from '../gpu/surface/registry.ts';
import { isAcc, isExact } from './surfaces.ts';

/** The Catmull-Clark preparation refused the cage (a message fit to show). An AccError, so that
 * the page's fallback for a cage an ACC scheme refuses (Phong, with the reason) takes it too. */
export class CatmullClarkRefused extends AccError {}

/** What one frame's draws hold, from the 14 bucket records. */
export interface InstancedCounts {
  /** The records as the GPU wrote them: 5 words per bucket (indexCount, instanceCount, firstIndex, baseVertex, 0). */
  records: Uint32Array;
  /** Triangles rasterised per pass (the snap's collapsed ones included). */
  triangles: number;
  /** Pattern vertices the vertex shader evaluates per pass. */
  vertices: number;
  patches: number;
  /** Patches per level (quad and triangle buckets together), levels with none left out. */
  levels: [number, number][];
}

/** The counts of a set of bucket records (pure: the unit tests check it). */
export function countsFromRecords(records: Uint32Array, patterns: PackedPatterns): InstancedCounts {
  let triangles = 0,
    vertices = 0,
    patches = 0;
  const perLevel = new Map<number, number>();
  patterns.entries.forEach((e, b) => {
    const n = records[5 * b + 1];
    triangles += (n * records[5 * b]) / 3;
    vertices += n * e.vertexCount;
    patches += n;
    if (n) perLevel.set(e.level, (perLevel.get(e.level) ?? 0) + n);
  });
  return { records, triangles, vertices, patches, levels: [...perLevel].sort((a, b) => a[0] - b[0]) };
}

export class InstancedView {
  readonly tess: InstancedTessellator;
  #mesh: InstancedMesh | null = null;
  /** The cage given (the model's; an ACC scheme tessellates its refinement of a cage with n-gons). */
  #cage: Cage | null = null;
  #staging: GPUBuffer;
  #state: 'idle' | 'copied' | 'mapping' = 'idle';
  /** Whether the latest encode's records are still to be copied (the staging buffer was busy). */
  #owed = false;
  /** The latest level parameters encoded. */
  lastLevels: LevelParams | null = null;
  /** The ACC patches of the cage (an ACC surface). */
  #acc: AccPatches | null = null;
  /** The exact surface: the cage's Catmull-Clark tables, and the compute Tessellator that lends
   * the instanced one its buffers and patch build (src/gpu/instanced/surface-cc.ts; this view owns it). */
  #cc: { data: CatmullClarkData; tess: Tessellator } | null = null;
  /** With `displaced`: the lender of the displacement arenas (Catmull-Clark: #cc.tess), and the
   * height map it holds. */
  #lender: Tessellator | null = null;
  #height: CageHeightMap | null = null;
  /** Whether the lender holds a map (a displaced view, a height map and uvs). */
  #hasMap = false;
  #settings: Partial<DisplacementSettings> = { enabled: false };
  readonly #device: GPUDevice;

  /** `surface`: Phong, an ACC scheme (setCage then throws AccError for cages it refuses) or the
   * exact Catmull-Clark surface (CatmullClarkRefused, likewise). `displaced`: the vertex function
   * displaces by the height map given to setCage (src/gpu/instanced/displace-vertex.ts). */
  constructor(
    device: GPUDevice,
    shading: ShadingResources,
    readonly surface: InstancedSurface = 'phong',
    readonly displaced = false,
  ) {
    this.#device = device;
    this.tess = new InstancedTessellator(device, {
      colorFormat: shading.colorFormat,
      sampleCount: shading.sampleCount,
      surface: surfaceScheme(surface).instancedKind,
      displacement: displaced,
    });
    this.tess.useRenderer(shading);
    this.#staging = device.createBuffer({
      label: 'instanced records readback',
      size: 20 * BUCKETS,
      usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
    });
  }

  get cage(): Cage | null {
    return this.#cage;
  }

  get mesh(): InstancedMesh | null {
    return this.#mesh;
  }

  /** The height map of the cage shown (setCage). */
  get height(): CageHeightMap | null {
    return this.#height;
  }

  /** Patches per patch colour (as wgsl/instanced/surface-*.wgsl patchColourIndex): regular,
   * irregular quad, triangle (ACC: a regular patch is ACC kind 0; Catmull-Clark: a quad of region
   * depth 0, one bicubic patch; Phong: every quad). */
  patchColourCounts(): [number, number, number, number] {
    const m = this.#mesh;
    const n: [number, number, number, number] = [0, 0, 0, 0];
    if (!m) return n;
    const kinds = this.#acc?.topology.patches;
    const cc = this.#cc?.data;
    for (let p = 0; p < m.patchCount; p++) {
      const tri = (m.patches[8 * p + 1] & 1) === 1;
      const t = m.patches[8 * p];
      if (tri) n[2]++;
      else if (cc) n[CC_TRI_WORD.get(cc.words[cc.layout.offset.tri + 3 * t + 1], 'depth') === 0 ? 0 : 1]++;
      else if (!kinds || kinds[2 * m.patches[8 * p + 6]] === 0) n[0]++;
      else n[1]++;
    }
    return n;
  }

  /** Upload a model's patches (its topology and positions; with an ACC surface, its ACC patches:
   * throws src/subdiv/acc.ts AccError, with a message fit to show, for a cage the scheme refuses).
   * `height`: its height map (a `displaced` view draws it; the settings: setDisplacement). */
  setCage(cage: Cage, height: CageHeightMap | null = null): void {
    // The cage the surface tessellates: an ACC scheme refines a cage with n-gons once (the same
    // limit); the patches, the mesh and the map's uvs are that cage's.
    const given = cage;
    if (isAcc(this.surface)) cage = surfaceScheme(this.surface).surfaceCage(cage).cage;
    const prepared = prepareMesh(cage);
    // Without a map (or uvs) a displaced view's lender still gives the owners (dispOn off).
    let disp: DisplacementData | undefined;
    if (this.displaced && height) disp = prepareDisplacement(cage, prepared, height.map, height.wrap);
    const mesh = prepareInstanced(cage, prepared);
    const acc = isAcc(this.surface) ? new AccPatches(this.#device, cage, this.surface) : null;
    let cc: { data: CatmullClarkData; tess: Tessellator } | null = null;
    if (isExact(this.surface)) {
      // Topology only, as the page's own cache prepares it (src/app/cc-tables.ts): tens of ms.
      let data: CatmullClarkData;
      try {
        data = buildCatmullClark(cage, prepared);
      } catch (e) {
        throw new CatmullClarkRefused((e as Error).message);
      }
      cc = { data, tess: ccSurfaceTessellator(this.#device, prepared, data, disp, this.#settingsFor(disp !== undefined)) };
    }
    const lender = this.displaced
      ? (cc?.tess ?? displacementLender(this.#device, prepared, disp, this.#settingsFor(disp !== undefined)))
      : null;
    this.#acc?.destroy();
    this.#acc = acc;
    if (this.#lender !== this.#cc?.tess) this.#lender?.destroy();
    this.#cc?.tess.destroy();
    this.#cc = cc;
    this.#lender = lender;
    this.#height = height;
    this.#hasMap = disp !== undefined;
    this.#mesh = mesh;
    this.#cage = given;
    this.tess.setMesh(mesh, acc ?? cc?.tess, lender ?? undefined);
  }

  /** The settings with displacement off where the lender has no map. */
  #settingsFor(hasMap: boolean): Partial<DisplacementSettings> {
    return { ...this.#settings, enabled: hasMap && this.#settings.enabled === true };
  }

  /** Scale, mid level, on/off of a displaced view (kept for the next setCage too). */
  setDisplacement(settings: Partial<DisplacementSettings>): void {
    this.#settings = { ...this.#settings, ...settings };
    if (this.#lender) setLenderDisplacement(this.#lender, this.#settingsFor(this.#hasMap));
  }

  /** Encode the level pass (before the frame's render passes) and, when the reader is free, a copy of its records. */
  encode(encoder: GPUCommandEncoder, lp: LevelParams): void {
    this.tess.encodeLevels(encoder, lp);
    this.lastLevels = lp;
    this.#owed = true;
    this.copyIfOwed(encoder);
  }

  /** Copy the latest records for reading, if they are owed and the reader is free. */
  copyIfOwed(encoder: GPUCommandEncoder): void {
    if (!this.#owed || this.#state !== 'idle') return;
    encoder.copyBufferToBuffer(this.tess.drawArgs, 0, this.#staging, 0, 20 * BUCKETS);
    this.#state = 'copied';
    this.#owed = false;
  }

  get owed(): boolean {
    return this.#owed;
  }

  /** After the copy was submitted: the counts, or null when there was nothing new to read. */
  async read(): Promise<InstancedCounts | null> {
    if (this.#state !== 'copied') return null;
    this.#state = 'mapping';
    try {
      await this.#staging.mapAsync(GPUMapMode.READ);
      const records = new Uint32Array(this.#staging.getMappedRange().slice(0));
      this.#staging.unmap();
      return countsFromRecords(records, this.tess.patterns);
    } catch {
      return null; // the device went away mid-read
    } finally {
      this.#state = 'idle';
    }
  }

  /** The CPU's records for every patch at `level` (static mode): what the GPU's must equal. */
  cpuRecords(level: number): Uint32Array | null {
    const m = this.#mesh;
    if (!m) return null;
    return cpuLevels(m, new Uint32Array(m.patchCount).fill(level), this.tess.patterns).records;
  }

  destroy(): void {
    this.tess.destroy();
    this.#acc?.destroy();
    if (this.#lender !== this.#cc?.tess) this.#lender?.destroy();
    this.#cc?.tess.destroy();
    this.#staging.destroy();
  }
}
