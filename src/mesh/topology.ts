// Half-edge adjacency for faces of any size, validation of cages, boundary
// sharpening as OpenSubdiv does it, and the per-face classification the GPU
// path needs. Everything is flat typed arrays.
import { CageError, type CageIssue } from './errors.ts';
import { type Cage, type SubdivOptions, DEFAULT_OPTIONS, SHARPNESS_INFINITE } from './types.ts';

/**
 * Half-edge h is face corner h: it runs from faceIndices[h] to the next corner of
 * the same face. twin[h] is the opposite half-edge, or -1 on a boundary.
 */
export interface HalfEdges {
  nVerts: number;
  nFaces: number;
  nEdges: number;
  faceOffsets: Int32Array;
  faceIndices: Int32Array;
  /** Face of each half-edge. */
  heFace: Int32Array;
  /** Next / previous half-edge in the same face. */
  heNext: Int32Array;
  hePrev: Int32Array;
  heTwin: Int32Array;
  heEdge: Int32Array;
  /** Edge e joins edgeVerts[2e] and edgeVerts[2e+1] (direction of its first half-edge). */
  edgeVerts: Int32Array;
  /** Number of faces on each edge (1 boundary, 2 interior, more: non-manifold). */
  edgeFaceCount: Int32Array;
  /** A half-edge of each edge. */
  edgeHe: Int32Array;
  /** Outgoing half-edges (face corners) of vertex v: vertHe[vertHeOffsets[v] .. vertHeOffsets[v+1]). */
  vertHeOffsets: Int32Array;
  vertHe: Int32Array;
  /** Incident edges of vertex v (CSR). */
  vertEdgeOffsets: Int32Array;
  vertEdges: Int32Array;
}

export interface HalfEdgeProblem {
  kind: 'non-manifold-edge' | 'inconsistent-winding';
  edge: number;
  faces: number[];
}

/** Build half-edge adjacency. Never throws on bad topology: problems are returned. */
export function buildHalfEdges(
  nVerts: number,
  faceOffsets: Int32Array,
  faceIndices: Int32Array,
): { he: HalfEdges; problems: HalfEdgeProblem[] } {
  const nFaces = faceOffsets.length - 1;
  const nHe = faceIndices.length;
  const heFace = new Int32Array(nHe);
  const heNext = new Int32Array(nHe);
  const hePrev = new Int32Array(nHe);
  const heTwin = new Int32Array(nHe).fill(-1);
  const heEdge = new Int32Array(nHe);
  for (let f = 0; f < nFaces; f++) {
    const a = faceOffsets[f],
      b = faceOffsets[f + 1],
      n = b - a;
    for (let j = 0; j < n; j++) {
      heFace[a + j] = f;
      heNext[a + j] = a + ((j + 1) % n);
      hePrev[a + j] = a + ((j + n - 1) % n);
    }
  }
  const map = new Map<number, number>();
  const edgeVertsA: number[] = [];
  const edgeHeA: number[] = [];
  const edgeCount: number[] = [];
  const extra = new Map<number, number[]>();
  const problems: HalfEdgeProblem[] = [];
  for (let h = 0; h < nHe; h++) {
    const a = faceIndices[h],
      b = faceIndices[heNext[h]];
    const key = a < b ? a * nVerts + b : b * nVerts + a;
    let e = map.get(key);
    if (e === undefined) {
      e = edgeHeA.length;
      map.set(key, e);
      edgeVertsA.push(a, b);
      edgeHeA.push(h);
      edgeCount.push(1);
    } else {
      const c = edgeCount[e]++;
      if (c === 1) {
        const h0 = edgeHeA[e];
        if (faceIndices[h0] === a) {
          let list = extra.get(e);
          if (!list) extra.set(e, (list = [h0]));
          list.push(h);
        } else {
          heTwin[h0] = h;
          heTwin[h] = h0;
        }
      } else {
        let list = extra.get(e);
        if (!list) {
          list = [edgeHeA[e]];
          const t = heTwin[edgeHeA[e]];
          if (t >= 0) list.push(t);
          extra.set(e, list);
        }
        list.push(h);
      }
    }
    heEdge[h] = e;
  }
  for (const [e, list] of extra) {
    for (const h of list) heTwin[h] = -1;
    const faces = list.map((h) => heFace[h]);
    problems.push({ kind: list.length > 2 ? 'non-manifold-edge' : 'inconsistent-winding', edge: e, faces });
  }
  const nEdges = edgeHeA.length;
  const edgeVerts = Int32Array.from(edgeVertsA);
  // Vertex -> outgoing half-edges, vertex -> edges (CSR).
  const { vertHeOffsets, vertHe, vertEdgeOffsets, vertEdges } = vertexAdjacency(nVerts, faceIndices, edgeVerts);
  return {
    he: {
      nVerts,
      nFaces,
      nEdges,
      faceOffsets,
      faceIndices,
      heFace,
      heNext,
      hePrev,
      heTwin,
      heEdge,
      edgeVerts,
      edgeFaceCount: Int32Array.from(edgeCount),
      edgeHe: Int32Array.from(edgeHeA),
      vertHeOffsets,
      vertHe,
      vertEdgeOffsets,
      vertEdges,
    },
    problems,
  };
}

