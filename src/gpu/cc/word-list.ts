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
  get view(): Uint32Array {
    return this.a.subarray(0, this.n);
  }
}

export const f32bits = (x: number): number => new Uint32Array(Float32Array.of(x).buffer)[0];
