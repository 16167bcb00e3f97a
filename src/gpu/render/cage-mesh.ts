/**
 * The cage itself, on the GPU:
 *  - `uploadCageMesh` fills the same buffers as the compute tessellator (`TessellatedMesh`) with
 *    the cage's faces, fan-triangulated and smooth-shaded: the flat "before" view, and a stand-in
 *    that exercises every draw path without the tessellator;
 *  - `uploadCageLines` builds the cage overlay: one line per polygon edge (not the triangulation's
 *    diagonals), crease edges in their own colour.
 * The CPU halves (`triangulateCage`, `cageEdges`) are pure, for the unit tests. DOM-free.
 */
import type { Cage } from '../../mesh/types.ts';
import { BARY_CORNER1, BARY_CORNER2, type TessellatedMesh } from '../contract/tessellated-mesh.ts';

export interface TriangulatedCage {
  positions: Float32Array;
  /** Area-weighted vertex normals, unit length (0,0,0 for a vertex on no face). */
  normals: Float32Array;
  indices: Uint32Array;
  /** Per vertex, the packed barycentric of its corner in `srcTri` (see types.ts). */
  bary: Uint32Array;
  srcTri: Uint32Array;
  vertexCount: number;
  triangleCount: number;
}

const CORNER_CODES = [0, BARY_CORNER1, BARY_CORNER2];

/**
 * Fan-triangulate every face that is not a hole (corners 0,k,k+1), keeping the cage's vertices
 * shared, and sum each triangle's cross product (twice its area, along its normal) into its
 * corners: the area-weighted normal.
 */
export function triangulateCage(cage: Cage): TriangulatedCage {
  const nVerts = cage.positions.length / 3;
  const nFaces = cage.faceOffsets.length - 1;
  const holes = new Set(cage.holes);
  let triangleCount = 0;
  for (let f = 0; f < nFaces; f++) {
    if (!holes.has(f)) triangleCount += Math.max(0, cage.faceOffsets[f + 1] - cage.faceOffsets[f] - 2);
  }

  // Typed-array copies and scalar loops: with an array per triangle and Float32Array.from this
  // took 57 ms of the page's thread on a 40,000-face cage.
  const positions = new Float32Array(cage.positions);
  const indices = new Uint32Array(triangleCount * 3);
  const acc = new Float64Array(nVerts * 3);
  const bary = new Uint32Array(nVerts);
  const srcTri = new Uint32Array(nVerts).fill(0xffffffff);
  const P = cage.positions;
  const corner = (v: number, c: number, t: number, nx: number, ny: number, nz: number) => {
    acc[3 * v] += nx;
    acc[3 * v + 1] += ny;
    acc[3 * v + 2] += nz;
    // A shared vertex belongs to many triangles; it records the first one it is a corner of.
    if (srcTri[v] === 0xffffffff) {
      srcTri[v] = t;
      bary[v] = CORNER_CODES[c];
    }
  };

  let t = 0;
  for (let f = 0; f < nFaces; f++) {
    if (holes.has(f)) continue;
    const a = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - a;
    const i = cage.faceIndices[a];
    for (let k = 1; k + 1 < n; k++, t++) {
      const j = cage.faceIndices[a + k],
        l = cage.faceIndices[a + k + 1];
      indices[3 * t] = i;
      indices[3 * t + 1] = j;
      indices[3 * t + 2] = l;
      const ux = P[3 * j] - P[3 * i],
        uy = P[3 * j + 1] - P[3 * i + 1],
        uz = P[3 * j + 2] - P[3 * i + 2];
      const vx = P[3 * l] - P[3 * i],
        vy = P[3 * l + 1] - P[3 * i + 1],
        vz = P[3 * l + 2] - P[3 * i + 2];
      const nx = uy * vz - uz * vy,
        ny = uz * vx - ux * vz,
        nz = ux * vy - uy * vx;
      corner(i, 0, t, nx, ny, nz);
      corner(j, 1, t, nx, ny, nz);
      corner(l, 2, t, nx, ny, nz);
    }
  }

  const normals = new Float32Array(nVerts * 3);
  for (let v = 0; v < nVerts; v++) {
    const len = Math.hypot(acc[3 * v], acc[3 * v + 1], acc[3 * v + 2]);
    if (len > 0) for (let k = 0; k < 3; k++) normals[3 * v + k] = acc[3 * v + k] / len;
    if (srcTri[v] === 0xffffffff) srcTri[v] = 0;
  }
  return { positions, normals, indices, bary, srcTri, vertexCount: nVerts, triangleCount };
}