/**
 * Ordered ring of vertex v, OpenSubdiv's convention: face i contains the directed
 * edge v->e_i and e_{i+1}->v. For a boundary vertex the ring starts at the leading
 * boundary edge. `he[i]` is the half-edge v->e_i inside face i (length = #faces).
 * Returns null if the faces around v do not form a single fan (non-manifold).
 */
export function vertexRing(m: HalfEdges, v: number, startHe = -1): { he: number[]; boundary: boolean } | null {
  const a = m.vertHeOffsets[v],
    b = m.vertHeOffsets[v + 1];
  const n = b - a;
  if (n === 0) return { he: [], boundary: false };
  let nb = 0;
  let start = startHe;
  for (let k = a; k < b; k++)
    if (m.heTwin[m.vertHe[k]] < 0) {
      nb++;
      start = m.vertHe[k];
    }
  if (nb > 1) return null;
  const boundary = nb === 1;
  if (start < 0) start = m.vertHe[a];
  const ring: number[] = [];
  let h = start;
  for (let guard = 0; guard <= n; guard++) {
    ring.push(h);
    const t = m.heTwin[m.hePrev[h]];
    if (t < 0 || t === start) break;
    h = t;
  }
  if (ring.length !== n) return null;
  return { he: ring, boundary };
}

/** Per-corner classification used by the GPU path. */
export const enum FaceKind {
  /** Quad whose 16-point neighbourhood is a regular bicubic B-spline patch. */
  Regular = 0,
  /** Quad touching an irregular vertex (extraordinary, dart, corner, crease end, boundary EV...). */
  QuadIrregular = 1,
  /** Quad sharing a vertex with a non-quad face. */
  QuadNextToNonQuad = 2,
  /** Triangle or n-gon. */
  NonQuad = 3,
}

export const FACE_FLAG_CREASED = 1; // some corner has a sharp (non-boundary) edge or vertex sharpness
export const FACE_FLAG_SEMISHARP = 2; // some corner has a semi-sharp edge or vertex
export const FACE_FLAG_BOUNDARY = 4; // touches the mesh boundary
export const FACE_FLAG_HOLE = 8; // no limit surface

export interface Topology extends HalfEdges {
  /** Boundary vertex (has a boundary edge). */
  vertBoundary: Uint8Array;
  /** Number of incident edges. */
  valence: Int32Array;
  /** Leading outgoing half-edge of each vertex's ring (-1 for unused vertices). */
  vertRingStart: Int32Array;
}

/**
 * Validate cage topology and build adjacency. Throws `CageError` naming the face
 * lines for non-manifold edges/vertices and inconsistent winding, and the tag
 * line for creases that are not edges.
 */
