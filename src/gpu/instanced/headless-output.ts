/**
 * The instanced tessellator's headless output (HeadlessInstanced, what InstancedTessellator.headless
 * reads back) and what the CLI and the checks make of it: each vertex's place on its cage face,
 * the output as OBJ, and the output welded across patches (WeldedInstanced) and its OBJ.
 */
import { PATCH_WORDS } from './buffer-layouts.ts';
import { patchDomain, type InstancedMesh } from './prepare-patches.ts';
import { patchTriangle } from './cpu-twin.ts';
import { faceParam, type FaceParam } from '../tess/face-params.ts';
import type { Cage } from '../../mesh/types.ts';
import { vertexEdges, MAX_POW2_LEVEL } from '../../pattern/pow2.ts';

export interface HeadlessInstanced {
  vertexCount: number;
  triangleCount: number;
  positions: Float32Array;
  normals: Float32Array;
  /** Per vertex: its patch. */
  patch: Uint32Array;
  /** Per vertex: the snapped pattern point (u, v) on its patch. */
  uv: Float32Array;
  indices: Uint32Array;
  /** Patches per bucket, as the GPU counted them. */
  counts: Uint32Array;
  /** The 14 indirect draw records the GPU wrote. */
  records: Uint32Array;
  /** Per edge: its level; per patch: its pattern level. */
  edgeLevels: Uint32Array;
  patchLevels: Uint32Array;
  /** GPU milliseconds of the headless run's passes ({ levels, evaluate }; {} without
   * timestamp queries). */
  timings: Record<string, number>;
}

/**
 * Where each headless output vertex lies on its cage face, in the CPU reference's addressing
 * (src/gpu/tess/face-params.ts: `f u v` on quads, `f k s t` on sub-faces of other faces), for the
 * CLI's --params.
 */
export function instancedVertexParams(m: InstancedMesh, cage: Cage, out: HeadlessInstanced): FaceParam[] {
  const params: FaceParam[] = [];
  for (let v = 0; v < out.vertexCount; v++) {
    const p = out.patch[v],
      P = out.patchLevels[p];
    const { t, w } = patchTriangle(m, p, P, Math.round(out.uv[2 * v] * P), Math.round(out.uv[2 * v + 1] * P));
    params.push(faceParam(m.prepared, cage, t, [w[0] / 65536, w[1] / 65536, w[2] / 65536]));
  }
  return params;
}

/** The headless output as OBJ: positions, normals, 1-based triangles; vertices are welded
 * within each patch only, and the triangles the snap collapsed (zero area in (u, v)) are left out. */
export function instancedToObj(out: HeadlessInstanced, header: string): string {
  const lines: string[] = [`# ${header}`];
  for (let v = 0; v < out.vertexCount; v++) lines.push(`v ${out.positions[3 * v]} ${out.positions[3 * v + 1]} ${out.positions[3 * v + 2]}`);
  for (let v = 0; v < out.vertexCount; v++) lines.push(`vn ${out.normals[3 * v]} ${out.normals[3 * v + 1]} ${out.normals[3 * v + 2]}`);
  let kept = 0;
  for (let t = 0; t < out.triangleCount; t++) {
    const [a, b, c] = [0, 1, 2].map((k) => out.indices[3 * t + k]);
    const uv = (x: number, k: number) => out.uv[2 * x + k];
    const area2 = (uv(b, 0) - uv(a, 0)) * (uv(c, 1) - uv(a, 1)) - (uv(b, 1) - uv(a, 1)) * (uv(c, 0) - uv(a, 0));
    if (area2 === 0) continue;
    lines.push(`f ${a + 1}//${a + 1} ${b + 1}//${b + 1} ${c + 1}//${c + 1}`);
    kept++;
  }
  lines.splice(1, 0, `# ${out.vertexCount} vertices, ${kept} triangles (${out.triangleCount - kept} collapsed by the snap left out)`);
  return lines.join('\n') + '\n';
}

/** The headless output welded across patches (what the CLI writes, as the compute tessellator's
 * OBJ is welded). Copies are merged by where they lie on the cage, never by position: a patch
 * corner by its cage vertex, a point on a cage edge by the edge and its canonical parameter
 * (exact: a multiple of 1/64), an interior point by its patch and (i, j). The welded position is
 * the first copy's; `gap` is the largest distance between copies merged (the two sides of an edge
 * evaluate the surface in f32 each: the crack the weld closes). Triangles the snap collapsed
 * (zero area in (u, v), or two corners welded together) are left out. */
export interface WeldedInstanced {
  vertexCount: number;
  triangleCount: number;
  positions: Float32Array;
  normals: Float32Array;
  indices: Uint32Array;
  /** Per welded vertex: the headless output vertex it was taken from. */
  source: Uint32Array;
  /** Triangles of the draw left out (collapsed by the snap). */
  collapsed: number;
  /** Largest distance between merged copies, in model units. */
  gap: number;
}

