/**
 * The exact Catmull-Clark surface for the instanced tessellator (src/gpu/instanced/instanced.ts, surface
 * 'catmull-clark'; issue 11).
 *
 * Design. The instanced vertex function evaluates the limit through the SAME WGSL evaluator as
 * the compute tessellator (src/gpu/cc/shaders.ts CC_SURFACE_WGSL: wgsl/cc/surface.wgsl evalSurface
 * with the packed words' getters and the crease basis), over the buffers of a compute Tessellator
 * with the Catmull-Clark surface that holds the same prepared mesh: its Params uniform (where its
 * tables lie), its static arena (the tables of src/gpu/cc/build.ts) and its cage arena (the
 * refined points and limits its patch build writes), borrowed as src/gpu/acc/error.ts borrows
 * them. Nothing of the Catmull-Clark data is packed twice and the patch build is the compute
 * tessellator's own (wgsl/cc/build.wgsl).
 *
 * The evaluator text is appended to the instanced module with its module-scope names renamed
 * (ccEvaluatorWgsl): the instanced tessellator has its own `params`, `staticBuf`, `cageBuf` and
 * accessors, and the borrowed buffers are bound in group 3 (wgsl/instanced/surface-cc.wgsl).
 *
 * Who runs the patch build: the instanced tessellator, at the start of every encodeLevels (the
 * level pass of the dynamic mode evaluates the surface too, and every draw after it does), by
 * the borrowed tessellator's encodePatchBuild: the analogue of the compute tessellator's rebuild,
 * which starts with the same build. The borrowed tessellator's Params must have been uploaded
 * once (Tessellator.encode does it): ccSurfaceTessellator does that.
 *
 * The borrowed tessellator must have flatBaseline off: evalSurface's flat-baseline branch blends
 * by that tessellator's own edge factors, meaningless here (checked in setMesh; its work buffer is
 * bound only because the branch is compiled).
 */
import ccGlueWgsl from '../../../wgsl/instanced/surface-cc.wgsl?raw';
import { CC_SURFACE_WGSL } from '../cc/shaders.ts';
import { TESS_PARAMS } from '../contract/tess.ts';
import { Tessellator } from '../tess/tessellator.ts';
import { bakeTables } from '../../pattern/tables.ts';
import type { CatmullClarkData } from '../cc/build.ts';
import type { PreparedMesh } from '../tess/prepare.ts';
import type { DisplacementData, DisplacementSettings } from '../tess/displacement-map.ts';
import { surfaceScheme } from '../surface/registry.ts';

/** The evaluator's module-scope names that clash with the instanced tessellator's, and the
 * wgsl/tess/common.wgsl accessors it calls (defined over the borrowed buffers in
 * wgsl/instanced/surface-cc.wgsl). */
const RENAMES: Record<string, string> = {
  params: 'ccParams',
  staticBuf: 'ccStatic',
  cageBuf: 'ccCage',
  evalSurface: 'ccEvalSurface',
  triVert: 'ccTriVert',
  triEdge: 'ccTriEdge',
  factorPos: 'ccFactorPos',
  factorNormal: 'ccFactorNormal',
  edgeF: 'ccEdgeF',
};

/**
 * `code` with the borrowed module-scope names renamed (whole identifiers): RENAMES restricted to
 * `names` (all by default). Shared by every module the instanced tessellator borrows from a
 * compute Tessellator: the Catmull-Clark evaluator here, wgsl/tess/displace.wgsl in
 * src/gpu/instanced/displace-vertex.ts. Throws when one of `names` is no longer there: the borrowed code
 * changed and the list must follow it (a stale list would otherwise only show as a shader compile
 * error).
 */
export function renameBorrowed(code: string, names: readonly string[] = Object.keys(RENAMES), who = 'ccEvaluatorWgsl'): string {
  for (const name of names) {
    if (!(name in RENAMES)) throw new Error(`${who}: no rename for '${name}'`);
    if (!new RegExp(`\\b${name}\\b`).test(code)) throw new Error(`${who}: the borrowed code no longer uses '${name}'`);
  }
  return code.replace(new RegExp(`\\b(${names.join('|')})\\b`, 'g'), (n) => RENAMES[n]);
}

