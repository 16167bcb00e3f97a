/**
 * CPU preparation of a cage for the compute tessellator, done once per model: plain flat
 * arrays that the GPU passes read (cage → topology → patches in the data flow).
 *
 *  - Faces are split into triangles: a triangle is itself, a quad is cut along its 0–2 diagonal
 *    (triangles (0, 1, 2) and (0, 2, 3)), and a face with n ≥ CENTRE_FAN_MIN_CORNERS corners is
 *    a fan of n triangles (centre, k, k + 1) round a new vertex at its centre. Why the centre:
 *    Catmull-Clark's parametrization of an n-gon is singular at its centre (an extraordinary
 *    point of valence n, whose sub-faces shrink like r^0.64 for n = 16), so a fan from corner 0
 *    sends long thin triangles across that point, and a straight row of the pattern in one of
 *    them bends on the surface by more than the sliver is wide: the pawn's 16-gon and the gear's
 *    7-gons folded 124 and 125 triangles at factor 8 that way. Round the centre every triangle
 *    has the singular point at a corner, and none folds (tests/gpu/tess/folds.node.test.ts). The
 *    centre vertices come after the cage's (index ≥ cageVertexCount), one per such face in
 *    face order; a centre lies at the mean of the face's corners with the face's normal.
 *    Faces without a limit surface are dropped: tagged holes, and under boundary
 *    interpolation 'none' the faces at an unsharpened boundary (OpenSubdiv's rule, as
 *    computeSharpness), so no surface evaluates a face the subdivision says is not there.
 *    Each triangle keeps its source face.
 *  - Vertex normals: area-weighted (the sum of the faces' cross products, Newell's), for Phong
 *    tessellation and for the adaptive factor rule; a centre vertex has its one face's. The
 *    Phong surface's α per edge follows from them (phong.ts phongTriAlphas).
 *  - Edges: every undirected edge of the triangulation once, canonically from its lower to
 *    its higher vertex index. The factor of an edge is computed and stored once per edge, so the
 *    two triangles of an edge can never disagree; its line runs in that canonical direction.
 *  - Per triangle: its three edge ids, and its pattern frame (clamped.ts chooseFrame) from the
 *    reverse flags, packed in one u32.
 */
import { type Cage, type SubdivOptions, SHARPNESS_INFINITE } from '../../mesh/types.ts';
import { ACC_SHARP_FROM } from '../../subdiv/acc.ts';
import { DEFAULT_OPTIONS, buildTopology, computeSharpness } from '../../mesh/index.ts';
import { chooseFrame, type Reverse } from '../../pattern/clamped.ts';
import { NO_OWNER, OWNER_WORD, PATTERN_FRAME_WORD } from '../contract/tess.ts';
import { phongTriAlphas } from '../surface/phong-alpha.ts';

/** Faces with at least this many corners are fanned round a centre vertex (see above). */
export const CENTRE_FAN_MIN_CORNERS = 5;

/** Is a face with this many corners fanned round a centre vertex? (One question, asked by the
 * triangulation here and by every builder that must know where a triangle's corner 0 is.) */
export function fannedRoundCentre(corners: number): boolean {
  return corners >= CENTRE_FAN_MIN_CORNERS;
}

