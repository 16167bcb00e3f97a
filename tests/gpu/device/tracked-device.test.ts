/**
 * The GPU memory ledger (src/gpu/device/tracked-device.ts) on a fake device: bytes counted at creation,
 * released once at destroy (however often it is called), texture sizes with mips and samples, and
 * every other device member forwarded to the real device with `this` bound to it.
 */
import { describe, expect, it } from 'vitest';
import { GpuMemory, textureBytes, trackDevice } from '../../../src/gpu/device/tracked-device.ts';

class FakeObject {
  destroyed = 0;
  constructor(readonly label: string) {}
  destroy(): void {
    this.destroyed++;
  }
}

function fakeDevice() {
  const made: FakeObject[] = [];
  const device = {
    label: 'fake',
    limits: { maxBufferSize: 1024 },
    createBuffer(desc: GPUBufferDescriptor) {
      const b = new FakeObject(desc.label ?? '');
      made.push(b);
      return b;
    },
    createTexture(desc: GPUTextureDescriptor) {
      const t = new FakeObject(desc.label ?? '');
      made.push(t);
      return t;
    },
    /** A method that needs `this` to be the device itself (as WebGPU's methods do). */
    whoAmI(this: unknown) {
      return this === device ? 'the device' : 'something else';
    },
  };
  return { device: device as unknown as GPUDevice, made, raw: device };
}

describe('GPU memory ledger', () => {
  it('counts buffers and textures from creation to destroy, once', () => {
    const { device: real, made } = fakeDevice();
    const { device, memory } = trackDevice(real);
    const a = device.createBuffer({ label: 'a', size: 100, usage: 0 });
    const b = device.createBuffer({ label: 'b', size: 28, usage: 0 });
    const t = device.createTexture({ label: 't', size: [4, 2], format: 'rgba8unorm', usage: 0 });
    expect(memory.counts).toEqual({ bytes: 160, buffers: 2, textures: 1, bufferBytes: 128, textureBytes: 32 });
    expect(memory.byLabel()).toEqual({ a: 100, b: 28, t: 32 });
    a.destroy();
    a.destroy();
    expect(memory.counts.bytes).toBe(60);
    expect(made[0].destroyed).toBe(2); // the real destroy still runs every time
    t.destroy();
    b.destroy();
    expect(memory.counts).toEqual({ bytes: 0, buffers: 0, textures: 0, bufferBytes: 0, textureBytes: 0 });
  });

  it('forwards everything else to the real device, bound to it', () => {
    const { device: real, raw } = fakeDevice();
    const { device } = trackDevice(real);
    expect(device.label).toBe('fake');
    expect(device.limits.maxBufferSize).toBe(1024);
    expect((device as unknown as typeof raw).whoAmI()).toBe('the device');
    device.label = 'renamed';
    expect(raw.label).toBe('renamed');
  });

  it('sizes textures: every mip level, array layers, 3D depth, samples', () => {
    expect(textureBytes({ size: [8, 8], format: 'rgba8unorm', usage: 0, mipLevelCount: 4 })).toBe(4 * (64 + 16 + 4 + 1));
    expect(textureBytes({ size: { width: 4, height: 4, depthOrArrayLayers: 3 }, format: 'r32float', usage: 0 })).toBe(4 * 16 * 3);
    expect(textureBytes({ size: [4, 4, 4], format: 'r8unorm', usage: 0, dimension: '3d', mipLevelCount: 2 })).toBe(64 + 8);
    expect(textureBytes({ size: [10, 5], format: 'depth32float', usage: 0, sampleCount: 4 })).toBe(10 * 5 * 4 * 4);
  });

  it('clear(): a lost device takes everything with it', () => {
    const memory = new GpuMemory();
    const { device } = trackDevice(fakeDevice().device, memory);
    device.createBuffer({ label: 'x', size: 64, usage: 0 });
    memory.clear();
    expect(memory.counts.bytes).toBe(0);
  });
});
