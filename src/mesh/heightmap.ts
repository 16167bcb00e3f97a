// Height maps for displacement: a runtime-agnostic greyscale image and its bilinear sampling
// with derivatives. No decoder here (the browser decodes with the platform's image decoding,
// Node with heightmap-png.ts), so this file can be bundled anywhere.
//
// Data layout: `data[j * width + i]` is texel (i, j), row j = 0 being the image's FIRST (top)
// row as stored in the PNG; raw integers 0 .. 2^bits − 1, read as value = raw / (2^bits − 1)
// in [0, 1]. 8-bit maps stay 8-bit (1 B/texel on the GPU), 16-bit maps 16-bit.
//
// Texture-coordinate convention (OBJ / OpenGL: v = 0 is the BOTTOM of the image):
//   continuous texel coordinates x = u·width − ½, y = (1 − v)·height − ½,
// so texel (i, j)'s centre is at u = (i + ½)/width, v = 1 − (j + ½)/height. The GPU must
// sample at (u, 1 − v) with the same ½-texel centres (WebGPU's convention) and should use
// textureLoad plus its own f32 weights: hardware bilinear filtering quantises the weights
// (typically to 8 bits), too coarse for a 1e-5 agreement with this reference.
// Bilinear between the four texels around (x, y); out-of-range texel indices follow `wrap`:
//   'repeat': index mod size (tiling maps, the default), 'clamp': clamped to [0, size − 1]
//   (clamp-to-edge, for atlases).

/** The largest height map taken, in texels (8192²: 128 MiB as 16-bit samples), by the page's
 * decoder (src/app/displacement.ts) and the CLI's (src/mesh/heightmap-png.ts) alike. */
export const MAX_HEIGHT_MAP_PIXELS = 8192 * 8192;

export type HeightWrap = 'repeat' | 'clamp';

/** One entry of public/models/displaced.json (written by scripts/models.ts): a project model, its
 * height map's file and bit depth, and its displacement h = (sample − midLevel)·scale, wrap. */
export interface DisplacedModelEntry {
  model: string;
  heightMap: string;
  bits: 8 | 16;
  scale: number;
  midLevel: number;
  wrap: HeightWrap;
}

export interface HeightMap {
  width: number;
  height: number;
  /** Raw texels, row-major from the top row (see the layout above). */
  data: Uint16Array;
  /** 8 or 16: raw values run 0 .. 2^bits − 1. */
  bits: 8 | 16;
}

export interface HeightSample {
  /** Sampled value in [0, 1]. */
  value: number;
  /** ∂value/∂u and ∂value/∂v in texture space (the bilinear patch's gradient, scaled by the texel counts). */
  dU: number;
  dV: number;
}

export function makeHeightMap(width: number, height: number, data: Uint16Array, bits: 8 | 16): HeightMap {
  if (!(Number.isInteger(width) && width > 0 && Number.isInteger(height) && height > 0))
    throw new RangeError(`height map size ${width}x${height} is not positive`);
  if (data.length !== width * height) throw new RangeError(`height map has ${data.length} texels, expected ${width}x${height}`);
  const max = (1 << bits) - 1;
  for (let i = 0; i < data.length; i++) if (data[i] > max) throw new RangeError(`texel ${i} = ${data[i]} exceeds ${bits}-bit range`);
  return { width, height, data, bits };
}

/** A map from a function of the texel centre's (u, v), quantised to `bits` (for generated maps and tests). */
export function heightMapFromFunction(width: number, height: number, bits: 8 | 16, fn: (u: number, v: number) => number): HeightMap {
  const max = (1 << bits) - 1;
  const data = new Uint16Array(width * height);
  for (let j = 0; j < height; j++)
    for (let i = 0; i < width; i++) {
      const x = fn((i + 0.5) / width, 1 - (j + 0.5) / height);
      data[j * width + i] = Math.round(Math.min(1, Math.max(0, x)) * max);
    }
  return { width, height, data, bits };
}

function wrapIndex(i: number, n: number, wrap: HeightWrap): number {
  if (wrap === 'clamp') return i < 0 ? 0 : i >= n ? n - 1 : i;
  return ((i % n) + n) % n;
}

/**
 * Value and gradient at texture coordinates (u, v). The value is bilinear between texel centres.
 * The gradient is not the bilinear patch's (constant along each texel row, it jumps at every texel
 * line): it blends the four texels' central differences with the same weights, so it is
 * continuous, and on a linear ramp it is the ramp's slope. The displaced normal follows it
 * (src/subdiv/displace.ts, wgsl/tess/displace.wgsl): with the patch gradient a bevel a few texels
 * wide shaded as steps, and triangles that do not line up with the texels sampled the steps as
 * saw teeth along every brick of the brick box.
 */
export function sampleHeight(map: HeightMap, u: number, v: number, wrap: HeightWrap = 'repeat'): HeightSample {
  if (!Number.isFinite(u) || !Number.isFinite(v)) throw new RangeError(`texture coordinate (${u}, ${v}) is not finite`);
  const W = map.width,
    H = map.height;
  const x = u * W - 0.5,
    y = (1 - v) * H - 0.5;
  const x0 = Math.floor(x),
    y0 = Math.floor(y);
  const fx = x - x0,
    fy = y - y0;
  const inv = 1 / ((1 << map.bits) - 1);
  const d = map.data;
  const t = (i: number, j: number): number => d[wrapIndex(j, H, wrap) * W + wrapIndex(i, W, wrap)] * inv;
  const blend = (f: (i: number, j: number) => number): number =>
    (1 - fy) * ((1 - fx) * f(x0, y0) + fx * f(x0 + 1, y0)) + fy * ((1 - fx) * f(x0, y0 + 1) + fx * f(x0 + 1, y0 + 1));
  const value = blend(t);
  // Central differences in texel units at the four texels (lattice indices, wrapped or clamped
  // as the lookups are: far outside a clamped map both sides are the edge texel, the gradient 0).
  const gx = blend((i, j) => 0.5 * (t(i + 1, j) - t(i - 1, j)));
  const gy = blend((i, j) => 0.5 * (t(i, j + 1) - t(i, j - 1)));
  // ∂x/∂u = W, ∂y/∂v = −H.
  return { value, dU: gx * W, dV: -gy * H };
}

/**
 * A height map from 8-bit RGBA pixels (row-major from the top, as canvas ImageData and
 * ImageDecoder frames give them): the first (red) channel, the same rule as the Node PNG
 * decoder (heightmap-png.ts), so the browser's createImageBitmap → getImageData path and Node
 * read a greyscale or RGB PNG identically. (The browser's 2D canvas is 8-bit: a 16-bit PNG
 * arrives cut to 8 bits on that path.)
 */
export function heightMapFromRgba(width: number, height: number, rgba: ArrayLike<number>): HeightMap {
  if (rgba.length !== 4 * width * height)
    throw new RangeError(`expected ${4 * width * height} RGBA bytes for ${width}x${height}, got ${rgba.length}`);
  const data = new Uint16Array(width * height);
  for (let p = 0; p < data.length; p++) data[p] = rgba[4 * p];
  return makeHeightMap(width, height, data, 8);
}