export interface PreparedMesh {
  /** Cage vertices, then one centre vertex per face fanned round its centre. */
  vertexCount: number;
  /** The cage's vertex count: vertices below it are the cage's (same index), the rest centres. */
  cageVertexCount: number;
  triangleCount: number;
  edgeCount: number;
  /** xyz per vertex (f32): the cage's positions, then the centres. */
  positions: Float32Array;
  /** Unit vertex normals, xyz per vertex (f32). */
  normals: Float32Array;
  /** Three cage vertices per triangle. */
  triVerts: Uint32Array;
  /** Three edge ids per triangle: edge i joins corner i to corner i+1. */
  triEdges: Uint32Array;
  /** The Phong surface's α of each triangle's three edges, 3 per triangle (phong.ts
   * phongTriAlphas: lower than PHONG_ALPHA where a vertex normal lies near a face's plane). */
  triPhongAlpha: Float32Array;
  /** Pattern frame per triangle (packPatternFrame). */
  triPatternFrame: Uint32Array;
  /** Source face of each triangle. */
  triFace: Uint32Array;
  /** Which triangle of its face each is, by the face corners it spans: k for (0, k, k + 1) of a
   * triangle or quad (k = 1, 2), or for (centre, k, k + 1 mod n) of a centre-fanned face. */
  triFan: Uint32Array;
  /** Two cage vertices per edge, lower index first. */
  edgeVerts: Uint32Array;
  /** One triangle of each edge and the edge's local index in it (an OwnerWord, contract/tess.ts). */
  edgeOwner: Uint32Array;
  /** The edge's second triangle (an OwnerWord), NO_OWNER on a boundary edge: with edgeOwner, the
   * two triangles whose interiors the factor rule looks into (wgsl/tess/factors.wgsl). */
  edgeTwin: Uint32Array;
  /** One triangle of each vertex and its corner in it (an OwnerWord), NO_OWNER if unused. */
  vertexOwner: Uint32Array;
  /** Split normals at infinitely sharp creases (splitCreases below): the output vertex of each
   * triangle corner, three per triangle (the cage vertex itself, or one of the extra slots). */
  cornerSlot: Uint32Array;
  /** The extra output vertices, after the vertexCount cage and centre vertices: one per sector
   * of a crease or corner vertex beyond the vertex owner's, as an OwnerWord of a triangle corner
   * in that sector. */
  slotOwner: Uint32Array;
  /** Per edge, 1 where its points are output twice, once per side (an infinitely sharp edge
   * with two triangles), else 0. */
  edgeSplit: Uint32Array;
  /** The same three for the ACC schemes, which build every crease and corner of sharpness ≥ 1 as
   * infinitely sharp (src/subdiv/acc.ts): their patches meet there with a normal per side too. */
  accSplit: CreaseSplit;
  /** Bounding box diagonal length: the model's size for tolerances. */
  size: number;
  bboxMin: [number, number, number];
  bboxMax: [number, number, number];
}

export { NO_OWNER };

/** The pattern frame of a triangle with these reverse flags, as a PatternFrameWord (its bits are
 * declared in contract/tess.ts). */
export function packPatternFrame(reverse: Reverse): number {
  return PATTERN_FRAME_WORD.pack(chooseFrame(reverse));
}

/** Faces without a limit surface under these options (tagged holes; boundary 'none' adds more). */
function holeFaces(cage: Cage, options: Partial<SubdivOptions>): Set<number> {
  const holes = new Set(cage.holes);
  if (options.boundary === 'none') {
    const topo = buildTopology(cage);
    const { hole } = computeSharpness(cage, topo, { ...DEFAULT_OPTIONS, ...options });
    for (let f = 0; f < hole.length; f++) if (hole[f]) holes.add(f);
  }
  return holes;
}