export function buildTopology(cage: Cage): Topology {
  const nVerts = cage.positions.length / 3;
  const { he, problems } = buildHalfEdges(nVerts, cage.faceOffsets, cage.faceIndices);
  const issues: CageIssue[] = [];
  const fl = (f: number): number => cage.faceLines[f] ?? 0;
  for (const p of problems) {
    const a = he.edgeVerts[2 * p.edge],
      b = he.edgeVerts[2 * p.edge + 1];
    const faceList =
      p.faces
        .slice(0, 4)
        .map((f) => `face ${f + 1}${fl(f) ? ` (line ${fl(f)})` : ''}`)
        .join(', ') + (p.faces.length > 4 ? `, ... (${p.faces.length - 4} more)` : '');
    if (p.kind === 'non-manifold-edge') {
      issues.push({
        line: fl(p.faces[p.faces.length - 1]),
        message: `non-manifold edge ${a + 1}-${b + 1}: shared by ${p.faces.length} faces: ${faceList}`,
      });
    } else {
      issues.push({
        line: fl(p.faces[1]),
        message: `inconsistent winding: edge ${a + 1}-${b + 1} is used in the same direction by ${faceList} (flip one of them)`,
      });
    }
  }
  const vertRingStart = new Int32Array(nVerts).fill(-1);
  const vertBoundary = new Uint8Array(nVerts);
  const valence = new Int32Array(nVerts);
  const badEdgeVerts = new Set<number>();
  for (const p of problems) {
    badEdgeVerts.add(he.edgeVerts[2 * p.edge]);
    badEdgeVerts.add(he.edgeVerts[2 * p.edge + 1]);
  }
  for (let v = 0; v < nVerts; v++) {
    valence[v] = he.vertEdgeOffsets[v + 1] - he.vertEdgeOffsets[v];
    for (let k = he.vertEdgeOffsets[v]; k < he.vertEdgeOffsets[v + 1]; k++)
      if (he.edgeFaceCount[he.vertEdges[k]] === 1) vertBoundary[v] = 1;
    if (he.vertHeOffsets[v + 1] === he.vertHeOffsets[v]) continue;
    if (badEdgeVerts.has(v)) continue;
    const ring = vertexRing(he, v);
    if (!ring) {
      const f = he.heFace[he.vertHe[he.vertHeOffsets[v]]];
      issues.push({
        line: cage.vertexLines[v] ?? 0,
        message: `non-manifold vertex ${v + 1}: its faces (e.g. face ${f + 1}${fl(f) ? ` on line ${fl(f)}` : ''}) do not form a single fan`,
      });
    } else vertRingStart[v] = ring.he[0];
  }
  // Creases must be edges.
  const edgeOf = (a: number, b: number): number => {
    for (let k = he.vertEdgeOffsets[a]; k < he.vertEdgeOffsets[a + 1]; k++) {
      const e = he.vertEdges[k];
      if (he.edgeVerts[2 * e] + he.edgeVerts[2 * e + 1] - a === b) return e;
    }
    return -1;
  };
  for (const c of cage.creases) {
    if (c.v0 < nVerts && c.v1 < nVerts && edgeOf(c.v0, c.v1) < 0) {
      issues.push({ line: c.line, message: `crease ${c.v0} ${c.v1} (0-based) is not an edge of any face` });
    }
  }
  if (issues.length) {
    issues.sort((x, y) => x.line - y.line);
    throw new CageError(issues);
  }
  return { ...he, vertBoundary, valence, vertRingStart };
}

/** Whether the cage is closed: every edge has two faces and no face is a hole (a drawn
 * surface with no boundary, whose back faces are never seen from outside). */
export function isClosed(cage: Cage, topo: HalfEdges): boolean {
  if (cage.holes.length) return false;
  for (let e = 0; e < topo.edgeFaceCount.length; e++) if (topo.edgeFaceCount[e] !== 2) return false;
  return topo.edgeFaceCount.length > 0;
}

