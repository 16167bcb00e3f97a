export * from './types.ts';
export * from './errors.ts';
export * from './obj.ts';
export * from './topology.ts';
export * from './uv.ts';
// Runtime-agnostic height maps; the Node PNG decoder (heightmap-png.ts, pngjs) is NOT re-exported, so the browser build never pulls it.
export * from './heightmap.ts';
export * from './range.ts';
export * from './text.ts';
export * from './up-axis.ts';
export * from './manifold.ts';
import { CageError, type CageIssue } from './errors.ts';
import { parseObj } from './obj.ts';
import { coordinateIssues, faceSizeIssues, zeroAreaFaces } from './range.ts';
import { buildTopology, type Topology } from './topology.ts';
import { repeatedVertices, splitNonManifold } from './manifold.ts';
import type { Cage } from './types.ts';
import { uvCoverage } from './uv.ts';

export interface LoadedCage {
  cage: Cage;
  topology: Topology;
  warnings: CageIssue[];
}

/**
 * Parse and validate an OBJ cage. Throws `CageError` (with line numbers) for any malformed or
 * degenerate input; never throws anything else. Non-manifold vertices and edges are split apart
 * (src/mesh/manifold.ts), with a warning each.
 */
export function loadCage(text: string): LoadedCage {
  try {
    const parsed = parseObj(text);
    const warnings = parsed.warnings;
    const range = [...faceSizeIssues(parsed.cage), ...coordinateIssues(parsed.cage)];
    if (range.length) throw new CageError(range);
    // Non-manifold vertices and edges are kept as OpenSubdiv keeps them (sharp), split so that each
    // fan and each face side stands alone (src/mesh/manifold.ts); the warnings say where. Only a
    // cage that needs it pays for the split (a face repeating a vertex, or a topology refused):
    // a manifold cage of a million faces is read as fast as before.
    let cage = parsed.cage;
    let topology: Topology;
    const split = (): void => {
      const r = splitNonManifold(cage);
      cage = r.cage;
      warnings.push(...r.warnings);
    };
    if (repeatedVertices(cage).size) split();
    try {
      topology = buildTopology(cage);
    } catch (e) {
      const before = cage;
      if (!(e instanceof CageError)) throw e;
      split();
      if (cage === before) throw e;
      topology = buildTopology(cage);
    }
    const flat = zeroAreaFaces(cage);
    if (flat.length)
      warnings.push({
        line: cage.faceLines[flat[0]] ?? 0,
        message: `${flat.length === 1 ? 'face' : `${flat.length} faces (the first:`} ${flat[0] + 1}${flat.length === 1 ? ' has' : ') have'} zero area: their normals are undefined`,
      });
    let unused = 0;
    for (let v = 0; v < topology.nVerts; v++) if (topology.vertHeOffsets[v + 1] === topology.vertHeOffsets[v]) unused++;
    if (unused) warnings.push({ line: 0, message: `${unused} vertices are not used by any face (ignored)` });
    // Face-varying UVs are all-or-nothing for interpolation (uv.ts): say where they stop.
    if (uvCoverage(cage) === 'partial') {
      let f = 0;
      for (; f < topology.nFaces; f++) {
        let miss = false;
        for (let h = cage.faceOffsets[f]; h < cage.faceOffsets[f + 1]; h++) if (cage.faceUvIndices[h] < 0) miss = true;
        if (miss) break;
      }
      warnings.push({
        line: cage.faceLines[f] ?? 0,
        message: `face ${f + 1} (and maybe others) lacks texture coordinates on some corners: the UVs are kept but cannot be used for displacement`,
      });
    }
    return { cage, topology, warnings };
  } catch (e) {
    if (e instanceof CageError) throw e;
    // Defensive: an internal failure is still reported as a cage error, not a crash.
    throw new CageError([{ line: 0, message: `internal error while reading cage: ${(e as Error)?.message ?? String(e)}` }]);
  }
}