export function prepareMesh(cage: Cage, options: Partial<SubdivOptions> = cage.fileOptions): PreparedMesh {
  const nV = cage.positions.length / 3;
  const holes = holeFaces(cage, options);
  const tris: number[] = [];
  const faces: number[] = [];
  const fans: number[] = [];
  const nFaces = cage.faceOffsets.length - 1;
  const P = cage.positions;
  // Newell's normal of every face: robust for non-planar polygons, area-weighted.
  const faceNormal = new Float64Array(3 * nFaces);
  for (let f = 0; f < nFaces; f++) {
    const s = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - s;
    for (let k = 0; k < n; k++) {
      const a = cage.faceIndices[s + k],
        b = cage.faceIndices[s + ((k + 1) % n)];
      faceNormal[3 * f] += (P[3 * a + 1] - P[3 * b + 1]) * (P[3 * a + 2] + P[3 * b + 2]);
      faceNormal[3 * f + 1] += (P[3 * a + 2] - P[3 * b + 2]) * (P[3 * a] + P[3 * b]);
      faceNormal[3 * f + 2] += (P[3 * a] - P[3 * b]) * (P[3 * a + 1] + P[3 * b + 1]);
    }
  }
  const centreFace: number[] = [];
  for (let f = 0; f < nFaces; f++) {
    if (holes.has(f)) continue;
    const s = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - s;
    if (fannedRoundCentre(n)) {
      const c = nV + centreFace.length;
      centreFace.push(f);
      for (let k = 0; k < n; k++) {
        tris.push(c, cage.faceIndices[s + k], cage.faceIndices[s + ((k + 1) % n)]);
        faces.push(f);
        fans.push(k);
      }
      continue;
    }
    for (let k = 1; k + 1 < n; k++) {
      tris.push(cage.faceIndices[s], cage.faceIndices[s + k], cage.faceIndices[s + k + 1]);
      faces.push(f);
      fans.push(k);
    }
  }
  const nT = tris.length / 3;
  const nVAll = nV + centreFace.length;

  const acc = new Float64Array(3 * nVAll);
  for (let f = 0; f < nFaces; f++) {
    const s = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - s;
    for (let k = 0; k < n; k++) {
      const v = cage.faceIndices[s + k];
      for (let c = 0; c < 3; c++) acc[3 * v + c] += faceNormal[3 * f + c];
    }
  }
  const positions = new Float32Array(3 * nVAll);
  positions.set(P);
  centreFace.forEach((f, j) => {
    const s = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - s;
    const v = nV + j;
    for (let c = 0; c < 3; c++) {
      let sum = 0;
      for (let k = 0; k < n; k++) sum += P[3 * cage.faceIndices[s + k] + c];
      positions[3 * v + c] = sum / n;
      acc[3 * v + c] = faceNormal[3 * f + c];
    }
  });
  const normals = new Float32Array(3 * nVAll);
  for (let v = 0; v < nVAll; v++) {
    const l = Math.hypot(acc[3 * v], acc[3 * v + 1], acc[3 * v + 2]);
    if (l > 0) for (let c = 0; c < 3; c++) normals[3 * v + c] = acc[3 * v + c] / l;
    else normals[3 * v + 2] = 1; // an unused or degenerate vertex: any unit vector
  }

  const edgeIds = new Map<number, number>();
  const edgeVerts: number[] = [];
  const edgeOwner: number[] = [];
  const edgeTwin: number[] = [];
  const triEdges = new Uint32Array(3 * nT);
  const triPatternFrame = new Uint32Array(nT);
  const vertexOwner = new Uint32Array(nVAll).fill(NO_OWNER);
  for (let t = 0; t < nT; t++) {
    const reverse: boolean[] = [];
    for (let i = 0; i < 3; i++) {
      const a = tris[3 * t + i],
        b = tris[3 * t + ((i + 1) % 3)];
      const lo = Math.min(a, b),
        hi = Math.max(a, b);
      const key = lo * nVAll + hi;
      let e = edgeIds.get(key);
      if (e === undefined) {
        e = edgeVerts.length / 2;
        edgeIds.set(key, e);
        edgeVerts.push(lo, hi);
        edgeOwner.push(OWNER_WORD.pack({ corner: i, tri: t }));
        edgeTwin.push(NO_OWNER);
      } else if (edgeTwin[e] === NO_OWNER) {
        edgeTwin[e] = OWNER_WORD.pack({ corner: i, tri: t });
      }
      triEdges[3 * t + i] = e;
      reverse.push(a > b); // walked from its higher vertex: reversed
      if (vertexOwner[a] === NO_OWNER) vertexOwner[a] = OWNER_WORD.pack({ corner: i, tri: t });
    }
    triPatternFrame[t] = packPatternFrame(reverse as unknown as Reverse);
  }

  const bboxMin: [number, number, number] = [Infinity, Infinity, Infinity];
  const bboxMax: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  for (let v = 0; v < nVAll; v++) {
    if (vertexOwner[v] === NO_OWNER) continue;
    for (let c = 0; c < 3; c++) {
      bboxMin[c] = Math.min(bboxMin[c], positions[3 * v + c]);
      bboxMax[c] = Math.max(bboxMax[c], positions[3 * v + c]);
    }
  }
  const size = nT ? Math.hypot(bboxMax[0] - bboxMin[0], bboxMax[1] - bboxMin[1], bboxMax[2] - bboxMin[2]) : 0;
  const split = splitCreases(cage, tris, faces, edgeVerts, edgeOwner, edgeTwin, vertexOwner, SHARPNESS_INFINITE);
  const accSplit = splitCreases(cage, tris, faces, edgeVerts, edgeOwner, edgeTwin, vertexOwner, ACC_SHARP_FROM);

  return {
    vertexCount: nVAll,
    cageVertexCount: nV,
    triangleCount: nT,
    edgeCount: edgeVerts.length / 2,
    positions,
    normals,
    triVerts: Uint32Array.from(tris),
    triEdges,
    triPhongAlpha: phongTriAlphas({ triangleCount: nT, edgeCount: edgeVerts.length / 2, triVerts: tris, triEdges }, positions, normals),
    triPatternFrame,
    triFace: Uint32Array.from(faces),
    triFan: Uint32Array.from(fans),
    edgeVerts: Uint32Array.from(edgeVerts),
    edgeOwner: Uint32Array.from(edgeOwner),
    edgeTwin: Uint32Array.from(edgeTwin),
    vertexOwner,
    ...split,
    accSplit,
    size,
    bboxMin,
    bboxMax,
  };
}

/** Where a surface's normals split (splitCreases): per triangle corner its output vertex, the
 * extra sectors' owners, per edge whether its points are output once per side. */
