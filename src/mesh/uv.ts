// Face-varying texture coordinates on a cage (OBJ `vt`, `f v/vt/vn`) and their interpolation
// over the limit surface.
//
// Data layout (in the Cage, types.ts): `uvs` holds (u, v) pairs; `faceUvIndices[h]` is the uv
// index of face corner h (the same index space as `faceIndices`, i.e. half-edge h of
// topology.ts), or -1. UVs are face-varying: two faces meeting at a cage vertex may give it
// different uvs, which is a UV seam. The mesh layer never merges or splits them.
//
// Interpolation rule: OpenSubdiv's face-varying "linear all" (Sdc::Options::FVAR_LINEAR_ALL):
// the uvs are bilinear over each face's own parameter domain, with no smoothing across faces.
//  - quad (corners 0..3 at (u,v) = (0,0), (1,0), (1,1), (0,1)):
//        uv(u,v) = (1−u)(1−v)·uv0 + u(1−v)·uv1 + u·v·uv2 + (1−u)v·uv3;
//  - face with n ≠ 4 corners, sub-face k at (s,t) in the exact reference's parameterisation
//    (src/subdiv/evaluate.ts): bilinear over the sub-quad whose
//    corners are uv_k, (uv_k + uv_k+1)/2, the mean of all n corner uvs, (uv_k−1 + uv_k)/2.
//    This is exactly what bilinear subdivision of the uv channel converges to (one bilinear
//    step splits the n-gon into these quads, and bilinear refinement of a quad reproduces it).
// Along a cage edge both forms are linear between the edge's two corner uvs of that face, so a
// point on an edge has the same uv whichever parameterisation (quad or sub-face) reaches it.
import { CageError } from './errors.ts';
import type { Topology } from './topology.ts';
import type { Cage } from './types.ts';
import type { HeightMap, HeightWrap } from './heightmap.ts';

/** uv and its derivatives with respect to the face parameters (u,v) (quads) or (s,t) (sub-faces). */
export interface UvPoint {
  uv: [number, number];
  /** ∂uv/∂u (or ∂uv/∂s) and ∂uv/∂v (or ∂uv/∂t). */
  dUvdu: [number, number];
  dUvdv: [number, number];
}

/** 'none': no corner has a uv; 'complete': every corner of every face has one; 'partial': some do. */
export function uvCoverage(cage: Cage): 'none' | 'complete' | 'partial' {
  let some = false,
    all = true;
  for (let h = 0; h < cage.faceUvIndices.length; h++) {
    if (cage.faceUvIndices[h] >= 0) some = true;
    else all = false;
  }
  if (cage.faceUvIndices.length === 0) return 'none';
  return all ? 'complete' : some ? 'partial' : 'none';
}

/**
 * Throws a CageError unless every face corner has a uv, naming the first face (and its line)
 * without one: interpolation needs all four (or n) corner uvs of a face.
 */
export function requireUvs(cage: Cage): void {
  const nf = cage.faceOffsets.length - 1;
  for (let f = 0; f < nf; f++) {
    for (let h = cage.faceOffsets[f]; h < cage.faceOffsets[f + 1]; h++) {
      if (!(cage.faceUvIndices[h] >= 0)) {
        const line = cage.faceLines[f] ?? 0;
        throw new CageError([
          {
            line,
            message: `face ${f + 1}${line ? ` (line ${line})` : ''} has no texture coordinate on corner ${h - cage.faceOffsets[f] + 1}: UVs (f v/vt) are needed on every face corner for displacement`,
          },
        ]);
      }
    }
  }
}

/** The uv of corner j (0-based, within the face) of face f. */
export function cornerUv(cage: Cage, f: number, j: number): [number, number] {
  const t = cage.faceUvIndices[cage.faceOffsets[f] + j];
  if (!(t >= 0)) throw new RangeError(`face ${f} corner ${j} has no uv`);
  return [cage.uvs[2 * t], cage.uvs[2 * t + 1]];
}

function bilinear(a: number[], b: number[], c: number[], d: number[], s: number, t: number): UvPoint {
  const uv: [number, number] = [0, 0],
    du: [number, number] = [0, 0],
    dv: [number, number] = [0, 0];
  for (let i = 0; i < 2; i++) {
    uv[i] = (1 - s) * (1 - t) * a[i] + s * (1 - t) * b[i] + s * t * c[i] + (1 - s) * t * d[i];
    du[i] = (1 - t) * (b[i] - a[i]) + t * (c[i] - d[i]);
    dv[i] = (1 - s) * (d[i] - a[i]) + s * (c[i] - b[i]);
  }
  return { uv, dUvdu: du, dUvdv: dv };
}

