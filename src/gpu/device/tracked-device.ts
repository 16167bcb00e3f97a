/**
 * GPU memory accounting: a GPUDevice stand-in that counts the bytes of every buffer and texture
 * created through it, from creation until its `destroy()`. The demo hands this device (not the
 * real one) to everything that allocates (renderer, tessellator, cage meshes, readers), so a leak
 * anywhere (an object replaced but never destroyed) shows up as bytes that never come back; the
 * soak test (e2e/soak.spec.ts) holds the page to that.
 *
 * Wrapping happens at the device, not in the classes that allocate, so those classes stay as they
 * are. A Proxy forwards every other member to the real device (methods bound to it: WebGPU's
 * methods check that `this` is a real device). The real device must still be passed wherever the
 * platform checks its type (GPUCanvasContext.configure): `real` gives it.
 *
 * Texture sizes are the logical size (texels × bytes per texel × samples, every mip level);
 * drivers may pad, and depth24plus may be stored in 4 or 8 bytes: the count is the demo's own
 * ledger, exact for what it asks for, not the driver's.
 */

export interface GpuMemoryCounts {
  /** Bytes of live buffers and textures. */
  bytes: number;
  buffers: number;
  textures: number;
  bufferBytes: number;
  textureBytes: number;
}

/** Bytes per texel of the uncompressed formats (the block formats count 4; the demo uses none). */
const TEXEL_BYTES: Record<string, number> = {
  r8unorm: 1,
  r8snorm: 1,
  r8uint: 1,
  r8sint: 1,
  stencil8: 1,
  r16uint: 2,
  r16sint: 2,
  r16float: 2,
  r16unorm: 2,
  r16snorm: 2,
  rg8unorm: 2,
  rg8snorm: 2,
  rg8uint: 2,
  rg8sint: 2,
  depth16unorm: 2,
  r32uint: 4,
  r32sint: 4,
  r32float: 4,
  rg16uint: 4,
  rg16sint: 4,
  rg16float: 4,
  rg16unorm: 4,
  rg16snorm: 4,
  rgba8unorm: 4,
  'rgba8unorm-srgb': 4,
  rgba8snorm: 4,
  rgba8uint: 4,
  rgba8sint: 4,
  bgra8unorm: 4,
  'bgra8unorm-srgb': 4,
  rgb9e5ufloat: 4,
  rgb10a2uint: 4,
  rgb10a2unorm: 4,
  rg11b10ufloat: 4,
  depth24plus: 4,
  'depth24plus-stencil8': 4,
  depth32float: 4,
  'depth32float-stencil8': 5,
  rg32uint: 8,
  rg32sint: 8,
  rg32float: 8,
  rgba16uint: 8,
  rgba16sint: 8,
  rgba16float: 8,
  rgba16unorm: 8,
  rgba16snorm: 8,
  rgba32uint: 16,
  rgba32sint: 16,
  rgba32float: 16,
};

/** The bytes a texture of this descriptor holds (all mip levels and samples). */
export function textureBytes(desc: GPUTextureDescriptor): number {
  const size = desc.size;
  const [w, h, d] =
    Array.isArray(size) || (typeof size === 'object' && Symbol.iterator in size)
      ? [...(size as Iterable<number>)]
      : [(size as GPUExtent3DDict).width, (size as GPUExtent3DDict).height, (size as GPUExtent3DDict).depthOrArrayLayers];
  const width = w ?? 1,
    height = h ?? 1,
    layers = d ?? 1;
  const texel = TEXEL_BYTES[desc.format] ?? 4;
  const is3d = desc.dimension === '3d';
  let bytes = 0;
  for (let level = 0; level < (desc.mipLevelCount ?? 1); level++) {
    const lw = Math.max(1, width >> level),
      lh = Math.max(1, height >> level);
    const ld = is3d ? Math.max(1, layers >> level) : layers;
    bytes += lw * lh * ld * texel;
  }
  return bytes * (desc.sampleCount ?? 1);
}

/** The ledger of one device's live buffers and textures. */
export class GpuMemory {
  readonly #live = new Map<GPUBuffer | GPUTexture, { bytes: number; kind: 'buffer' | 'texture'; label: string }>();

  add(object: GPUBuffer | GPUTexture, kind: 'buffer' | 'texture', bytes: number): void {
    this.#live.set(object, { bytes, kind, label: object.label });
    // Count the release once, however often destroy() is called (destroying twice is legal).
    const destroy = object.destroy.bind(object);
    Object.defineProperty(object, 'destroy', {
      configurable: true,
      value: () => {
        this.#live.delete(object);
        destroy();
      },
    });
  }

  get counts(): GpuMemoryCounts {
    const c: GpuMemoryCounts = { bytes: 0, buffers: 0, textures: 0, bufferBytes: 0, textureBytes: 0 };
    for (const o of this.#live.values()) {
      c.bytes += o.bytes;
      if (o.kind === 'buffer') {
        c.buffers++;
        c.bufferBytes += o.bytes;
      } else {
        c.textures++;
        c.textureBytes += o.bytes;
      }
    }
    return c;
  }

  /** Live bytes per label (what to look at when a count does not come back). */
  byLabel(): Record<string, number> {
    const out: Record<string, number> = {};
    for (const o of this.#live.values()) out[o.label || '(no label)'] = (out[o.label || '(no label)'] ?? 0) + o.bytes;
    return out;
  }

  /** The device is gone (lost or destroyed): everything it held went with it. */
  clear(): void {
    this.#live.clear();
  }
}

export interface TrackedDevice {
  /** Use this one for everything that allocates. */
  device: GPUDevice;
  /** The device itself, for the platform calls that check its type (canvas configure). */
  real: GPUDevice;
  memory: GpuMemory;
}

/** A device whose buffers and textures are counted in `memory` until destroyed. */
export function trackDevice(real: GPUDevice, memory = new GpuMemory()): TrackedDevice {
  const createBuffer = (desc: GPUBufferDescriptor): GPUBuffer => {
    const buffer = real.createBuffer(desc);
    memory.add(buffer, 'buffer', desc.size);
    return buffer;
  };
  const createTexture = (desc: GPUTextureDescriptor): GPUTexture => {
    const texture = real.createTexture(desc);
    memory.add(texture, 'texture', textureBytes(desc));
    return texture;
  };
  const bound = new Map<PropertyKey, unknown>();
  const device = new Proxy(real, {
    get(target, prop) {
      if (prop === 'createBuffer') return createBuffer;
      if (prop === 'createTexture') return createTexture;
      const value = Reflect.get(target, prop, target);
      if (typeof value !== 'function') return value;
      // One bound function per method, so that identity comparisons (removeEventListener) hold.
      let fn = bound.get(prop);
      if (!fn) bound.set(prop, (fn = (value as (...a: unknown[]) => unknown).bind(target)));
      return fn;
    },
    set(target, prop, value) {
      return Reflect.set(target, prop, value, target);
    },
  });
  return { device, real, memory };
}
