/**
 * Non-manifold cages as OpenSubdiv takes them, made manifold by splitting: every surface here
 * (and the half-edge topology under them) needs each vertex's faces to form one fan and each edge
 * to join at most two faces that run along it in opposite directions. OpenSubdiv (Far's topology
 * refiner) keeps such cages and makes their features sharp:
 *   - an edge with more than two faces, or two faces along it in the same direction, is
 *     infinitely sharp (so each face's side of it follows the edge's crease curve, B-spline of the
 *     edge's own points, and nothing across it);
 *   - a non-manifold vertex (its faces form several fans, or it has a non-manifold edge) is
 *     infinitely sharp (a corner), except on a non-manifold crease: exactly two non-manifold edges,
 *     no boundary edge and more faces than edges (a fin along a line), where the crease rule runs
 *     along the two edges.
 * Under those rules nothing crosses a non-manifold edge or vertex: each fan's surface depends on
 * its own faces and on the crease curves it shares, which depend only on the points along them.
 * So splitting gives the same limit surface: each fan of a vertex becomes its own vertex (copies
 * at one position; the first keeps the number), a non-manifold edge becomes one boundary edge per
 * face side (boundaries are infinitely sharp already), and the vertices OpenSubdiv sharpens get a
 * corner tag on every copy. Crease and corner tags on split vertices follow to every copy.
 *
 * Data: fans are found with a union-find over face corners (corner h = position h of faceIndices):
 * two corners at a vertex are in one fan when they share a manifold edge (exactly two half-edges,
 * opposite directions). Linear in the cage.
 */
import { CageError, type CageIssue } from './errors.ts';
import { SHARPNESS_INFINITE, type Cage, type CornerTag, type CreaseTag } from './types.ts';

export interface ManifoldSplit {
  /** The cage itself when it is manifold; else the split cage (same faces, in the same order). */
  cage: Cage;
  /** What was changed, for the loader's warnings. */
  warnings: CageIssue[];
  /** The cage vertex each vertex of the split cage stands for. */
  vertexOrigin: Int32Array;
}

/** Split the non-manifold vertices and edges of a cage (see the header). A face that repeats a
 * vertex has its corners there split apart when they are in different fans (a zero-length edge,
 * a face pinched at a vertex whose edges there are non-manifold); where they are one fan, the
 * face folds onto itself and is refused (CageError naming its line). */
