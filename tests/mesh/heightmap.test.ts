// Height maps: bilinear sampling with derivatives and its conventions (src/mesh/heightmap.ts),
// PNG decoding and encoding in Node (src/mesh/heightmap-png.ts).
import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { heightMapFromFunction, heightMapFromRgba, makeHeightMap, sampleHeight } from '../../src/mesh/heightmap.ts';
import { HeightMapError, decodeHeightPng, encodeHeightPng } from '../../src/mesh/heightmap-png.ts';

// 4 x 3, raw 8-bit values chosen so no two neighbours are equal.
const RAW = [10, 200, 30, 120, 250, 0, 90, 60, 5, 180, 77, 140];
const map = makeHeightMap(4, 3, Uint16Array.from(RAW), 8);
const texel = (i: number, j: number): number => RAW[j * 4 + i] / 255;

describe('height map sampling', () => {
  it('texel centres return the texel; row 0 is the top of the image (v near 1)', () => {
    for (let j = 0; j < 3; j++)
      for (let i = 0; i < 4; i++) {
        expect(sampleHeight(map, (i + 0.5) / 4, 1 - (j + 0.5) / 3).value).toBeCloseTo(texel(i, j), 12);
      }
  });

  it("is bilinear between texel centres; its gradient blends the texels' central differences bilinearly", () => {
    const u = (1 + 0.5 + 0.3) / 4,
      v = 1 - (1 + 0.5 + 0.6) / 3; // 30% from texel (1,1) to (2,1), 60% to row 2
    const want = 0.4 * (0.7 * texel(1, 1) + 0.3 * texel(2, 1)) + 0.6 * (0.7 * texel(1, 2) + 0.3 * texel(2, 2));
    const s = sampleHeight(map, u, v);
    expect(s.value).toBeCloseTo(want, 12);
    // Per texel unit; repeat wrap. ∂x/∂u = W, ∂y/∂v = −H.
    const t = (i: number, j: number) => texel((i + 4) % 4, (j + 3) % 3);
    const gx = (i: number, j: number) => (t(i + 1, j) - t(i - 1, j)) / 2;
    const gy = (i: number, j: number) => (t(i, j + 1) - t(i, j - 1)) / 2;
    const blend = (g: (i: number, j: number) => number) => 0.4 * (0.7 * g(1, 1) + 0.3 * g(2, 1)) + 0.6 * (0.7 * g(1, 2) + 0.3 * g(2, 2));
    expect(s.dU).toBeCloseTo(blend(gx) * 4, 12);
    expect(s.dV).toBeCloseTo(-blend(gy) * 3, 12);
  });

  it('its gradient is continuous across texel borders (the bilinear patch gradient jumps there), and exact on a ramp', () => {
    // The shading normal follows this gradient: a jump at every texel line, sampled by triangles that
    // do not line up with the texels, drew saw teeth along the brick box's bevels.
    for (const [u, v] of [
      [2 / 4, 0.5],
      [0.3, 1 - 1 / 3],
    ]) {
      const e = 1e-9;
      const a = sampleHeight(map, u - e, v - e),
        b = sampleHeight(map, u + e, v + e);
      expect(Math.abs(a.dU - b.dU)).toBeLessThan(1e-6);
      expect(Math.abs(a.dV - b.dV)).toBeLessThan(1e-6);
    }
    const ramp = heightMapFromFunction(64, 32, 16, (u, v) => 0.2 + 0.5 * u + 0.25 * v);
    for (const [u, v] of [
      [0.31, 0.47],
      [0.5, 0.5],
      [0.77, 0.2],
    ]) {
      const s = sampleHeight(ramp, u, v, 'clamp');
      expect(s.dU).toBeCloseTo(0.5, 3);
      expect(s.dV).toBeCloseTo(0.25, 3);
    }
  });

  it('repeat wraps by whole tiles; clamp holds the edge texels', () => {
    for (const [u, v] of [
      [0.03, 0.2],
      [0.97, 0.9],
      [0.5, 0.01],
    ]) {
      expect(sampleHeight(map, u + 1, v - 2).value).toBeCloseTo(sampleHeight(map, u, v).value, 12);
    }
    // Repeat: between the last and first column the lookup blends texels 3 and 0.
    expect(sampleHeight(map, 0, 1 - 0.5 / 3).value).toBeCloseTo((texel(3, 0) + texel(0, 0)) / 2, 12);
    expect(sampleHeight(map, 0, 1 - 0.5 / 3, 'clamp').value).toBeCloseTo(texel(0, 0), 12);
    expect(sampleHeight(map, -0.7, 1.3, 'clamp').value).toBeCloseTo(texel(0, 0), 12);
    expect(sampleHeight(map, -0.7, 1.3, 'clamp').dU).toBe(0);
  });

  it('16-bit maps scale by 65535; bad sizes and values are refused', () => {
    const m16 = makeHeightMap(1, 1, Uint16Array.from([65535]), 16);
    expect(sampleHeight(m16, 0.3, 0.3).value).toBe(1);
    expect(() => makeHeightMap(2, 2, new Uint16Array(3), 8)).toThrow(/3 texels/);
    expect(() => makeHeightMap(1, 1, Uint16Array.from([256]), 8)).toThrow(/8-bit/);
    expect(() => sampleHeight(map, NaN, 0)).toThrow(/not finite/);
  });
});

