/**
 * One Catmull-Clark step of a whole cage, as a new cage whose limit surface is the same: what the
 * ACC schemes take in place of a cage with n-gons (Loop and Schaefer's and the NVIDIA paper's
 * answer: their patches are quads and triangles, and one step turns every face into quads).
 *
 * The new cage is level 1 of the cage's refinement (src/subdiv/level.ts refine, OpenSubdiv's rules
 * and numbering): vertex points [0, nv) keep the cage's vertex numbers, then the edge points
 * [nv, nv + ne) in the topology's edge order, then the face points. Child face h (one per face
 * corner h of the cage, in face order) is [V(c_j), E(c_j c_j+1), F, E(c_j-1 c_j)] for corner j of
 * its parent face: so on a cage quad, child j is the quadrant at corner j with (s, t) along the
 * quad's edges j → j+1 and j → j−1; on a triangle or an n-gon, child j is sub-face j of the
 * surface's (k, s, t) parametrisation (src/subdiv/evaluate.ts).
 *
 * Why the limit is the same, tag by tag: the decayed sharpness of level 1 is written as the new
 * cage's crease and corner tags (a crease's child halves; Chaikin's averaged values), and refining
 * the new cage from there repeats the original's levels 2, 3, … exactly (the same rules on the same
 * points; the options are written into fileOptions, the creasing method among them). Boundaries
 * need no tags of their own (they are sharpened again from the new topology, as the cage's were);
 * holes stay holes in every child. tests/subdiv/refine-cage.test.ts evaluates both limits.
 *
 * The positions of the new cage follow the cage's at the time of the call: a deforming cage calls
 * this again (or refines its positions with refine() over the same topology).
 */
import {
  type Cage,
  type CornerTag,
  type CreaseTag,
  DEFAULT_OPTIONS,
  type SubdivOptions,
  type Topology,
  buildTopology,
  faceCount,
} from '../mesh/index.ts';
import { levelFromCage, refine } from './level.ts';

export interface RefinedCage {
  cage: Cage;
  /** The cage face each new face comes from, and which of its corners the new face holds. */
  faceParent: Int32Array;
  faceCorner: Int32Array;
}

/** The cage's subdivision options: its file's, over OpenSubdiv's defaults. */
export function cageOptions(cage: Cage): SubdivOptions {
  return { ...DEFAULT_OPTIONS, ...cage.fileOptions };
}

/** Whether some face of the cage has more than four corners. */
export function hasNgons(cage: Cage): boolean {
  const n = faceCount(cage);
  for (let f = 0; f < n; f++) if (cage.faceOffsets[f + 1] - cage.faceOffsets[f] > 4) return true;
  return false;
}

/** One Catmull-Clark step of the whole cage (see the header). Throws as buildTopology does for a
 * cage the topology refuses. */
export function refineCage(cage: Cage, topology?: Topology, options: SubdivOptions = cageOptions(cage)): RefinedCage {
  const topo = topology ?? buildTopology(cage);
  const child = refine(levelFromCage(cage, topo, options));
  const he = child.he;
  const faceParent = child.faceParent as Int32Array;
  const faceCorner = child.faceCorner as Int32Array;
  const nFaces = he.nFaces;

  const creases: CreaseTag[] = [];
  for (let e = 0; e < he.nEdges; e++) {
    const s = child.edgeSharp[e];
    if (s > 0) creases.push({ v0: he.edgeVerts[2 * e], v1: he.edgeVerts[2 * e + 1], sharpness: s, line: 0 });
  }
  const corners: CornerTag[] = [];
  for (let v = 0; v < he.nVerts; v++) {
    const s = child.vertSharp[v];
    if (s > 0) corners.push({ v, sharpness: s, line: v < cage.vertexLines.length ? cage.vertexLines[v] : 0 });
  }
  const holes: number[] = [];
  const holeLines: number[] = [];
  const faceLines = new Int32Array(nFaces);
  for (let h = 0; h < nFaces; h++) {
    const line = cage.faceLines[faceParent[h]] ?? 0;
    faceLines[h] = line;
    if (child.hole[h]) {
      holes.push(h);
      holeLines.push(line);
    }
  }
  const vertexLines = new Int32Array(he.nVerts);
  vertexLines.set(cage.vertexLines.subarray(0, Math.min(cage.vertexLines.length, he.nVerts)));

  const { uvs, faceUvIndices } = refinedUvs(cage, faceParent, faceCorner);
  return {
    cage: {
      positions: child.pos,
      faceOffsets: Int32Array.from(he.faceOffsets),
      faceIndices: Int32Array.from(he.faceIndices),
      uvs,
      faceUvIndices,
      // The file's vertex normals belong to the cage's corners; the new corners have none.
      normals: new Float64Array(0),
      faceNormalIndices: new Int32Array(he.faceIndices.length).fill(-1),
      creases,
      corners,
      holes,
      holeLines,
      fileOptions: { ...options },
      rawTags: cage.rawTags.slice(),
      faceLines,
      vertexLines,
      // Vertex points keep their numbers: a copy exempt from the corner rule stays exempt.
      ...(cage.cornerExempt ? { cornerExempt: cage.cornerExempt.slice() } : {}),
    },
    faceParent,
    faceCorner,
  };
}

/**
 * The new corners' uvs, "linear all" (as src/mesh/uv.ts uvAtSubFace interpolates a sub-face): a
 * vertex point keeps its corner's uv, an edge point takes the mean of its edge's two corners in
 * that face, the face point the mean of the face's corners; per face, so a seam stays a seam. A
 * face with a corner without a uv gives its children none (-1).
 */
function refinedUvs(cage: Cage, faceParent: Int32Array, faceCorner: Int32Array): { uvs: Float64Array; faceUvIndices: Int32Array } {
  const nFaces = faceParent.length;
  const faceUvIndices = new Int32Array(4 * nFaces).fill(-1);
  if (cage.uvs.length === 0) return { uvs: new Float64Array(0), faceUvIndices };
  const uvs = new Float64Array(2 * 4 * nFaces);
  const uvOf = (h: number, c: 0 | 1) => cage.uvs[2 * cage.faceUvIndices[h] + c];
  for (let h = 0; h < nFaces; h++) {
    const f = faceParent[h];
    const a = cage.faceOffsets[f],
      n = cage.faceOffsets[f + 1] - a,
      j = faceCorner[h];
    let complete = true;
    for (let i = 0; i < n; i++) if (!(cage.faceUvIndices[a + i] >= 0)) complete = false;
    if (!complete) continue;
    const at = (i: number) => a + ((((j + i) % n) + n) % n);
    for (const c of [0, 1] as const) {
      let centre = 0;
      for (let i = 0; i < n; i++) centre += uvOf(a + i, c) / n;
      const here = uvOf(at(0), c);
      const o = 8 * h + c;
      uvs[o] = here;
      uvs[o + 2] = (here + uvOf(at(1), c)) / 2;
      uvs[o + 4] = centre;
      uvs[o + 6] = (uvOf(at(-1), c) + here) / 2;
    }
    for (let i = 0; i < 4; i++) faceUvIndices[4 * h + i] = 4 * h + i;
  }
  return { uvs, faceUvIndices };
}