function checkParam(s: number, t: number): void {
  if (!(s >= 0 && s <= 1 && t >= 0 && t <= 1)) throw new RangeError(`parameter (${s}, ${t}) outside [0,1]^2`);
}

/** uv on quad face f at (u,v), corners 0..3 at (0,0), (1,0), (1,1), (0,1). */
export function uvAt(cage: Cage, f: number, u: number, v: number): UvPoint {
  const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
  if (n !== 4) throw new RangeError(`face ${f} has ${n} corners: use uvAtSubFace(cage, face, k, s, t)`);
  checkParam(u, v);
  return bilinear(cornerUv(cage, f, 0), cornerUv(cage, f, 1), cornerUv(cage, f, 2), cornerUv(cage, f, 3), u, v);
}

/** uv on sub-face k of face f at (s,t); for a quad, k = 0 and (s,t) = (u,v). */
export function uvAtSubFace(cage: Cage, f: number, k: number, s: number, t: number): UvPoint {
  const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
  if (n === 4) {
    if (k !== 0) throw new RangeError(`sub-face ${k} does not exist on a quad`);
    return uvAt(cage, f, s, t);
  }
  if (!(Number.isInteger(k) && k >= 0 && k < n)) throw new RangeError(`sub-face ${k} does not exist on a face with ${n} corners`);
  checkParam(s, t);
  const c = (j: number): [number, number] => cornerUv(cage, f, ((j % n) + n) % n);
  const centre = [0, 0];
  for (let j = 0; j < n; j++) {
    const q = c(j);
    centre[0] += q[0] / n;
    centre[1] += q[1] / n;
  }
  const a = c(k),
    next = c(k + 1),
    prev = c(k - 1);
  return bilinear(a, [(a[0] + next[0]) / 2, (a[1] + next[1]) / 2], centre, [(prev[0] + a[0]) / 2, (prev[1] + a[1]) / 2], s, t);
}

/**
 * UV seams: edge e is a seam when its two faces give either of its end vertices different uvs
 * (compared by value, so two `vt` lines with equal numbers are not a seam); a vertex is a seam
 * vertex when the faces around it do not all agree on its uv. Boundary edges are not seams.
 */
export function uvSeams(cage: Cage, topo: Topology): { edge: Uint8Array; vertex: Uint8Array } {
  const edge = new Uint8Array(topo.nEdges);
  const vertex = new Uint8Array(topo.nVerts);
  const uvOf = (h: number): string => {
    const t = cage.faceUvIndices[h];
    return t >= 0 ? `${cage.uvs[2 * t]},${cage.uvs[2 * t + 1]}` : 'none';
  };
  for (let h = 0; h < topo.faceIndices.length; h++) {
    const tw = topo.heTwin[h];
    if (tw < 0) continue;
    // h runs a→b in its face; its twin runs b→a: compare a with the twin's next corner, b with the twin's own corner.
    if (uvOf(h) !== uvOf(topo.heNext[tw]) || uvOf(topo.heNext[h]) !== uvOf(tw)) edge[topo.heEdge[h]] = 1;
  }
  for (let v = 0; v < topo.nVerts; v++) {
    const a = topo.vertHeOffsets[v],
      b = topo.vertHeOffsets[v + 1];
    for (let k = a + 1; k < b; k++)
      if (uvOf(topo.vertHe[k]) !== uvOf(topo.vertHe[a])) {
        vertex[v] = 1;
        break;
      }
  }
  return { edge, vertex };
}

/**
 * Texels of a width x height map whose centres lie inside some face's uv polygon (the face's
 * uv region under linear-all interpolation: its edges are straight in uv). 'repeat' folds uvs
 * outside [0, 1] back into the map; 'clamp' ignores texels outside it. Returns a mask
 * (row-major from the top row, as heightmap.ts) and the covered count.
 */
