/**
 * The demo's output-buffer limits (src/app/limits.ts): what a capacity asks of the device, and the
 * sentences the page shows when a device with WebGPU's default limits cannot hold it.
 */
import { describe, expect, it } from 'vitest';
import { clampMessages, wantedOutputLimits } from '../../src/app/limits.ts';
import { cageTooLarge } from '../../src/gpu/tess/arenas.ts';
import { workBytesAtLeast } from '../../src/gpu/tess/arenas.ts';
import { makeCage } from '../../src/mesh/index.ts';

const DEFAULTS = { maxStorageBufferBindingSize: 128 * 2 ** 20, maxBufferSize: 256 * 2 ** 20 };

describe('output limits', () => {
  it('asks for 12 bytes per vertex and per triangle in the largest buffers', () => {
    expect(wantedOutputLimits(4e6)).toEqual({ maxStorageBufferBindingSize: 48e6, maxBufferSize: 48e6 });
  });

  it('says nothing when the capacity fits the device', () => {
    expect(clampMessages([], DEFAULTS, 4e6)).toEqual([]);
  });

  it('on default limits, the talk’s 16M capacity is cut to what a 128 MiB binding holds, and says so', () => {
    const m = clampMessages(['maxStorageBufferBindingSize: 128 MiB of the 183 MiB asked for'], DEFAULTS, 16e6);
    expect(m).toEqual([
      'maxStorageBufferBindingSize: 128 MiB of the 183 MiB asked for',
      `output buffers: ${Math.floor(DEFAULTS.maxStorageBufferBindingSize / 12).toLocaleString('en-US')} vertices and triangles (16,000,000 asked for); the budget scales factors to fit`,
    ]);
  });

  it('compatibility mode with no vertex-stage storage: says which views are not available', () => {
    const m = clampMessages(
      ['maxStorageBuffersInVertexStage: 0 of the 8 asked for'],
      { ...DEFAULTS, maxStorageBuffersInVertexStage: 0 },
      4e6,
    );
    expect(m[0]).toBe('maxStorageBuffersInVertexStage: 0 of the 8 asked for');
    expect(m[1]).toMatch(/wireframe, patch colours, error heat maps and the instanced tessellator are not available/);
    expect(clampMessages([], { ...DEFAULTS, maxStorageBuffersInVertexStage: 2 }, 4e6)).toEqual([]);
  });
});

describe('a cage too large for the device, from its counts', () => {
  const grid = (n: number) => {
    const v: number[] = [];
    const f: number[][] = [];
    for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) v.push(i, j, 0);
    for (let j = 0; j < n; j++)
      for (let i = 0; i < n; i++) f.push([j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i]);
    return makeCage(v, f);
  };

  it('passes a cage whose scratch buffer fits, and refuses one that cannot in plain words, with how many faces would', () => {
    const small = grid(10);
    expect(cageTooLarge(small, 64, DEFAULTS.maxStorageBufferBindingSize)).toBeNull();
    const bytes = workBytesAtLeast(small, 64);
    const said = cageTooLarge(small, 64, bytes / 4);
    expect(said).toMatch(/^100 faces: this device tessellates cages of up to about 25 faces at factors up to 64/);
    // Just enough: taken.
    expect(cageTooLarge(small, 64, bytes)).toBeNull();
  });
});
