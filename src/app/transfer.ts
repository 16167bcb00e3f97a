/** Every ArrayBuffer under `x` (the typed arrays of a cage, its topology, a prepared mesh), once
 * each: what a worker hands back by transfer rather than by copy. */
export function buffersOf(x: unknown, out = new Set<ArrayBuffer>()): Set<ArrayBuffer> {
  if (ArrayBuffer.isView(x)) {
    if (x.buffer instanceof ArrayBuffer) out.add(x.buffer);
  } else if (x && typeof x === 'object') for (const v of Object.values(x)) buffersOf(v, out);
  return out;
}