export function splitNonManifold(cage: Cage): ManifoldSplit {
  const nv = cage.positions.length / 3;
  const nf = cage.faceOffsets.length - 1;
  const idx = cage.faceIndices;
  const nc = idx.length;
  const faceOf = new Int32Array(nc);
  const next = new Int32Array(nc);
  for (let f = 0; f < nf; f++) {
    const a = cage.faceOffsets[f],
      b = cage.faceOffsets[f + 1];
    for (let h = a; h < b; h++) {
      faceOf[h] = f;
      next[h] = h + 1 < b ? h + 1 : a;
    }
  }
  // Half-edges h (from idx[h] to idx[next[h]]) by undirected edge.
  const byEdge = new Map<number, number[]>();
  const key = (a: number, b: number) => (a < b ? a * nv + b : b * nv + a);
  for (let h = 0; h < nc; h++) {
    const k = key(idx[h], idx[next[h]]);
    const list = byEdge.get(k);
    if (list) list.push(h);
    else byEdge.set(k, [h]);
  }
  const parent = Int32Array.from({ length: nc }, (_, i) => i);
  const find = (x: number): number => {
    while (parent[x] !== x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  const union = (x: number, y: number) => {
    const a = find(x),
      b = find(y);
    if (a !== b) parent[Math.max(a, b)] = Math.min(a, b);
  };
  const nonManifoldEdges: number[][] = [];
  const zeroLength: number[] = [];
  for (const list of byEdge.values()) {
    // A zero-length edge (a vertex repeated in a row): OpenSubdiv's degenerate edge, non-manifold.
    if (idx[list[0]] === idx[next[list[0]]]) {
      zeroLength.push(...list);
      continue;
    }
    const manifold = list.length === 2 && idx[list[0]] === idx[next[list[1]]];
    if (list.length === 1) continue;
    if (!manifold) {
      nonManifoldEdges.push(list);
      continue;
    }
    const [h1, h2] = list;
    union(h1, next[h2]); // at idx[h1]
    union(next[h1], h2); // at idx[h2]
  }
  // Fans per vertex: the distinct roots of its corners, in corner order.
  const fanRoots: number[][] = Array.from({ length: nv }, () => []);
  for (let h = 0; h < nc; h++) {
    const r = find(h);
    const roots = fanRoots[idx[h]];
    if (!roots.includes(r)) roots.push(r);
  }
  const nmEdgeCount = new Int32Array(nv);
  for (const list of nonManifoldEdges) {
    nmEdgeCount[idx[list[0]]]++;
    nmEdgeCount[idx[next[list[0]]]]++;
  }
  // A vertex's zero-length edges are one edge (its pair (v, v)), however many faces have one.
  for (const v of new Set(zeroLength.map((h) => idx[h]))) nmEdgeCount[v]++;
  // A face whose corners at one vertex are in one fan folds onto itself there.
  const issues: CageIssue[] = [];
  for (let f = 0; f < nf; f++) {
    const roots = new Set<number>();
    for (let h = cage.faceOffsets[f]; h < cage.faceOffsets[f + 1]; h++) {
      const r = find(h);
      if (roots.has(r)) {
        issues.push({ line: cage.faceLines[f] ?? 0, message: `degenerate face: vertex ${idx[h] + 1} appears more than once` });
        break;
      }
      roots.add(r);
    }
  }
  if (issues.length) throw new CageError(issues);
  let split = nonManifoldEdges.length > 0 || zeroLength.length > 0;
  for (let v = 0; v < nv && !split; v++) if (fanRoots[v].length > 1) split = true;
  if (!split) return { cage, warnings: [], vertexOrigin: Int32Array.from({ length: nv }, (_, i) => i) };

  // Copies: fan 0 of v keeps v; the others are appended.
  const copyOfRoot = new Map<number, number>();
  const origin: number[] = Array.from({ length: nv }, (_, i) => i);
  for (let v = 0; v < nv; v++)
    fanRoots[v].forEach((r, i) => {
      if (i === 0) copyOfRoot.set(r, v);
      else {
        copyOfRoot.set(r, origin.length);
        origin.push(v);
      }
    });
  const faceIndices = new Int32Array(nc);
  for (let h = 0; h < nc; h++) faceIndices[h] = copyOfRoot.get(find(h)) as number;
  const copies = (v: number): number[] => fanRoots[v].map((r) => copyOfRoot.get(r) as number);

  // The vertices OpenSubdiv sharpens (Far's base tagging): non-manifold ones, but for a crease of
  // two non-manifold edges with no boundary edge and more faces than edges.
  const warnings: CageIssue[] = [];
  const corners: CornerTag[] = [];
  const exempt: number[] = [];
  const cornerAt = new Map<number, CornerTag>();
  for (const c of cage.corners) for (const v of copies(c.v)) cornerAt.set(v, { ...c, v });
  // Distinct edges and boundary edges per vertex (byEdge holds each edge once; a zero-length one
  // is one edge of its vertex).
  const edgesAt = new Int32Array(nv);
  const boundaryEdges = new Int32Array(nv);
  for (const list of byEdge.values()) {
    const a = idx[list[0]],
      b = idx[next[list[0]]];
    edgesAt[a]++;
    if (b !== a) edgesAt[b]++;
    if (list.length === 1) {
      boundaryEdges[a]++;
      boundaryEdges[b]++;
    }
  }
  const facesAt = new Int32Array(nv);
  for (let h = 0; h < nc; h++) facesAt[idx[h]]++;
  // Vertices some face repeats (a zero-length edge, a pinched face): always sharpened (measured
  // against OpenSubdiv 3.5 on its catmark_nonman_edges cage).
  const repeated = repeatedVertices(cage);
  for (let v = 0; v < nv; v++) {
    const fans = fanRoots[v].length;
    if (fans <= 1 && nmEdgeCount[v] === 0) continue;
    const edges = edgesAt[v];
    const nmCrease = nmEdgeCount[v] === 2 && boundaryEdges[v] === 0 && facesAt[v] > edges && !repeated.has(v);
    if (!nmCrease) for (const c of copies(v)) cornerAt.set(c, { v: c, sharpness: SHARPNESS_INFINITE, line: cage.vertexLines[v] ?? 0 });
    // A copy with one face (a fan of one face between the two edges) would be sharpened by the
    // edge-and-corner rule; OpenSubdiv's vertex is a crease.
    else exempt.push(...copies(v));
    if (fans > 1)
      warnings.push({
        line: cage.vertexLines[v] ?? 0,
        message: `non-manifold vertex ${v + 1}: its faces form ${fans} fans, kept as ${fans} vertices at one position (${nmCrease ? 'a crease along its non-manifold edges' : 'infinitely sharp'}, as OpenSubdiv makes it)`,
      });
  }
  for (const list of nonManifoldEdges) {
    const a = idx[list[0]],
      b = idx[next[list[0]]];
    const faces = list.map((h) => faceOf[h]);
    const same = list.length === 2;
    warnings.push({
      line: cage.faceLines[faces[faces.length - 1]] ?? 0,
      message: same
        ? `edge ${a + 1}-${b + 1} runs the same way in faces ${faces[0] + 1} and ${faces[1] + 1} (inconsistent winding): kept apart as an infinitely sharp edge, as OpenSubdiv does (flip one face to join them)`
        : `non-manifold edge ${a + 1}-${b + 1}: shared by ${list.length} faces, each kept with its own side of it (infinitely sharp, as OpenSubdiv makes it)`,
    });
  }
  corners.push(...cornerAt.values());
  corners.sort((x, y) => x.v - y.v);
  // Crease tags: onto every edge of the split cage between copies of their two vertices; and every
  // edge a non-manifold edge becomes is infinitely sharp (most are boundaries, but two of its faces
  // that are joined elsewhere, e.g. glued back to back, meet across it again in the split cage).
  const creases: CreaseTag[] = [];
  const n2 = origin.length;
  const tagged = new Set<number>();
  const tag = (list: readonly number[], c: CreaseTag) => {
    for (const h of list) {
      const a = faceIndices[h],
        b = faceIndices[next[h]];
      const k = a < b ? a * n2 + b : b * n2 + a;
      if (tagged.has(k)) continue;
      tagged.add(k);
      creases.push({ ...c, v0: a, v1: b });
    }
  };
  for (const list of nonManifoldEdges)
    tag(list, { v0: 0, v1: 0, sharpness: SHARPNESS_INFINITE, line: cage.faceLines[faceOf[list[0]]] ?? 0 });
  for (const h of zeroLength) tag([h], { v0: 0, v1: 0, sharpness: SHARPNESS_INFINITE, line: cage.faceLines[faceOf[h]] ?? 0 });
  if (zeroLength.length) {
    const f = faceOf[zeroLength[0]];
    warnings.push({
      line: cage.faceLines[f] ?? 0,
      message: `${zeroLength.length === 1 ? 'face' : `${zeroLength.length} faces (the first:`} ${f + 1}${zeroLength.length === 1 ? '' : ')'} repeat${zeroLength.length === 1 ? 's' : ''} a vertex in a row: a zero-length edge, kept infinitely sharp, its vertex split per fan (as OpenSubdiv does)`,
    });
  }
  for (const c of cage.creases) tag(byEdge.get(key(c.v0, c.v1)) ?? [], c);
  const positions = new Float64Array(3 * origin.length);
  const vertexLines = new Int32Array(origin.length);
  origin.forEach((v, i) => {
    positions[3 * i] = cage.positions[3 * v];
    positions[3 * i + 1] = cage.positions[3 * v + 1];
    positions[3 * i + 2] = cage.positions[3 * v + 2];
    vertexLines[i] = cage.vertexLines[v] ?? 0;
  });
  warnings.sort((x, y) => x.line - y.line);
  return {
    cage: { ...cage, positions, faceIndices, creases, corners, vertexLines, ...(exempt.length ? { cornerExempt: exempt } : {}) },
    warnings,
    vertexOrigin: Int32Array.from(origin),
  };
}

/** The vertices some face names twice (none in a common cage; no allocation per face: the loader
 * asks this of every cage before deciding whether to split it). */
export function repeatedVertices(cage: Cage): Set<number> {
  const idx = cage.faceIndices;
  const out = new Set<number>();
  for (let f = 0; f + 1 < cage.faceOffsets.length; f++) {
    const a = cage.faceOffsets[f],
      b = cage.faceOffsets[f + 1];
    for (let i = a; i < b; i++) for (let j = i + 1; j < b; j++) if (idx[i] === idx[j]) out.add(idx[i]);
  }
  return out;
}