/** Find the edge joining a and b, or -1. */
export function findEdge(m: HalfEdges, a: number, b: number): number {
  for (let k = m.vertEdgeOffsets[a]; k < m.vertEdgeOffsets[a + 1]; k++) {
    const e = m.vertEdges[k];
    if (m.edgeVerts[2 * e] + m.edgeVerts[2 * e + 1] - a === b) return e;
  }
  return -1;
}

/** Sharpness and holes after applying the boundary rules (OpenSubdiv's Far factory semantics). */
export interface Sharpness {
  edge: Float64Array;
  vertex: Float64Array;
  hole: Uint8Array;
}

export function computeSharpness(cage: Cage, topo: Topology, options: SubdivOptions = DEFAULT_OPTIONS): Sharpness {
  const edge = new Float64Array(topo.nEdges);
  const vertex = new Float64Array(topo.nVerts);
  const hole = new Uint8Array(topo.nFaces);
  const explicitInf = new Uint8Array(topo.nEdges);
  for (const c of cage.creases) {
    const e = findEdge(topo, c.v0, c.v1);
    if (e >= 0) {
      edge[e] = c.sharpness;
      explicitInf[e] = c.sharpness >= SHARPNESS_INFINITE ? 1 : 0;
    }
  }
  for (const c of cage.corners) vertex[c.v] = c.sharpness;
  for (const f of cage.holes) hole[f] = 1;
  for (let e = 0; e < topo.nEdges; e++) if (topo.edgeFaceCount[e] === 1) edge[e] = SHARPNESS_INFINITE;
  const exempt = new Set(cage.cornerExempt ?? []);
  for (let v = 0; v < topo.nVerts; v++) {
    if (!topo.vertBoundary[v]) continue;
    const nf = topo.vertHeOffsets[v + 1] - topo.vertHeOffsets[v];
    if (options.boundary === 'edge-and-corner' && nf === 1 && !exempt.has(v)) vertex[v] = SHARPNESS_INFINITE;
    if (options.boundary === 'none') {
      let unsharpBoundary = false;
      for (let k = topo.vertEdgeOffsets[v]; k < topo.vertEdgeOffsets[v + 1]; k++) {
        const e = topo.vertEdges[k];
        if (topo.edgeFaceCount[e] === 1 && !explicitInf[e]) unsharpBoundary = true;
      }
      if (unsharpBoundary) for (let k = topo.vertHeOffsets[v]; k < topo.vertHeOffsets[v + 1]; k++) hole[topo.heFace[topo.vertHe[k]]] = 1;
    }
  }
  return { edge, vertex, hole };
}

export const isInf = (s: number): boolean => s >= SHARPNESS_INFINITE;
export const isSemi = (s: number): boolean => s > 0 && s < SHARPNESS_INFINITE;

/** OpenSubdiv's decrementSharpness (f32). */
export function decSharp(s: number): number {
  if (!(s > 0)) return 0;
  if (s >= SHARPNESS_INFINITE) return SHARPNESS_INFINITE;
  if (s > 1) return Math.fround(s - 1);
  return 0;
}

/**
 * Child sharpness of every edge incident to v, at v (uniform or Chaikin: OpenSubdiv's Sdc
 * Crease::SubdivideEdgeSharpnessesAroundVertex). `parent` holds the edges' sharpness in the
 * vertex's edge order; under Chaikin a semi-sharp edge's child averages it with the other
 * semi-sharp edges at v (3/4 and 1/4) before the decrement.
 */
export function childEdgeSharpAtVertex(parent: number[], chaikin: boolean, out: number[]): void {
  out.length = parent.length;
  if (!chaikin || parent.length < 2) {
    for (let i = 0; i < parent.length; i++) out[i] = decSharp(parent[i]);
    return;
  }
  let sum = 0,
    count = 0;
  for (const s of parent)
    if (isSemi(s)) {
      count++;
      sum = Math.fround(sum + s);
    }
  for (let i = 0; i < parent.length; i++) {
    const p = parent[i];
    if (count === 0) out[i] = p;
    else if (!(p > 0)) out[i] = 0;
    else if (isInf(p)) out[i] = SHARPNESS_INFINITE;
    else if (count === 1) out[i] = decSharp(p);
    else {
      const avg = Math.fround(Math.fround(sum - p) / (count - 1));
      const c = Math.fround(Math.fround(Math.fround(0.75 * p) + Math.fround(0.25 * avg)) - 1);
      out[i] = Math.max(c, 0);
    }
  }
}