/** CC_SURFACE_WGSL with RENAMES applied (whole identifiers); throws when a name is no longer there. */
export function ccEvaluatorWgsl(code: string = CC_SURFACE_WGSL): string {
  return renameBorrowed(code);
}

/** The surface module of the instanced tessellator's Catmull-Clark surface: the compute
 * tessellator's Params struct, the group-3 bindings and accessors, the renamed evaluator. */
export function instancedCCSurfaceWgsl(): string {
  return [TESS_PARAMS.wgsl, ccGlueWgsl, ccEvaluatorWgsl()].join('\n');
}

/** Throws unless `tess` can lend its Catmull-Clark buffers for `prepared`'s triangles. */
export function checkCCSource(tess: Tessellator, prepared: PreparedMesh): void {
  if (!surfaceScheme(tess.surface).exactLimit)
    throw new Error(`the instanced Catmull-Clark surface needs a Catmull-Clark Tessellator (got ${tess.surface})`);
  if (tess.flatBaseline)
    throw new Error('the instanced Catmull-Clark surface is the exact limit: its Tessellator must have flatBaseline off');
  const own = tess.prepared;
  if (!own) throw new Error('the instanced Catmull-Clark surface needs a Tessellator with the mesh set');
  if (own !== prepared) {
    // The evaluator finds its tables by cage triangle: the two triangulations must be one.
    const same =
      own.vertexCount === prepared.vertexCount &&
      own.triangleCount === prepared.triangleCount &&
      own.triVerts.every((v, i) => v === prepared.triVerts[i]);
    if (!same) throw new Error('the Catmull-Clark Tessellator holds another mesh than the instanced one');
  }
}

/**
 * A compute Tessellator that only lends its Catmull-Clark buffers: the smallest tables and output
 * (one rebuild at factor 1, which uploads its Params and runs the patch build once), flat
 * baseline off. `cc`: buildCatmullClark(cage, prepared). With `displacement` (prepareDisplacement
 * of the same prepared mesh) it lends the displacement arenas too (src/gpu/instanced/displace-vertex.ts;
 * the settings: setLenderDisplacement). The caller owns it (destroy()).
 */
export function ccSurfaceTessellator(
  device: GPUDevice,
  prepared: PreparedMesh,
  cc: CatmullClarkData,
  displacement?: DisplacementData,
  settings?: Partial<DisplacementSettings>,
): Tessellator {
  const tess = Tessellator.create(device, bakeTables(2), {
    surface: 'catmull-clark',
    flatBaseline: false,
    vertexCapacity: prepared.vertexCount + prepared.slotOwner.length + prepared.edgeCount,
    triangleCapacity: prepared.triangleCount,
  });
  tess.setMesh(prepared, cc, undefined, displacement);
  if (settings) tess.setDisplacement(settings);
  uploadLenderParams(tess);
  return tess;
}

/** Upload a lending tessellator's Params (with its patch build, on Catmull-Clark) by one rebuild at
 * factor 1 over its smallest tables: Tessellator uploads its Params only in encode. */
export function uploadLenderParams(tess: Tessellator): void {
  const enc = tess.device.createCommandEncoder({ label: 'instanced surface source: params + first build' });
  tess.encode(enc, {
    mode: 'fixed',
    fixedFactor: 1,
    lodScale: 1,
    viewProj: new Float32Array(16),
    eye: [0, 0, 0],
    viewportHeight: 1,
    fovY: 1,
  });
  tess.device.queue.submit([enc.finish()]);
}

/** GPU memory of a lending tessellator's arenas (what the instanced surface reads). */
export function ccSourceBytes(tess: Tessellator): number {
  return tess.paramsBuffer.size + tess.staticBuffer.size + tess.cageBuffer.size + tess.workBuffer.size;
}
