// Node-only PNG reading and writing of height maps (pngjs). Kept apart from heightmap.ts and
// out of src/mesh/index.ts so the browser build never pulls pngjs (the browser decodes with
// createImageBitmap / ImageDecoder).
//
// Channel rule: greyscale (with or without alpha) PNGs give their grey value; RGB, RGBA and
// palette PNGs give their FIRST channel (red), not a luminance mix, so a height map saved as
// RGB with equal channels reads exactly and the GPU can read the same channel (.r) of any
// texture format. Alpha is ignored. Bit depth: 16-bit PNGs stay 16-bit; 1, 2, 4 and 8-bit PNGs
// become 8-bit (1/2/4-bit grey scaled exactly to 0..255, as the PNG spec's replication does).
import { crc32, inflateSync } from 'node:zlib';
import { PNG } from 'pngjs';
import { type HeightMap, MAX_HEIGHT_MAP_PIXELS } from './heightmap.ts';

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
  checkPngLayout(bytes);
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

function corrupt(reason: string): HeightMapError {
  return new HeightMapError(`height map: corrupt, truncated or unsupported PNG (${reason})`);
}

/** Channels per pixel of each PNG colour type (3 is palette indices). */
const CHANNELS: Record<number, number> = { 0: 1, 2: 3, 3: 1, 4: 2, 6: 4 };

/**
 * Check what the file declares against what it holds, before the decoder allocates for it: the
 * size against MAX_HEIGHT_MAP_PIXELS (a 69-byte file can declare 16384² and cost gigabytes), every
 * chunk inside the file, an IEND, and the inflated image data as long as the size needs (pngjs
 * reads missing rows as zeros: a truncated map would be a silently flat one).
 */
function checkPngLayout(bytes: Uint8Array): void {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  let at = 8;
  let header: { width: number; height: number; depth: number; colorType: number; interlace: number } | undefined;
  const idat: Uint8Array[] = [];
  let ended = false;
  while (at + 8 <= bytes.length && !ended) {
    const length = view.getUint32(at);
    const type = String.fromCharCode(...bytes.subarray(at + 4, at + 8));
    if (at + 12 + length > bytes.length) throw corrupt(`its ${type.replace(/[^A-Za-z]/g, '?')} chunk runs past the end of the file`);
    const data = bytes.subarray(at + 8, at + 8 + length);
    // A chunk whose CRC fails is not read (an IHDR's size least of all).
    if (crc32(bytes.subarray(at + 4, at + 8 + length)) !== view.getUint32(at + 8 + length))
      throw corrupt(`its ${type.replace(/[^A-Za-z]/g, '?')} chunk fails its CRC check`);
    if (type === 'IHDR' && length >= 13) {
      const d = new DataView(data.buffer, data.byteOffset, data.byteLength);
      header = { width: d.getUint32(0), height: d.getUint32(4), depth: data[8], colorType: data[9], interlace: data[12] };
      if (!(header.width > 0 && header.height > 0)) throw new HeightMapError(`height map: PNG has size ${header.width}x${header.height}`);
      if (header.width * header.height > MAX_HEIGHT_MAP_PIXELS)
        throw new HeightMapError(
          `height map: the PNG declares ${header.width}x${header.height}, more than the ${MAX_HEIGHT_MAP_PIXELS} texels (8192x8192) taken`,
        );
    } else if (type === 'IDAT') idat.push(data);
    else if (type === 'IEND') ended = true;
    at += 12 + length;
  }
  if (!header) throw corrupt('no IHDR header chunk');
  if (!ended) throw corrupt('no IEND chunk: the file is cut short');
  const channels = CHANNELS[header.colorType];
  if (channels === undefined) return; // the decoder names an unknown colour type
  // Filtered scanlines: a filter byte and ceil(width·bits/8) bytes per row, per Adam7 pass if interlaced.
  const rowBytes = (w: number) => (w > 0 ? 1 + Math.ceil((w * channels * header.depth) / 8) : 0);
  let expected = 0;
  if (header.interlace === 1) {
    const passes = [
      [0, 0, 8, 8],
      [4, 0, 8, 8],
      [0, 4, 4, 8],
      [2, 0, 4, 4],
      [0, 2, 2, 4],
      [1, 0, 2, 2],
      [0, 1, 1, 2],
    ];
    for (const [x0, y0, dx, dy] of passes) {
      const w = Math.ceil((header.width - x0) / dx);
      const h = Math.ceil((header.height - y0) / dy);
      if (w > 0 && h > 0) expected += h * rowBytes(w);
    }
  } else expected = header.height * rowBytes(header.width);
  let inflated: number;
  try {
    inflated = inflateSync(Buffer.concat(idat), { maxOutputLength: expected + 1, finishFlush: 2 /* Z_SYNC_FLUSH */ }).length;
  } catch (e) {
    if ((e as { code?: string }).code === 'ERR_BUFFER_TOO_LARGE') return; // more than needed: the decoder ignores the rest
    throw corrupt(`its image data does not inflate: ${(e as Error)?.message ?? String(e)}`);
  }
  if (inflated < expected)
    throw corrupt(`its image data holds ${inflated} of the ${expected} bytes a ${header.width}x${header.height} image needs`);
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
