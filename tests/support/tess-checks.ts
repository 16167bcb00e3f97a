/**
 * Checks of a GPU tessellation against the CPU: patterns, counts, surface, watertightness.
 * Used by the GPU tests (Node and browser) and by the headless CLI's test.
 */
import { ONE } from '../../src/pattern/fixed.ts';
import { clampedTriangle, type Reverse } from '../../src/pattern/clamped.ts';
import { phongPoint } from '../../src/gpu/surface/phong.ts';
import { hableLine } from '../../src/pattern/hable-line.ts';
import { NO_OWNER } from '../../src/gpu/tess/prepare.ts';
import type { CreaseSplit, PreparedMesh } from '../../src/gpu/tess/prepare.ts';
import type { MeshReadback } from '../../src/gpu/device/readback.ts';
import { decodeBary, OWNER_WORD } from '../../src/gpu/contract/tess.ts';

export interface TessReport {
  problems: string[];
  maxPositionError: number; // relative to the model size
  maxNormalError: number; // radians
  expectedVertices: number;
  expectedTriangles: number;
}

/** Angle between two vectors, accurate for small angles too (acos is not, near 1). */
export function angleBetween(a: number[], b: number[]): number {
  const cx = a[1] * b[2] - a[2] * b[1],
    cy = a[2] * b[0] - a[0] * b[2],
    cz = a[0] * b[1] - a[1] * b[0];
  return Math.atan2(Math.hypot(cx, cy, cz), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

/** For each output vertex, the first output vertex at its bit-identical position (itself if it
 * is the first): where normals split at an infinitely sharp crease (prepare.ts splitCreases) a
 * point's copies share one position. */
export function firstAtPosition(out: { positions: ArrayLike<number>; vertexCount: number }): Uint32Array {
  const firstAt = new Map<string, number>();
  const first = new Uint32Array(out.vertexCount);
  for (let v = 0; v < out.vertexCount; v++) {
    const k = `${out.positions[3 * v]},${out.positions[3 * v + 1]},${out.positions[3 * v + 2]}`;
    const f = firstAt.get(k);
    first[v] = f ?? v;
    if (f === undefined) firstAt.set(k, v);
  }
  return first;
}

/** Weights of an output vertex per cage vertex, from its (srcTri, bary). */
function weightsByCageVertex(mesh: PreparedMesh, out: MeshReadback, v: number): Map<number, number> {
  const s = out.srcTri[v];
  const tv = [mesh.triVerts[3 * s], mesh.triVerts[3 * s + 1], mesh.triVerts[3 * s + 2]];
  const w = decodeBary(out.bary[v]);
  const m = new Map<number, number>();
  w.forEach((x, i) => {
    if (x !== 0) m.set(tv[i], x);
  });
  return m;
}

export function checkTessellation(
  mesh: PreparedMesh,
  edgeF: Uint32Array,
  out: MeshReadback,
  opts: {
    closed: boolean;
    maxErrors?: number;
    /** The surface at (t, w); null where the caller holds the vertex to its own rule instead. */
    /** The surface at (t, w), and the position error it is held to there (a fraction of the model
     * size; 1e-5 unless `bound` says otherwise, as in the Catmull-Clark surface's blended squares). */
    reference?: (t: number, w: [number, number, number]) => { pos: number[]; normal: number[]; bound?: number } | null;
    /** The tessellator splits normals at creases (prepare.ts splitCreases), so those points are
     * output once per side or sector: true for the Catmull-Clark surface's split (at infinitely
     * sharp creases: the mesh's own), or the split used (the ACC schemes': mesh.accSplit). */
    split?: boolean | CreaseSplit;
  },
): TessReport {
  const problems: string[] = [];
  const add = (p: string) => {
    if (problems.length < (opts.maxErrors ?? 20)) problems.push(p);
  };
  // Expected patterns from the GPU's own edge factors (the rule is tested separately).
  let expectedTriangles = 0;
  let expectedVertices = mesh.vertexCount;
  // Interior points of each edge, once per side where the normals split; and the extra sectors.
  const split: CreaseSplit | undefined = opts.split === true ? mesh : opts.split || undefined;
  let splitCopies = split ? split.slotOwner.length : 0;
  for (let e = 0; e < mesh.edgeCount; e++) {
    const interior = hableLine(edgeF[e] / ONE).x.length - 2;
    expectedVertices += interior;
    if (split?.edgeSplit[e]) splitCopies += interior;
  }
  expectedVertices += splitCopies;
  let triOut = 0;
  for (let t = 0; t < mesh.triangleCount; t++) {
    const tv = [mesh.triVerts[3 * t], mesh.triVerts[3 * t + 1], mesh.triVerts[3 * t + 2]];
    const factors = [0, 1, 2].map((i) => edgeF[mesh.triEdges[3 * t + i]] / ONE) as [number, number, number];
    const reverse = [0, 1, 2].map((i) => tv[i] > tv[(i + 1) % 3]) as unknown as Reverse;
    const p = clampedTriangle(factors, reverse);
    expectedTriangles += p.triangleCount;
    let interior = 0;
    for (let v = 0; v < p.vertexCount; v++) if (p.bary[3 * v] && p.bary[3 * v + 1] && p.bary[3 * v + 2]) interior++;
    expectedVertices += interior;
    for (let k = 0; k < p.triangleCount && triOut + k < out.triangleCount; k++) {
      for (let c = 0; c < 3; c++) {
        const gv = out.indices[3 * (triOut + k) + c];
        if (gv >= out.vertexCount) {
          add(`triangle ${triOut + k}: index ${gv} out of range`);
          continue;
        }
        const m = weightsByCageVertex(mesh, out, gv);
        const got = tv.map((x) => m.get(x) ?? 0);
        const lv = p.triangles[3 * k + c];
        const want = [p.bary[3 * lv], p.bary[3 * lv + 1], p.bary[3 * lv + 2]];
        if (got[0] + got[1] + got[2] !== ONE || got.some((x, i) => x !== want[i])) {
          add(`cage triangle ${t}, pattern triangle ${k}, corner ${c}: GPU barycentric ${got} ≠ CPU ${want}`);
        }
      }
    }
    triOut += p.triangleCount;
  }
  if (out.triangleCount !== expectedTriangles) add(`triangle count ${out.triangleCount} ≠ CPU ${expectedTriangles}`);
  if (out.vertexCount !== expectedVertices) add(`vertex count ${out.vertexCount} ≠ CPU ${expectedVertices}`);

  // The two sides of a split crease refer to two output vertices at one (bit-identical)
  // position; canonical[v] is the first vertex at v's position (v itself without splits).
  const canonical = split ? firstAtPosition(out) : Uint32Array.from({ length: out.vertexCount }, (_, v) => v);

  // Surface: every vertex against the CPU's Phong evaluation (or opts.reference) at its barycentrics.
  // A split crease's second copy has the first's position (the owner side's, displaced along its
  // normal where displacement is on): only its normal is its own side's.
  let maxPositionError = 0;
  let maxNormalError = 0;
  /** The vertex furthest over its bound (error ÷ bound), and the message for it. */
  let worstExcess = 0;
  let worstMessage = '';
  for (let v = 0; v < out.vertexCount; v++) {
    const s = out.srcTri[v];
    if (v < mesh.vertexCount && mesh.vertexOwner[v] === NO_OWNER) continue; // a cage vertex no face uses
    const m = weightsByCageVertex(mesh, out, v);
    const w = [0, 1, 2].map((i) => (m.get(mesh.triVerts[3 * s + i]) ?? 0) / ONE) as [number, number, number];
    const ref = opts.reference ? opts.reference(s, w) : phongPoint(mesh, s, w);
    const pos = [out.positions[3 * v], out.positions[3 * v + 1], out.positions[3 * v + 2]];
    const nrm = [out.normals[3 * v], out.normals[3 * v + 1], out.normals[3 * v + 2]];
    if (pos.some((x) => !Number.isFinite(x)) || nrm.some((x) => !Number.isFinite(x))) add(`vertex ${v}: NaN or infinity`);
    if (!ref) continue;
    const dp = canonical[v] !== v ? 0 : Math.hypot(pos[0] - ref.pos[0], pos[1] - ref.pos[1], pos[2] - ref.pos[2]) / mesh.size;
    maxPositionError = Math.max(maxPositionError, dp);
    maxNormalError = Math.max(maxNormalError, angleBetween(nrm, ref.normal));
    const bound = (ref as { bound?: number }).bound ?? 1e-5;
    if (dp / bound > worstExcess) {
      worstExcess = dp / bound;
      worstMessage = `position error ${dp} of the model size > ${bound}`;
    }
  }
  if (worstExcess > 1) add(worstMessage);

  // Watertight: every edge of a closed output used by exactly two triangles, once each way (by
  // the first vertex at each position where normals split, above).
  const directed = new Map<string, number>();
  for (let t = 0; t < out.triangleCount; t++) {
    for (let c = 0; c < 3; c++) {
      const a = canonical[out.indices[3 * t + c]],
        b = canonical[out.indices[3 * t + ((c + 1) % 3)]];
      if (a === b) add(`triangle ${t} repeats vertex ${a}`);
      const k = `${a},${b}`;
      directed.set(k, (directed.get(k) ?? 0) + 1);
    }
  }
  for (const [k, n] of directed) {
    const [a, b] = k.split(',');
    if (n > 1) add(`directed edge ${k} used ${n} times`);
    if (opts.closed && !directed.has(`${b},${a}`)) add(`edge ${k} has no opposite: not watertight`);
  }
  // No two vertices left at the same position that should have been one, except the copies of
  // a split crease: the same cage point (same weights) on an infinitely sharp edge or at a vertex
  // with extra sectors, exactly as many as laid out.
  const seen = new Map<string, number>();
  const hasSectors = new Set(
    Array.from(split?.slotOwner ?? [], (o) => {
      const { tri, corner } = OWNER_WORD.unpack(o);
      return mesh.triVerts[3 * tri + corner];
    }),
  );
  const sharpEdge = new Set<string>();
  for (let e = 0; e < mesh.edgeCount; e++) if (split?.edgeSplit[e]) sharpEdge.add(`${mesh.edgeVerts[2 * e]},${mesh.edgeVerts[2 * e + 1]}`);
  let copies = 0;
  for (let v = 0; v < out.vertexCount; v++) {
    if (v < mesh.vertexCount && mesh.vertexOwner[v] === NO_OWNER) continue;
    const k = `${out.positions[3 * v]},${out.positions[3 * v + 1]},${out.positions[3 * v + 2]}`;
    const other = seen.get(k);
    if (other !== undefined) {
      const a = weightsByCageVertex(mesh, out, other),
        b = weightsByCageVertex(mesh, out, v);
      const same = a.size === b.size && [...a].every(([x, w]) => b.get(x) === w);
      const at = [...b.keys()].sort((x, y) => x - y);
      const onCrease = (at.length === 1 && hasSectors.has(at[0])) || (at.length === 2 && sharpEdge.has(`${at[0]},${at[1]}`));
      if (split && same && onCrease) copies++;
      else add(`vertices ${other} and ${v} share the position ${k} but are not welded`);
    }
    seen.set(k, v);
  }
  if (copies !== splitCopies) add(`${copies} split-crease copies, ${splitCopies} laid out`);
  return { problems, maxPositionError, maxNormalError, expectedVertices, expectedTriangles };
}