/** Is vertex v a regular corner of a B-spline patch (OpenSubdiv's isRegular test)? */
export function isRegularVertex(
  m: HalfEdges,
  v: number,
  edgeSharp: ArrayLike<number>,
  vertSharp: ArrayLike<number>,
  boundary: boolean,
): boolean {
  const nf = m.vertHeOffsets[v + 1] - m.vertHeOffsets[v];
  const a = m.vertEdgeOffsets[v],
    b = m.vertEdgeOffsets[v + 1];
  const ne = b - a;
  const vs = vertSharp[v];
  for (let k = m.vertHeOffsets[v]; k < m.vertHeOffsets[v + 1]; k++) {
    const f = m.heFace[m.vertHe[k]];
    if (m.faceOffsets[f + 1] - m.faceOffsets[f] !== 4) return false;
  }
  let inf = 0;
  for (let k = a; k < b; k++) {
    const s = edgeSharp[m.vertEdges[k]];
    if (s > 0 && s < SHARPNESS_INFINITE) return false;
    if (s >= SHARPNESS_INFINITE) inf++;
  }
  if (vs > 0 && vs < SHARPNESS_INFINITE) return false;
  if (boundary) {
    if (nf === 2 && ne === 3) return inf === 2 && vs === 0;
    if (nf === 1 && ne === 2) return vs >= SHARPNESS_INFINITE;
    return false;
  }
  if (nf !== 4 || ne !== 4) return false;
  if (vs > 0) return false;
  if (inf === 0 || inf === 4) return true;
  if (inf !== 2) return false;
  // The two sharp edges must be opposite: walk the ring.
  const ring = vertexRing(m, v);
  if (!ring) return false;
  const s0 = edgeSharp[m.heEdge[ring.he[0]]] > 0,
    s1 = edgeSharp[m.heEdge[ring.he[1]]] > 0;
  const s2 = edgeSharp[m.heEdge[ring.he[2]]] > 0;
  return (s0 && s2) || (s1 && !s0 && !s2);
}

export interface Classification {
  faceKind: Uint8Array;
  faceFlags: Uint8Array;
  /** 1 where a vertex is a regular patch corner (see isRegularVertex). */
  vertexRegular: Uint8Array;
  /** 1 for interior vertices of valence != 4 and boundary vertices with != 2 faces. */
  vertexExtraordinary: Uint8Array;
}

