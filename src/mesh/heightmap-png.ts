// Node-only PNG reading and writing of height maps (pngjs). Kept apart from heightmap.ts and
// out of src/mesh/index.ts so the browser build never pulls pngjs (the browser decodes with
// createImageBitmap / ImageDecoder).
//
// Channel rule: greyscale (with or without alpha) PNGs give their grey value; RGB, RGBA and
// palette PNGs give their FIRST channel (red), not a luminance mix, so a height map saved as
// RGB with equal channels reads exactly and the GPU can read the same channel (.r) of any
// texture format. Alpha is ignored. Bit depth: 16-bit PNGs stay 16-bit; 1, 2, 4 and 8-bit PNGs
// become 8-bit (1/2/4-bit grey scaled exactly to 0..255, as the PNG spec's replication does).
import { PNG } from 'pngjs';
import type { HeightMap } from './heightmap.ts';

export class HeightMapError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'HeightMapError';
  }
}

const PNG_SIGNATURE = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];

/** Decode a PNG into a height map; throws HeightMapError with a readable reason for anything else. */
export function decodeHeightPng(bytes: Uint8Array): HeightMap {
  if (!(bytes instanceof Uint8Array)) throw new HeightMapError('height map: input is not bytes');
  if (bytes.length < 8 || PNG_SIGNATURE.some((b, i) => bytes[i] !== b)) {
    throw new HeightMapError(`height map: not a PNG file (${bytes.length < 8 ? `only ${bytes.length} bytes` : 'wrong signature'})`);
  }
  let png: ReturnType<typeof PNG.sync.read>;
  try {
    // skipRescale keeps 16-bit samples as 16-bit (in a Uint16Array) instead of cutting them to 8.
    png = PNG.sync.read(Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength), { skipRescale: true });
  } catch (e) {
    throw new HeightMapError(`height map: corrupt, truncated or unsupported PNG (decoder says: ${(e as Error)?.message ?? String(e)})`);
  }
  const { width, height, depth } = png;
  const colorType = png.colorType as number; // 3 (palette) is possible at runtime though the typings omit it
  if (!(width > 0 && height > 0)) throw new HeightMapError(`height map: PNG has size ${width}x${height}`);
  // pngjs expands every pixel to 4 channels (RGBA, grey replicated); palette images are already 8-bit RGBA.
  const src = png.data as unknown as ArrayLike<number>;
  if (src.length < width * height * 4) throw new HeightMapError('height map: PNG pixel data is truncated');
  const bits: 8 | 16 = depth === 16 && colorType !== 3 ? 16 : 8;
  const scale = colorType === 3 || depth >= 8 ? 1 : 255 / ((1 << depth) - 1);
  const data = new Uint16Array(width * height);
  for (let p = 0; p < width * height; p++) data[p] = src[4 * p] * scale;
  return { width, height, data, bits };
}

/** Encode a height map as a greyscale PNG of its own bit depth (deflate level 9, for small files). */
export function encodeHeightPng(map: HeightMap): Uint8Array {
  const png = new PNG({ width: map.width, height: map.height, colorType: 0, inputColorType: 0, bitDepth: map.bits, inputHasAlpha: false });
  if (map.bits === 16) {
    // pngjs takes 16-bit input as native-endian Uint16 samples.
    png.data = Buffer.from(new Uint16Array(map.data).buffer) as typeof png.data;
  } else {
    png.data = Buffer.from(Uint8Array.from(map.data)) as typeof png.data;
  }
  return new Uint8Array(
    PNG.sync.write(png, { colorType: 0, inputColorType: 0, bitDepth: map.bits, inputHasAlpha: false, deflateLevel: 9 }),
  );
}
