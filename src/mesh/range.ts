// Which coordinates a cage may have. Every path ends on the GPU in 32-bit floats, so a cage the
// CPU reads exactly (in f64) can still become NaN or a point there: refused here, with the lines,
// rather than drawn or written as NaN. The policy is to refuse, not to recentre and rescale: a
// rescaled output would be in other units than the cage, silently.
import type { CageIssue } from './errors.ts';
import type { Cage } from './types.ts';

/** The largest coordinate magnitude taken. f32 ends at 3.4e38 and the pipeline squares lengths
 * and multiplies three of them (cross products of edges, projected areas): 1e12 keeps those
 * products (1e36) finite. */
export const MAX_COORDINATE = 1e12;
/** The smallest extent taken: its cube (1e-36) stays above f32's smallest normal (1.2e-38). */
export const MIN_EXTENT = 1e-12;
/** f32 has a 24-bit significand: a model smaller than 2^-16 of its distance from the origin keeps
 * under 256 distinct values per axis, its faces fold and its normals turn to noise. */
export const MIN_RELATIVE_EXTENT = 2 ** -16;

const SHOWN = 8;

/** Problems with the cage's coordinates (empty when it is fine); each names its line. */
export function coordinateIssues(cage: Cage): CageIssue[] {
  const issues: CageIssue[] = [];
  const P = cage.positions;
  const nv = P.length / 3;
  const line = (v: number) => cage.vertexLines[v] ?? 0;
  let huge = 0;
  for (let v = 0; v < nv; v++) {
    for (let a = 0; a < 3; a++) {
      const x = P[3 * v + a];
      if (Math.abs(x) > MAX_COORDINATE) {
        if (huge++ < SHOWN)
          issues.push({
            line: line(v),
            message: `vertex ${v + 1}: coordinate ${x} is beyond ±${MAX_COORDINATE.toExponential().replace('+', '')}, more than the GPU's 32-bit arithmetic holds: scale the model down`,
          });
        break;
      }
    }
  }
  if (huge > SHOWN)
    issues.push({ line: 0, message: `... ${huge - SHOWN} more vertices beyond ±${MAX_COORDINATE.toExponential().replace('+', '')}` });
  if (huge) return issues;
  // Extent and distance from the origin over the vertices the faces use (unused ones are dropped).
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  let far = 0;
  let first = -1;
  for (const v of cage.faceIndices) {
    if (first < 0) first = v;
    for (let a = 0; a < 3; a++) {
      const x = P[3 * v + a];
      if (x < lo[a]) lo[a] = x;
      if (x > hi[a]) hi[a] = x;
      far = Math.max(far, Math.abs(x));
    }
  }
  if (first < 0) return issues;
  const extent = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  if (extent < MIN_EXTENT)
    issues.push({
      line: line(first),
      message: `the model spans only ${extent.toPrecision(3)}, below ${MIN_EXTENT}: in the GPU's 32-bit arithmetic its vertices collapse to a point: scale the model up`,
    });
  else if (extent < far * MIN_RELATIVE_EXTENT)
    issues.push({
      line: line(first),
      message: `the model spans ${extent.toPrecision(3)} but lies ${far.toPrecision(3)} from the origin: in the GPU's 32-bit floats its vertices merge: move it near the origin`,
    });
  return issues;
}

/** Faces of zero area (all corners on one line or point): their normals are undefined. */
export function zeroAreaFaces(cage: Cage): number[] {
  const P = cage.positions;
  const out: number[] = [];
  const nf = cage.faceOffsets.length - 1;
  let lo = Infinity;
  let hi = -Infinity;
  for (const x of P) {
    if (x < lo) lo = x;
    if (x > hi) hi = x;
  }
  // Relative to the model's size: twice the area in units of its extent squared.
  const tiny = (hi - lo) ** 2 * 1e-14;
  for (let f = 0; f < nf; f++) {
    // Newell's normal: twice the vector area of a planar or non-planar polygon.
    let nx = 0;
    let ny = 0;
    let nz = 0;
    const a = cage.faceOffsets[f];
    const b = cage.faceOffsets[f + 1];
    for (let h = a; h < b; h++) {
      const p = 3 * cage.faceIndices[h];
      const q = 3 * cage.faceIndices[h + 1 < b ? h + 1 : a];
      nx += (P[p + 1] - P[q + 1]) * (P[p + 2] + P[q + 2]);
      ny += (P[p + 2] - P[q + 2]) * (P[p] + P[q]);
      nz += (P[p] - P[q]) * (P[p + 1] + P[q + 1]);
    }
    if (Math.hypot(nx, ny, nz) <= tiny) out.push(f);
  }
  return out;
}

/** The most corners a face may have. The CPU reference's time grows with the square of a face's
 * size (each of its n sub-faces is refined with the whole fan round its centre, 5 s for a
 * 1,500-gon) and the GPU Catmull-Clark build packs a face's size in 12 bits; OpenSubdiv stops at
 * 65,535. A face this large is better split by the modeller. */
export const MAX_FACE_CORNERS = 1024;

/** Faces with more than MAX_FACE_CORNERS corners, each with its line. */
export function faceSizeIssues(cage: Cage): CageIssue[] {
  const issues: CageIssue[] = [];
  const nf = cage.faceOffsets.length - 1;
  for (let f = 0; f < nf && issues.length < SHOWN; f++) {
    const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
    if (n > MAX_FACE_CORNERS)
      issues.push({
        line: cage.faceLines[f] ?? 0,
        message: `face ${f + 1} has ${n} corners, more than the ${MAX_FACE_CORNERS} taken: split it`,
      });
  }
  return issues;
}

/** The bounding-box diagonal of a cage's positions. */
export function cageDiagonal(positions: ArrayLike<number>): number {
  const lo = [Infinity, Infinity, Infinity],
    hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i++) {
    lo[i % 3] = Math.min(lo[i % 3], positions[i]);
    hi[i % 3] = Math.max(hi[i % 3], positions[i]);
  }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1;
}
