/**
 * The tessellation pipeline without a browser: cage in, welded mesh out (OBJ, and the
 * parameter of every vertex on its cage face). Used by `npm run tessellate` and the benchmark.
 */
import type { HeightMap, HeightWrap } from '../../mesh/heightmap.ts';
import { prepareDisplacement } from './displacement-map.ts';
import { mat4 } from 'gl-matrix';
import { Tessellator } from './tessellator.ts';
import { prepareMesh, type PreparedMesh } from './prepare.ts';
import { readBuffer, readMesh, type MeshReadback } from '../device/readback.ts';
import { faceParam, type FaceParam } from './face-params.ts';
import type { FactorParams } from '../contract/tessellated-mesh.ts';
import { decodeBary, NO_OWNER } from '../contract/tess.ts';
import { bakeTables } from '../../pattern/tables.ts';
import { MAX_FACTOR } from '../contract/constants.ts';
import { releaseSurfaceData, surfaceScheme, type SurfaceData, type SurfaceId } from '../surface/registry.ts';
import type { Cage } from '../../mesh/types.ts';

export interface HeadlessOptions {
  mode: 'fixed' | 'adaptive';
  /** The surface: the Catmull-Clark limit surface (default), Phong tessellation, or an ACC
   * approximation of the limit surface ('bezier-acc', 'gregory-acc', 'pm-acc'). */
  surface?: SurfaceId;
  /** Catmull-Clark: blend towards the flat triangle at low tess factors (default off here, so
   * every vertex lies on the exact limit surface). */
  flatBaseline?: boolean;
  fixedFactor?: number;
  lodScale?: number;
  eye?: [number, number, number];
  target?: [number, number, number];
  viewportHeight?: number;
  fovY?: number;
  vertexCapacity?: number;
  triangleCapacity?: number;
  /** Displace by a height map over the cage's uvs (src/gpu/tess/displacement-map.ts): h = (sample −
   * midLevel)·scale along the surface normal. */
  displacement?: { map: HeightMap; scale: number; midLevel: number; wrap: HeightWrap };
}

/** A camera for adaptive mode: the given eye and target, or a three-quarter view that frames the model. */
export function headlessCamera(mesh: PreparedMesh, o: HeadlessOptions): FactorParams {
  const centre = [0, 1, 2].map((i) => (mesh.bboxMin[i] + mesh.bboxMax[i]) / 2) as [number, number, number];
  const target = o.target ?? centre;
  const eye =
    o.eye ?? ([centre[0] + 0.55 * mesh.size, centre[1] + 0.45 * mesh.size, centre[2] + 1.1 * mesh.size] as [number, number, number]);
  const fovY = o.fovY ?? Math.PI / 4;
  const dist = Math.hypot(eye[0] - target[0], eye[1] - target[1], eye[2] - target[2]);
  const view = mat4.lookAt(mat4.create(), eye, target, [0, 1, 0]);
  const proj = mat4.perspectiveZO(mat4.create(), fovY, 16 / 9, Math.max(1e-4, dist * 1e-3), dist + 4 * mesh.size);
  return {
    mode: o.mode,
    fixedFactor: o.fixedFactor ?? 1,
    lodScale: o.lodScale ?? 1,
    viewProj: mat4.multiply(mat4.create(), proj, view) as Float32Array,
    eye,
    viewportHeight: o.viewportHeight ?? 1080,
    fovY,
  };
}

export interface HeadlessResult {
  /** The cage tessellated: the one given, or the surface's in its place (SurfaceScheme.surfaceCage). */
  cage: Cage;
  mesh: PreparedMesh;
  out: MeshReadback;
  edgeF: Uint32Array;
  timings: Record<string, number>;
}

/** `prepared`: the mesh and the surface's data (Catmull-Clark tables or ACC patches) made by the
 * caller (e.g. to time the preparation), instead of making them here. A surface throws, with the
 * reason, on a cage it does not take (an ACC scheme: AccError, src/subdiv/acc.ts). */