export function uvTexelCoverage(
  cage: Cage,
  width: number,
  height: number,
  wrap: 'repeat' | 'clamp' = 'repeat',
): { mask: Uint8Array; covered: number } {
  requireUvs(cage);
  const mask = new Uint8Array(width * height);
  let covered = 0;
  const nf = cage.faceOffsets.length - 1;
  for (let f = 0; f < nf; f++) {
    const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
    // Polygon in continuous texel coordinates (x = u·W − ½, y = (1 − v)·H − ½): centres are integers.
    const px: number[] = [],
      py: number[] = [];
    for (let j = 0; j < n; j++) {
      const [u, v] = cornerUv(cage, f, j);
      px.push(u * width - 0.5);
      py.push((1 - v) * height - 0.5);
    }
    const x0 = Math.ceil(Math.min(...px)),
      x1 = Math.floor(Math.max(...px));
    const y0 = Math.ceil(Math.min(...py)),
      y1 = Math.floor(Math.max(...py));
    for (let y = y0; y <= y1; y++)
      for (let x = x0; x <= x1; x++) {
        // Even-odd crossing test (the polygons are simple; orientation does not matter).
        let inside = false;
        for (let a = 0, b = n - 1; a < n; b = a++) {
          if (py[a] > y !== py[b] > y && x < px[b] + ((y - py[b]) * (px[a] - px[b])) / (py[a] - py[b])) inside = !inside;
        }
        if (!inside) continue;
        let i = x,
          j = y;
        if (wrap === 'repeat') {
          i = ((i % width) + width) % width;
          j = ((j % height) + height) % height;
        } else if (i < 0 || i >= width || j < 0 || j >= height) continue;
        if (!mask[j * width + i]) {
          mask[j * width + i] = 1;
          covered++;
        }
      }
  }
  return { mask, covered };
}

/**
 * The uvs packed for upload (f32): two floats per face corner, at 2·(faceOffsets[f] + j) for
 * corner j of face f, so a shader that knows a face's corner offset reads its corner uvs
 * directly (no vt indirection). Throws (naming the face line) unless every corner has a uv.
 */
export function faceCornerUvs(cage: Cage): Float32Array {
  requireUvs(cage);
  const out = new Float32Array(2 * cage.faceUvIndices.length);
  for (let h = 0; h < cage.faceUvIndices.length; h++) {
    const t = cage.faceUvIndices[h];
    out[2 * h] = cage.uvs[2 * t];
    out[2 * h + 1] = cage.uvs[2 * t + 1];
  }
  return out;
}

/**
 * A conservative range of the height SAMPLE (in [0, 1]) over each face: the min and max of
 * every texel that a bilinear lookup anywhere in the face's uv bounding box can touch (the
 * interpolated value never leaves the range of its four texels). For the displacement-aware
 * factor rule and bounds: h = (sample − midLevel)·scale then lies in the mapped range.
 * Layout: [min, max] per face, at 2f and 2f + 1.
 */
export function faceSampleRange(cage: Cage, map: HeightMap, wrap: HeightWrap = 'repeat'): Float64Array {
  requireUvs(cage);
  const nf = cage.faceOffsets.length - 1;
  const out = new Float64Array(2 * nf);
  const inv = 1 / ((1 << map.bits) - 1);
  const W = map.width,
    H = map.height;
  for (let f = 0; f < nf; f++) {
    let x0 = Infinity,
      x1 = -Infinity,
      y0 = Infinity,
      y1 = -Infinity;
    for (let j = 0; j < cage.faceOffsets[f + 1] - cage.faceOffsets[f]; j++) {
      const [u, v] = cornerUv(cage, f, j);
      const x = u * W - 0.5,
        y = (1 - v) * H - 0.5;
      x0 = Math.min(x0, x);
      x1 = Math.max(x1, x);
      y0 = Math.min(y0, y);
      y1 = Math.max(y1, y);
    }
    // Texels floor(x) and floor(x) + 1 for every x in [x0, x1]; a repeat range wider than the map is all of it.
    let i0 = Math.floor(x0),
      i1 = Math.floor(x1) + 1,
      j0 = Math.floor(y0),
      j1 = Math.floor(y1) + 1;
    if (wrap === 'clamp') {
      i0 = Math.max(0, Math.min(W - 1, i0));
      i1 = Math.max(0, Math.min(W - 1, i1));
      j0 = Math.max(0, Math.min(H - 1, j0));
      j1 = Math.max(0, Math.min(H - 1, j1));
    }
    if (i1 - i0 >= W) {
      i0 = 0;
      i1 = W - 1;
    }
    if (j1 - j0 >= H) {
      j0 = 0;
      j1 = H - 1;
    }
    let lo = Infinity,
      hi = -Infinity;
    for (let j = j0; j <= j1; j++) {
      const jj = ((j % H) + H) % H;
      for (let i = i0; i <= i1; i++) {
        const x = map.data[jj * W + (((i % W) + W) % W)];
        if (x < lo) lo = x;
        if (x > hi) hi = x;
      }
    }
    out[2 * f] = lo * inv;
    out[2 * f + 1] = hi * inv;
  }
  return out;
}
