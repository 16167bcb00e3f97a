/**
 * Fixed-point arithmetic shared by every pattern.
 *
 * Positions on an edge and barycentric weights are integers over ONE = 2^16, as in the
 * D3D11 reference tessellator. With integers, `ONE - t` is exact, so two triangles that walk
 * a shared edge in opposite directions produce bit-identical points, and the GPU (which reads
 * baked integer tables) reproduces the CPU exactly.
 */
export const FRAC_BITS = 16;
export const ONE = 1 << FRAC_BITS; // 65536

/** Round half to even, as IEEE `roundTiesToEven` and WGSL `round()` do. */
export function roundHalfEven(x: number): number {
  const r = Math.round(x);
  // Math.round rounds .5 up; fix the ties that should go down to the even neighbour.
  if (r - x === 0.5 && r % 2 !== 0) return r - 1;
  return r;
}

/**
 * A tess factor as 16.16 fixed point: first to the nearest float32 (what a shader or the
 * D3D11 reference sees), then to the nearest multiple of 2^-16, ties to even.
 * Not defined for NaN or infinities; callers clamp first.
 */
export function factorToFixed(f: number): number {
  return roundHalfEven(Math.fround(f) * ONE);
}

/** Fixed point to a float parameter in [0, 1] (exact: every k/2^16 is a double). */
export function toUnit(k: number): number {
  return k / ONE;
}