export function weldInstanced(m: InstancedMesh, out: HeadlessInstanced): WeldedInstanced {
  const nV = m.prepared.vertexCount,
    nE = m.edgeCount;
  const S = MAX_POW2_LEVEL + 1;
  const ids = new Map<number, number>();
  const remap = new Uint32Array(out.vertexCount);
  const source: number[] = [];
  let gap = 0;
  for (let v = 0; v < out.vertexCount; v++) {
    const p = out.patch[v],
      P = out.patchLevels[p];
    const i = Math.round(out.uv[2 * v] * P),
      j = Math.round(out.uv[2 * v + 1] * P);
    const dom = patchDomain(m, p);
    const on = vertexEdges(dom, P, i, j);
    let key: number;
    if (on.length === 0) key = nV + nE * S + (p * S + i) * S + j;
    else {
      const { edge, t } = on[0];
      const n = dom === 'tri' ? 3 : 4;
      if (t === 0) key = m.corners[4 * p + edge];
      else if (t === P) key = m.corners[4 * p + ((edge + 1) % n)];
      else {
        const e = m.patches[PATCH_WORDS * p + 2 + edge];
        const canonical = ((m.patches[PATCH_WORDS * p + 1] >> (1 + edge)) & 1) === 1;
        const c = ((canonical ? t : P - t) * MAX_POW2_LEVEL) / P;
        key = nV + e * S + c;
      }
    }
    let w = ids.get(key);
    if (w === undefined) {
      w = source.length;
      ids.set(key, w);
      source.push(v);
    } else {
      const f = source[w];
      const d = Math.hypot(
        out.positions[3 * v] - out.positions[3 * f],
        out.positions[3 * v + 1] - out.positions[3 * f + 1],
        out.positions[3 * v + 2] - out.positions[3 * f + 2],
      );
      gap = Math.max(gap, d);
    }
    remap[v] = w;
  }
  const src = Uint32Array.from(source);
  const positions = new Float32Array(3 * src.length);
  const normals = new Float32Array(3 * src.length);
  src.forEach((v, w) => {
    positions.set(out.positions.subarray(3 * v, 3 * v + 3), 3 * w);
    normals.set(out.normals.subarray(3 * v, 3 * v + 3), 3 * w);
  });
  const tris: number[] = [];
  for (let t = 0; t < out.triangleCount; t++) {
    const [a, b, c] = [0, 1, 2].map((k) => out.indices[3 * t + k]);
    const uv = (x: number, k: number) => out.uv[2 * x + k];
    const area2 = (uv(b, 0) - uv(a, 0)) * (uv(c, 1) - uv(a, 1)) - (uv(b, 1) - uv(a, 1)) * (uv(c, 0) - uv(a, 0));
    const [wa, wb, wc] = [remap[a], remap[b], remap[c]];
    if (area2 === 0 || wa === wb || wb === wc || wa === wc) continue;
    tris.push(wa, wb, wc);
  }
  return {
    vertexCount: src.length,
    triangleCount: tris.length / 3,
    positions,
    normals,
    indices: Uint32Array.from(tris),
    source: src,
    collapsed: out.triangleCount - tris.length / 3,
    gap,
  };
}

/** The welded mesh as OBJ (positions, normals, 1-based triangles), as src/gpu/tess/headless.ts meshToObj. */
export function weldedToObj(w: WeldedInstanced, header: string): string {
  const lines: string[] = [
    `# ${header}`,
    `# ${w.vertexCount} vertices, ${w.triangleCount} triangles (${w.collapsed} collapsed by the snap left out; largest weld gap ${w.gap.toExponential(2)})`,
  ];
  for (let v = 0; v < w.vertexCount; v++) lines.push(`v ${w.positions[3 * v]} ${w.positions[3 * v + 1]} ${w.positions[3 * v + 2]}`);
  for (let v = 0; v < w.vertexCount; v++) lines.push(`vn ${w.normals[3 * v]} ${w.normals[3 * v + 1]} ${w.normals[3 * v + 2]}`);
  for (let t = 0; t < w.triangleCount; t++) {
    const [a, b, c] = [w.indices[3 * t] + 1, w.indices[3 * t + 1] + 1, w.indices[3 * t + 2] + 1];
    lines.push(`f ${a}//${a} ${b}//${b} ${c}//${c}`);
  }
  return lines.join('\n') + '\n';
}

/** Face parameters of the welded vertices (each its source copy's, instancedVertexParams). */
export function weldedVertexParams(m: InstancedMesh, cage: Cage, out: HeadlessInstanced, w: WeldedInstanced): FaceParam[] {
  const all = instancedVertexParams(m, cage, out);
  return Array.from(w.source, (v) => all[v]);
}