/** Classify faces for the GPU path (regular / quad near an irregular vertex / quad near a non-quad / non-quad). */
export function classify(topo: Topology, sharp: Sharpness): Classification {
  const nv = topo.nVerts,
    nf = topo.nFaces;
  const vertexRegular = new Uint8Array(nv);
  const vertexExtraordinary = new Uint8Array(nv);
  const nearNonQuad = new Uint8Array(nv);
  const creasedV = new Uint8Array(nv);
  for (let f = 0; f < nf; f++) {
    if (topo.faceOffsets[f + 1] - topo.faceOffsets[f] !== 4) {
      for (let h = topo.faceOffsets[f]; h < topo.faceOffsets[f + 1]; h++) nearNonQuad[topo.faceIndices[h]] = 1;
    }
  }
  for (let v = 0; v < nv; v++) {
    const nfv = topo.vertHeOffsets[v + 1] - topo.vertHeOffsets[v];
    const b = !!topo.vertBoundary[v];
    vertexRegular[v] = isRegularVertex(topo, v, sharp.edge, sharp.vertex, b) ? 1 : 0;
    vertexExtraordinary[v] = nfv > 0 && (b ? nfv !== 2 : nfv !== 4) ? 1 : 0;
    let flags = 0;
    if (sharp.vertex[v] > 0 && !(b && nfv === 1)) flags |= FACE_FLAG_CREASED;
    if (sharp.vertex[v] > 0 && sharp.vertex[v] < SHARPNESS_INFINITE) flags |= FACE_FLAG_SEMISHARP;
    for (let k = topo.vertEdgeOffsets[v]; k < topo.vertEdgeOffsets[v + 1]; k++) {
      const e = topo.vertEdges[k];
      const s = sharp.edge[e];
      if (s > 0 && topo.edgeFaceCount[e] === 2) flags |= FACE_FLAG_CREASED;
      if (s > 0 && s < SHARPNESS_INFINITE) flags |= FACE_FLAG_SEMISHARP;
    }
    if (b) flags |= FACE_FLAG_BOUNDARY;
    creasedV[v] = flags;
  }
  const faceKind = new Uint8Array(nf);
  const faceFlags = new Uint8Array(nf);
  for (let f = 0; f < nf; f++) {
    const a = topo.faceOffsets[f],
      b = topo.faceOffsets[f + 1];
    let flags = sharp.hole[f] ? FACE_FLAG_HOLE : 0;
    let allReg = true,
      nearNQ = false;
    for (let h = a; h < b; h++) {
      const v = topo.faceIndices[h];
      flags |= creasedV[v];
      if (!vertexRegular[v]) allReg = false;
      if (nearNonQuad[v]) nearNQ = true;
    }
    faceFlags[f] = flags;
    faceKind[f] = b - a !== 4 ? FaceKind.NonQuad : nearNQ ? FaceKind.QuadNextToNonQuad : allReg ? FaceKind.Regular : FaceKind.QuadIrregular;
  }
  return { faceKind, faceFlags, vertexRegular, vertexExtraordinary };
}

/**
 * Vertex → outgoing half-edges and vertex → edges, as offset tables (CSR): half-edge h leaves
 * faceIndices[h]; edge e joins edgeVerts[2e] and edgeVerts[2e + 1]. Shared by the cage's topology
 * and the refined levels of src/gpu/cc/build.ts.
 */
export function vertexAdjacency(
  nVerts: number,
  faceIndices: ArrayLike<number>,
  edgeVerts: ArrayLike<number>,
): { vertHeOffsets: Int32Array; vertHe: Int32Array; vertEdgeOffsets: Int32Array; vertEdges: Int32Array } {
  const nHe = faceIndices.length,
    nEdges = edgeVerts.length / 2;
  const vertHeOffsets = new Int32Array(nVerts + 1);
  for (let h = 0; h < nHe; h++) vertHeOffsets[faceIndices[h] + 1]++;
  for (let v = 0; v < nVerts; v++) vertHeOffsets[v + 1] += vertHeOffsets[v];
  const vertHe = new Int32Array(nHe);
  const fill = vertHeOffsets.slice(0, nVerts);
  for (let h = 0; h < nHe; h++) vertHe[fill[faceIndices[h]]++] = h;
  const vertEdgeOffsets = new Int32Array(nVerts + 1);
  for (let e = 0; e < nEdges; e++) {
    vertEdgeOffsets[edgeVerts[2 * e] + 1]++;
    vertEdgeOffsets[edgeVerts[2 * e + 1] + 1]++;
  }
  for (let v = 0; v < nVerts; v++) vertEdgeOffsets[v + 1] += vertEdgeOffsets[v];
  const vertEdges = new Int32Array(2 * nEdges);
  const fill2 = vertEdgeOffsets.slice(0, nVerts);
  for (let e = 0; e < nEdges; e++) {
    vertEdges[fill2[edgeVerts[2 * e]]++] = e;
    vertEdges[fill2[edgeVerts[2 * e + 1]]++] = e;
  }
  return { vertHeOffsets, vertHe, vertEdgeOffsets, vertEdges };
}