describe('height map PNG (Node)', () => {
  it('8-bit and 16-bit greyscale round-trip exactly', () => {
    for (const bits of [8, 16] as const) {
      const m = heightMapFromFunction(37, 23, bits, (u, v) => 0.5 + 0.5 * Math.sin(9 * u) * Math.cos(7 * v));
      const d = decodeHeightPng(encodeHeightPng(m));
      expect(d.bits).toBe(bits);
      expect([d.width, d.height]).toEqual([37, 23]);
      expect(Array.from(d.data)).toEqual(Array.from(m.data));
    }
    // 16-bit values that 8 bits cannot hold survive.
    const fine = makeHeightMap(3, 1, Uint16Array.from([1, 32768, 65534]), 16);
    expect(Array.from(decodeHeightPng(encodeHeightPng(fine)).data)).toEqual([1, 32768, 65534]);
  });

  it('RGB and RGBA PNGs read their first (red) channel', () => {
    for (const colorType of [2, 6] as const) {
      const png = new PNG({ width: 2, height: 1 });
      // Opaque for RGB (pngjs would blend a translucent pixel onto white); translucent for RGBA, alpha ignored.
      png.data = Buffer.from([10, 99, 250, 255, 200, 3, 7, colorType === 6 ? 128 : 255]);
      const bytes = PNG.sync.write(png, { colorType });
      const d = decodeHeightPng(new Uint8Array(bytes));
      expect(d.bits).toBe(8);
      expect(Array.from(d.data)).toEqual([10, 200]);
    }
  });

  it('a bad PNG gives a HeightMapError that says what is wrong', () => {
    const good = encodeHeightPng(heightMapFromFunction(8, 8, 8, (u) => u));
    const cases: [Uint8Array, RegExp][] = [
      [new Uint8Array(0), /not a PNG.*only 0 bytes/],
      [new TextEncoder().encode('GIF89a not a png at all'), /not a PNG.*signature/],
      [good.slice(0, 40), /corrupt, truncated or unsupported PNG/],
    ];
    const flipped = good.slice();
    flipped[20] ^= 0xff; // inside the IHDR chunk: its CRC no longer matches
    cases.push([flipped, /corrupt, truncated or unsupported PNG/]);
    for (const [bytes, re] of cases) {
      expect(() => decodeHeightPng(bytes)).toThrow(HeightMapError);
      expect(() => decodeHeightPng(bytes)).toThrow(re);
    }
  });

  it('RGBA pixels (the browser path) read like the Node decoder: the red channel', () => {
    const png = new PNG({ width: 3, height: 2 });
    png.data = Buffer.from([9, 1, 2, 255, 40, 50, 60, 255, 255, 0, 0, 255, 0, 255, 255, 255, 128, 128, 128, 255, 77, 0, 0, 10]);
    const node = decodeHeightPng(new Uint8Array(PNG.sync.write(png, { colorType: 6 })));
    const rgba = heightMapFromRgba(3, 2, png.data);
    expect(Array.from(rgba.data)).toEqual(Array.from(node.data));
    expect(Array.from(rgba.data)).toEqual([9, 40, 255, 0, 128, 77]);
    expect(() => heightMapFromRgba(3, 2, new Uint8Array(23))).toThrow(/24 RGBA bytes/);
  });
});