export interface CreaseSplit {
  cornerSlot: Uint32Array;
  slotOwner: Uint32Array;
  edgeSplit: Uint32Array;
}

/**
 * Split normals. Across an infinitely sharp crease the limit surface has a normal per side, and
 * at a vertex where such creases meet, one per SECTOR (the faces between two of them); at a
 * vertex with an infinitely sharp corner tag, one per face. One output vertex per point would
 * give the far side's triangles the near side's normal (tests/gpu/cc/crease-normals.node.test.ts), so:
 *  - an infinitely sharp edge with two triangles has its points output twice (edgeSplit), the
 *    second copy for its twin triangle (edgeTwin);
 *  - a vertex gets one output vertex per sector: the sector of its owner triangle keeps the
 *    vertex's own index, every other sector an extra slot after the vertices (slotOwner).
 * Both copies of a point take their position from the same evaluation (the owner side's), so the
 * output stays watertight in positions; only their normals differ. Sectors are found by joining
 * the corners at a vertex across every edge that is not split (at a corner-tagged vertex, only
 * across edges inside one cage face), in time linear in the triangles.
 *
 * The Catmull-Clark evaluator gives each face's corner its own sector's limit normal (at an
 * extraordinary vertex from the fan's per-face tangents, src/gpu/cc/build.ts "fan limits"; at a
 * regular one from the patch with its phantom points), so every copy gets its side's normal.
 */
function splitCreases(
  cage: Cage,
  tris: readonly number[],
  faces: readonly number[],
  edgeVerts: readonly number[],
  edgeOwner: readonly number[],
  edgeTwin: readonly number[],
  vertexOwner: Uint32Array,
  sharpFrom: number,
): CreaseSplit {
  const nT = tris.length / 3;
  const nE = edgeVerts.length / 2;
  const nVAll = vertexOwner.length;
  const key = (a: number, b: number) => (a < b ? `${a},${b}` : `${b},${a}`);
  const sharp = new Set(cage.creases.filter((c) => c.sharpness >= sharpFrom).map((c) => key(c.v0, c.v1)));
  const cornerTag = new Set(cage.corners.filter((c) => c.sharpness >= sharpFrom).map((c) => c.v));

  const edgeSplit = new Uint32Array(nE);
  for (let e = 0; e < nE; e++) {
    const a = edgeVerts[2 * e],
      b = edgeVerts[2 * e + 1];
    if (edgeTwin[e] !== NO_OWNER && sharp.has(key(a, b))) edgeSplit[e] = 1;
  }

  // Union-find over triangle corners (3t + i).
  const parent = Uint32Array.from({ length: 3 * nT }, (_, c) => c);
  const find = (c: number): number => {
    while (parent[c] !== c) {
      parent[c] = parent[parent[c]];
      c = parent[c];
    }
    return c;
  };
  const cornerOf = (t: number, v: number) => 3 * t + (tris[3 * t] === v ? 0 : tris[3 * t + 1] === v ? 1 : 2);
  for (let e = 0; e < nE; e++) {
    if (edgeTwin[e] === NO_OWNER || edgeSplit[e]) continue;
    const t0 = OWNER_WORD.unpack(edgeOwner[e]).tri,
      t1 = OWNER_WORD.unpack(edgeTwin[e]).tri;
    for (const v of [edgeVerts[2 * e], edgeVerts[2 * e + 1]]) {
      if (cornerTag.has(v) && faces[t0] !== faces[t1]) continue;
      const a = find(cornerOf(t0, v)),
        b = find(cornerOf(t1, v));
      if (a !== b) parent[Math.max(a, b)] = Math.min(a, b);
    }
  }
  // The owner's sector keeps the vertex; the others get slots in the order they are met.
  const rootSlot = new Map<number, number>();
  for (let v = 0; v < nVAll; v++) {
    if (vertexOwner[v] === NO_OWNER) continue;
    const o = OWNER_WORD.unpack(vertexOwner[v]);
    rootSlot.set(find(3 * o.tri + o.corner), v);
  }
  const cornerSlot = new Uint32Array(3 * nT);
  const slotOwner: number[] = [];
  for (let c = 0; c < 3 * nT; c++) {
    const r = find(c);
    let slot = rootSlot.get(r);
    if (slot === undefined) {
      slot = nVAll + slotOwner.length;
      slotOwner.push(OWNER_WORD.pack({ corner: c % 3, tri: Math.floor(c / 3) }));
      rootSlot.set(r, slot);
    }
    cornerSlot[c] = slot;
  }
  return { cornerSlot, slotOwner: Uint32Array.from(slotOwner), edgeSplit };
}
