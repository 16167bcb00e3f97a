/**
 * The demo's height maps: the project's displaced models (public/models/displaced.json, written
 * by scripts/models.ts, fetched once beside the models), and PNG files a
 * user drops or opens, decoded by the browser's own image decoding (createImageBitmap, then the
 * red channel of a 2D canvas: src/mesh/heightmap.ts heightMapFromRgba, the same channel rule as
 * the Node decoder). The 2D canvas is 8-bit, so a 16-bit PNG is displaced at 8 bits here (the CLI
 * reads all 16).
 */
import { heightMapFromRgba, MAX_HEIGHT_MAP_PIXELS, type DisplacedModelEntry, type HeightMap } from '../mesh/heightmap.ts';
import type { CageHeightMap } from './geometry.ts';

/** A height map as the demo holds it for one cage: the map, and its own scale and mid level
 * (the panel's scale multiplies this one). */
export interface HeightEntry {
  height: CageHeightMap;
  scale: number;
  midLevel: number;
  /** The file it came from (shown in messages). */
  source: string;
}

/** The panel's displacement on a cage's map: on/off, the scale (the map's times the panel's), the mid level. */
export interface DisplacementSettings {
  enabled: boolean;
  scale: number;
  midLevel: number;
}

type DisplacedModel = DisplacedModelEntry;

let index: Promise<DisplacedModel[]> | null = null;

/** The project's height map for model `name` (its file name without .obj) in directory `dir`,
 * if it has one. The index is fetched once (a failed fetch is tried again next time). */
export async function builtinHeight(name: string, dir: string): Promise<DisplacedModel | undefined> {
  index ??= fetch(`${dir}displaced.json`).then((r) => {
    if (!r.ok) throw new Error(`could not fetch ${dir}displaced.json: HTTP ${r.status}`);
    return r.json() as Promise<DisplacedModel[]>;
  });
  try {
    return (await index).find((d) => d.model === `${name}.obj`);
  } catch (e) {
    index = null;
    throw e;
  }
}

/** Decode an image file into a height map, or throw an Error whose message says why. */
export async function decodeHeightImage(blob: Blob, name: string): Promise<HeightMap> {
  let bitmap: ImageBitmap;
  try {
    // No colour management and no premultiplication: the stored values are the heights.
    bitmap = await createImageBitmap(blob, { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
  } catch {
    throw new Error(`${name} is not an image this browser can decode (a PNG height map is expected)`);
  }
  try {
    const { width, height } = bitmap;
    if (width * height > MAX_HEIGHT_MAP_PIXELS)
      throw new Error(`${name} is ${width}x${height}: more than the ${MAX_HEIGHT_MAP_PIXELS} texels (8192x8192) taken`);
    const canvas = new OffscreenCanvas(width, height);
    const ctx = canvas.getContext('2d', { willReadFrequently: true });
    if (!ctx) throw new Error('no 2D canvas to read the image with');
    ctx.drawImage(bitmap, 0, 0);
    return heightMapFromRgba(width, height, ctx.getImageData(0, 0, width, height, { colorSpace: 'srgb' }).data);
  } finally {
    bitmap.close();
  }
}

/** Fetch and decode one of the project's height maps. */
export async function fetchBuiltinHeight(d: DisplacedModel, dir: string): Promise<HeightEntry> {
  const url = `${dir}${encodeURIComponent(d.heightMap)}`;
  const res = await fetch(url);
  if (!res.ok) throw new Error(`could not fetch ${url}: HTTP ${res.status}`);
  const map = await decodeHeightImage(await res.blob(), d.heightMap);
  return { height: { map, wrap: d.wrap }, scale: d.scale, midLevel: d.midLevel, source: d.heightMap };
}

/** A user's map on a cage without one: heights of ±1 % of the model's size around grey 0.5. */
export function defaultHeightScale(positions: ArrayLike<number>): number {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i++) {
    lo[i % 3] = Math.min(lo[i % 3], positions[i]);
    hi[i % 3] = Math.max(hi[i % 3], positions[i]);
  }
  return 0.02 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}
