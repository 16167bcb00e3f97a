/**
 * The two helpers every table of the Catmull-Clark preparation is packed with (src/gpu/cc/build.ts
 * and the files of its steps): a growable u32 list, and an f32's bits as a u32 word.
 */

/** Growable u32 list. */
export class U32 {
  a = new Uint32Array(1024);
  n = 0;
  push(x: number): void {
    if (this.n === this.a.length) {
      const b = new Uint32Array(2 * this.a.length);
      b.set(this.a);
      this.a = b;
    }
    this.a[this.n++] = x >>> 0;
  }
  /** Room for k more words; returns the array to write them into (at n, n + 1, …; the writer
   * sets n after): a hot loop's writes without a call per word. */
  reserve(k: number): Uint32Array {
    if (this.n + k > this.a.length) {
      const b = new Uint32Array(Math.max(2 * this.a.length, this.n + k));
      b.set(this.a.subarray(0, this.n));
      this.a = b;
    }
    return this.a;
  }
  get view(): Uint32Array {
    return this.a.subarray(0, this.n);
  }
}

const f32Scratch = new Float32Array(1);
const u32Scratch = new Uint32Array(f32Scratch.buffer);
/** x rounded to f32, as its bits (one scratch word, no arrays made per call: the preparation packs
 * one per sharp point). */
export const f32bits = (x: number): number => {
  f32Scratch[0] = x;
  return u32Scratch[0];
};