/** Upload the triangulated cage into fresh buffers with the tessellator's layout and usages. */
export function uploadCageMesh(device: GPUDevice, cage: Cage, triangulated?: TriangulatedCage): TessellatedMesh {
  const tri = triangulated ?? triangulateCage(cage);
  const STORAGE = GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST;
  const upload = (label: string, data: Uint32Array | Float32Array, usage: number) => {
    // Zero-size buffers are legal but cannot be bound; keep at least one element.
    const buffer = device.createBuffer({ label, size: Math.max(16, align4(data.byteLength)), usage });
    device.queue.writeBuffer(buffer, 0, data);
    return buffer;
  };
  const counts = new Uint32Array(4);
  counts[0] = tri.vertexCount;
  counts[1] = tri.triangleCount;
  new Float32Array(counts.buffer, 8, 1)[0] = 1; // budget scale: the cage is never over budget
  return {
    positions: upload('cage mesh positions', tri.positions, GPUBufferUsage.VERTEX | STORAGE),
    normals: upload('cage mesh normals', tri.normals, GPUBufferUsage.VERTEX | STORAGE),
    bary: upload('cage mesh barycentrics', tri.bary, STORAGE),
    srcTri: upload('cage mesh source triangles', tri.srcTri, STORAGE),
    indices: upload('cage mesh indices', tri.indices, GPUBufferUsage.INDEX | STORAGE),
    // Written from the CPU here; the tessellator writes its own on the GPU.
    drawArgs: upload('cage mesh draw args', new Uint32Array([tri.triangleCount * 3, 1, 0, 0, 0]), GPUBufferUsage.INDIRECT | STORAGE),
    counts: upload('cage mesh counts', counts, STORAGE),
    vertexCapacity: tri.vertexCount,
    triangleCapacity: tri.triangleCount,
  };
}

export function destroyMesh(mesh: TessellatedMesh): void {
  for (const b of [mesh.positions, mesh.normals, mesh.bary, mesh.srcTri, mesh.indices, mesh.drawArgs, mesh.counts]) b.destroy();
}

export interface CageEdges {
  /** Vertex pairs, one per undirected polygon edge. */
  pairs: Uint32Array;
  /** Per edge, its crease sharpness (0 smooth, 10 infinitely sharp). */
  sharpness: Float32Array;
}

/** Every polygon edge once (holes included: they are part of the cage), with its crease sharpness. */
export function cageEdges(cage: Cage): CageEdges {
  const nVerts = cage.positions.length / 3;
  const key = (a: number, b: number) => (a < b ? a * nVerts + b : b * nVerts + a);
  const creases = new Map<number, number>();
  for (const c of cage.creases) creases.set(key(c.v0, c.v1), Math.max(c.sharpness, creases.get(key(c.v0, c.v1)) ?? 0));
  const seen = new Set<number>();
  const pairs: number[] = [];
  const sharpness: number[] = [];
  const nFaces = cage.faceOffsets.length - 1;
  for (let f = 0; f < nFaces; f++) {
    const a = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - a;
    for (let k = 0; k < n; k++) {
      const v0 = cage.faceIndices[a + k];
      const v1 = cage.faceIndices[a + ((k + 1) % n)];
      const id = key(v0, v1);
      if (seen.has(id)) continue;
      seen.add(id);
      pairs.push(v0, v1);
      sharpness.push(creases.get(id) ?? 0);
    }
  }
  return { pairs: Uint32Array.from(pairs), sharpness: Float32Array.from(sharpness) };
}

/** The cage overlay: two vertices per edge, position (float32x3) and colour (unorm8x4), stride 16. */
export interface CageLines {
  vertices: GPUBuffer;
  vertexCount: number;
  edgeCount: number;
}

export const CAGE_LINE_STRIDE = 16;
/** Smooth edges, and crease edges (infinitely sharp at the end of the ramp). RGBA, 0..255, sRGB. */
const CAGE_SMOOTH = [255, 138, 61, 255];
const CAGE_CREASE = [86, 196, 255, 255];
/** The UV-seam view: seam edges (src/mesh/uv.ts uvSeams) stand out, the others recede. */
const CAGE_SEAM = [255, 60, 200, 255];
const CAGE_NOT_SEAM = [90, 90, 90, 255];

/** `seam(a, b)`, when given, draws the UV-seam view: seam edges in CAGE_SEAM, the rest dim. */
export function cageLineVertices(
  cage: Cage,
  seam?: (a: number, b: number) => boolean,
): { data: ArrayBuffer; vertexCount: number; edgeCount: number } {
  const { pairs, sharpness } = cageEdges(cage);
  const edgeCount = sharpness.length;
  const data = new ArrayBuffer(edgeCount * 2 * CAGE_LINE_STRIDE);
  const f32 = new Float32Array(data);
  const u8 = new Uint8Array(data);
  for (let e = 0; e < edgeCount; e++) {
    const s = Math.min(1, sharpness[e] / 2); // semi-sharp edges in between
    const colour = seam
      ? seam(pairs[2 * e], pairs[2 * e + 1])
        ? CAGE_SEAM
        : CAGE_NOT_SEAM
      : CAGE_SMOOTH.map((c, i) => Math.round(c + (CAGE_CREASE[i] - c) * s));
    for (let end = 0; end < 2; end++) {
      const v = pairs[2 * e + end];
      const at = (2 * e + end) * CAGE_LINE_STRIDE;
      f32.set([cage.positions[3 * v], cage.positions[3 * v + 1], cage.positions[3 * v + 2]], at / 4);
      u8.set(colour, at + 12);
    }
  }
  return { data, vertexCount: edgeCount * 2, edgeCount };
}

export function uploadCageLines(device: GPUDevice, cage: Cage, seam?: (a: number, b: number) => boolean): CageLines {
  const { data, vertexCount, edgeCount } = cageLineVertices(cage, seam);
  const vertices = device.createBuffer({
    label: 'cage overlay lines',
    size: Math.max(CAGE_LINE_STRIDE, data.byteLength),
    usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST,
  });
  device.queue.writeBuffer(vertices, 0, data);
  return { vertices, vertexCount, edgeCount };
}

function align4(n: number): number {
  return (n + 3) & ~3;
}
