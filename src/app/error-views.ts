/**
 * The demo's ACC error views (issue 10): per drawn ACC surface (the main one, and the comparison
 * view's right half), the GPU error pass over its output (src/gpu/acc/heat.ts AccHeatPass), run
 * whenever that output is rebuilt, and its max / RMS read back asynchronously; and, per cage, the
 * exact Catmull-Clark reference the passes evaluate (a Catmull-Clark Tessellator used only for its
 * patch build and uniforms, at factor 1 and with a tiny output). No DOM.
 */
import type { Cage } from '../mesh/types.ts';
import { buildCatmullClark, type CatmullClarkData } from '../gpu/cc/build.ts';
import { AccHeatPass, type HeatTotals } from '../gpu/acc/heat.ts';
import type { AccPatches } from '../gpu/acc/patches.ts';
import { Tessellator } from '../gpu/tess/tessellator.ts';
import type { FactorParams } from '../gpu/contract/tessellated-mesh.ts';
import { patternTables, type TessellatorGeometry } from './geometry.ts';

interface PassState {
  geometry: TessellatorGeometry;
  acc: AccPatches;
  pass: AccHeatPass;
  /** Not encoded since it was made (its values are not there yet). */
  fresh: boolean;
  totals: HeatTotals | null;
}

export class ErrorViews {
  readonly #device: GPUDevice;
  #reference: { cage: Cage; tess: Tessellator; encoded: boolean } | null = null;
  #passes: PassState[] = [];

  constructor(device: GPUDevice) {
    this.#device = device;
  }

  /**
   * The pass of `geometry` (an ACC surface showing `cage`), made on first use for its current
   * patches; null when it has none (not an ACC surface, no mesh yet). `cc`: the cage's
   * Catmull-Clark tables (the exact reference). Where the scheme tessellates another cage in its
   * place (one Catmull-Clark step of a cage with n-gons: the same limit), the reference is built on
   * that cage here, from its topology (tens of ms on the demo's models).
   */
  passFor(geometry: TessellatorGeometry, cage: Cage, cc: CatmullClarkData): AccHeatPass | null {
    const acc = geometry.accPatches,
      prepared = geometry.prepared,
      output = geometry.output,
      tessellated = geometry.tessellatedCage?.cage;
    if (!acc || !prepared || !output || !tessellated) return null;
    if (tessellated !== cage) {
      if (this.#reference?.cage !== tessellated) cc = buildCatmullClark(tessellated, prepared);
      cage = tessellated;
    }
    let state = this.#passes.find((s) => s.geometry === geometry);
    if (state && state.acc === acc) return state.pass;
    if (state) this.#drop(state);
    if (this.#reference?.cage !== cage) {
      this.#reference?.tess.destroy();
      // Factor 1 everywhere: its output (never drawn) holds the cage's own triangles.
      const room = 2 * (prepared.vertexCount + prepared.edgeCount + prepared.triangleCount) + 64;
      const tess = Tessellator.create(this.#device, patternTables(), {
        surface: 'catmull-clark',
        flatBaseline: false,
        vertexCapacity: room,
        triangleCapacity: room,
      });
      tess.setMesh(prepared, cc);
      this.#reference = { cage, tess, encoded: false };
    }
    state = { geometry, acc, pass: new AccHeatPass(this.#device, acc, prepared, cage, output.vertexCapacity), fresh: true, totals: null };
    this.#passes.push(state);
    return state.pass;
  }

  /**
   * Record `geometry`'s error pass when its output was rebuilt in this encoder (`rebuilt`) or
   * the pass is new; the reference's patch build first, the first time. `factors`: any (only
   * the reference's patch build and uniforms are used).
   */
  encode(encoder: GPUCommandEncoder, geometry: TessellatorGeometry, rebuilt: boolean, factors: FactorParams): void {
    const state = this.#passes.find((s) => s.geometry === geometry);
    const ref = this.#reference;
    if (!state || !ref || !geometry.output) return;
    if (!(rebuilt || state.fresh)) {
      state.pass.copyIfOwed(encoder);
      return;
    }
    if (!ref.encoded) {
      ref.tess.encode(encoder, { ...factors, mode: 'fixed', fixedFactor: 1 });
      ref.encoded = true;
    }
    state.pass.encode(encoder, ref.tess, geometry.output);
    state.fresh = false;
  }

  /** The last totals read back for `geometry`'s pass (null before the first, or without one). */
  totals(geometry: TessellatorGeometry | null): HeatTotals | null {
    return this.#passes.find((s) => s.geometry === geometry)?.totals ?? null;
  }

  /** Whether `geometry` has a pass whose values are on the GPU (drawable). */
  ready(geometry: TessellatorGeometry | null): AccHeatPass | null {
    const s = this.#passes.find((p) => p.geometry === geometry);
    return s && !s.fresh ? s.pass : null;
  }

  /** Read every copied total back (after the frame's submit); true when any changed. */
  async read(): Promise<boolean> {
    const owed = this.#passes.filter((s) => s.pass.owed);
    const got = await Promise.all(owed.map((s) => s.pass.read()));
    let changed = false;
    owed.forEach((s, i) => {
      if (got[i] && got[i] !== s.totals) {
        s.totals = got[i];
        changed = true;
      }
    });
    return changed;
  }

  /** Some pass's totals wait for a frame to copy them (the demo draws on demand: ask for one). */
  get copyOwed(): boolean {
    return this.#passes.some((s) => s.pass.copyOwed);
  }

  /** Free the passes of geometries no longer drawn (`keep`: those still drawn). */
  retain(keep: readonly (TessellatorGeometry | null)[]): void {
    for (const s of [...this.#passes]) if (!keep.includes(s.geometry)) this.#drop(s);
  }

  #drop(state: PassState): void {
    state.pass.destroy();
    this.#passes = this.#passes.filter((s) => s !== state);
  }

  destroy(): void {
    for (const s of this.#passes) s.pass.destroy();
    this.#passes = [];
    this.#reference?.tess.destroy();
    this.#reference = null;
  }
}