export async function tessellateOnce(
  device: GPUDevice,
  cage: Cage,
  o: HeadlessOptions,
  tess?: Tessellator,
  prepared?: { mesh: PreparedMesh } & SurfaceData,
): Promise<HeadlessResult> {
  const surface = tess?.surface ?? o.surface ?? 'catmull-clark';
  // The cage the surface tessellates (an ACC scheme refines a cage with n-gons once); a caller
  // that prepared the mesh prepared it from that cage.
  if (!prepared) cage = surfaceScheme(surface).surfaceCage(cage).cage;
  const mesh = prepared?.mesh ?? prepareMesh(cage);
  const own = !tess;
  const t =
    tess ??
    Tessellator.create(device, bakeTables(MAX_FACTOR), {
      vertexCapacity: o.vertexCapacity,
      triangleCapacity: o.triangleCapacity,
      surface,
      flatBaseline: o.flatBaseline ?? false,
    });
  const scheme = surfaceScheme(t.surface);
  let ownData: SurfaceData | undefined;
  try {
    // Surface data made here (ACC patches hold GPU buffers) is released here; the caller's is the caller's.
    const data = prepared && scheme.hasData(prepared) ? prepared : (ownData = scheme.prepare(device, cage, mesh));
    const d = o.displacement;
    const disp = d ? prepareDisplacement(cage, mesh, d.map, d.wrap) : undefined;
    t.setMesh(mesh, data.cc, data.acc, disp);
    if (d) t.setDisplacement({ scale: d.scale, midLevel: d.midLevel, enabled: true });
    device.pushErrorScope('validation');
    const enc = device.createCommandEncoder({ label: 'headless rebuild' });
    t.encode(enc, headlessCamera(mesh, o));
    device.queue.submit([enc.finish()]);
    const error = await device.popErrorScope();
    if (error) throw new Error(`WebGPU validation error: ${error.message}`);
    const out = await readMesh(device, t.output);
    const edgeF = new Uint32Array(await readBuffer(device, t.workBuffer, 4 * mesh.edgeCount, 4 * t.workLayout.edgeF));
    const timings = await t.readTimings();
    return { cage, mesh, out, edgeF, timings };
  } finally {
    if (own) t.destroy();
    if (ownData) releaseSurfaceData(ownData);
  }
}

/**
 * The output without the vertices no triangle uses (a cage's unused vertices go through the
 * pipeline, numbered as in the cage), for writing: the result, and the output vertices it keeps in
 * order (null when it keeps all). A caller filters per-vertex data (vertexParams) by `kept`.
 */
export function withoutUnusedVertices(r: HeadlessResult): { r: HeadlessResult; kept: Uint32Array | null } {
  const { out } = r;
  const used = new Uint8Array(out.vertexCount);
  for (let i = 0; i < 3 * out.triangleCount; i++) used[out.indices[i]] = 1;
  let n = 0;
  for (const u of used) n += u;
  if (n === out.vertexCount) return { r, kept: null };
  const kept = new Uint32Array(n);
  const renumber = new Uint32Array(out.vertexCount);
  const positions = new Float32Array(3 * n);
  const normals = new Float32Array(3 * n);
  const bary = new Uint32Array(n);
  const srcTri = new Uint32Array(n);
  for (let v = 0, k = 0; v < out.vertexCount; v++) {
    if (!used[v]) continue;
    kept[k] = v;
    renumber[v] = k;
    positions.set(out.positions.subarray(3 * v, 3 * v + 3), 3 * k);
    normals.set(out.normals.subarray(3 * v, 3 * v + 3), 3 * k);
    bary[k] = out.bary[v];
    srcTri[k] = out.srcTri[v];
    k++;
  }
  const indices = out.indices.slice(0, 3 * out.triangleCount).map((v) => renumber[v]);
  return { r: { ...r, out: { ...out, vertexCount: n, positions, normals, bary, srcTri, indices } }, kept };
}

/** Float barycentric weights of output vertex v on its source triangle. */
export function vertexWeights(out: MeshReadback, v: number): [number, number, number] {
  const [w0, w1, w2] = decodeBary(out.bary[v]);
  return [w0 / 65536, w1 / 65536, w2 / 65536];
}

/** The welded mesh as OBJ (positions, normals, 1-based triangles). */
export function meshToObj(r: HeadlessResult, header: string): string {
  const { out } = r;
  const lines: string[] = [`# ${header}`, `# ${out.vertexCount} vertices, ${out.triangleCount} triangles`];
  for (let v = 0; v < out.vertexCount; v++) lines.push(`v ${out.positions[3 * v]} ${out.positions[3 * v + 1]} ${out.positions[3 * v + 2]}`);
  for (let v = 0; v < out.vertexCount; v++) lines.push(`vn ${out.normals[3 * v]} ${out.normals[3 * v + 1]} ${out.normals[3 * v + 2]}`);
  for (let t = 0; t < out.triangleCount; t++) {
    const [a, b, c] = [out.indices[3 * t] + 1, out.indices[3 * t + 1] + 1, out.indices[3 * t + 2] + 1];
    lines.push(`f ${a}//${a} ${b}//${b} ${c}//${c}`);
  }
  return lines.join('\n') + '\n';
}

/** Every output vertex's source face and parameter (unused cage vertices: null). */
export function vertexParams(r: HeadlessResult, cage: Cage): (FaceParam | null)[] {
  const params: (FaceParam | null)[] = [];
  for (let v = 0; v < r.out.vertexCount; v++) {
    if (v < r.mesh.vertexCount && r.mesh.vertexOwner[v] === NO_OWNER) params.push(null);
    else params.push(faceParam(r.mesh, cage, r.out.srcTri[v], vertexWeights(r.out, v)));
  }
  return params;
}

/** One `f u v` or `f k s t` per line, the input format of `npm run subdiv -- --points`. */
export function paramsToText(params: (FaceParam | null)[]): string {
  return (
    params
      .map((p) => (p === null ? '# unused cage vertex' : 'u' in p ? `${p.face} ${p.u} ${p.v}` : `${p.face} ${p.k} ${p.s} ${p.t}`))
      .join('\n') + '\n'
  );
}
