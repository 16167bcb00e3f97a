/**
 * A command encoder that counts what a rebuild records into it: compute passes, and dispatches
 * (direct and indirect). It wraps a real encoder (every call goes through to it), so the rebuild
 * also runs; the counts are what the issue of the dispatch chain measures (each dispatch costs a
 * launch and a barrier on a GPU, whatever its size).
 */
export interface DispatchCounts {
  passes: number;
  direct: number;
  indirect: number;
}

function forward<T extends object>(target: T, intercept: Partial<Record<string | symbol, unknown>>): T {
  return new Proxy(target, {
    get(t, k) {
      if (k in intercept) return intercept[k];
      const v = Reflect.get(t, k, t);
      return typeof v === 'function' ? v.bind(t) : v;
    },
  });
}

export function countingEncoder(encoder: GPUCommandEncoder): { encoder: GPUCommandEncoder; counts: DispatchCounts } {
  const counts: DispatchCounts = { passes: 0, direct: 0, indirect: 0 };
  const wrapped = forward(encoder, {
    beginComputePass: (desc?: GPUComputePassDescriptor) => {
      counts.passes++;
      const pass = encoder.beginComputePass(desc);
      return forward(pass, {
        dispatchWorkgroups: (x: number, y?: number, z?: number) => {
          counts.direct++;
          pass.dispatchWorkgroups(x, y, z);
        },
        dispatchWorkgroupsIndirect: (buffer: GPUBuffer, offset: number) => {
          counts.indirect++;
          pass.dispatchWorkgroupsIndirect(buffer, offset);
        },
      });
    },
  });
  return { encoder: wrapped, counts };
}
