/**
 * The shapes every pattern returns. Positions are fixed point (integers over ONE = 2^16,
 * see fixed.ts); convert with `toUnit` only at the edge of the program (drawing, JSON).
 */

/** 1D line patterns. `pow2-snap`, `one-at-a-time`, `even`, `odd-first`, `slow-slide` are the
 * talk's steps towards `hable`; `integer`, `pow2`, `fractional_odd`, `fractional_even` are the
 * D3D11 partitionings, equal to the reference tessellator. */
export const LINE_MODES = [
  'pow2-snap',
  'one-at-a-time',
  'even',
  'odd-first',
  'slow-slide',
  'hable',
  'integer',
  'pow2',
  'fractional_odd',
  'fractional_even',
] as const;
export type LineMode = (typeof LINE_MODES)[number];

export const D3D11_PARTITIONINGS = ['integer', 'pow2', 'fractional_odd', 'fractional_even'] as const;
export type D3D11Partitioning = (typeof D3D11_PARTITIONINGS)[number];

/** A line: sorted fixed-point parameters, 0 first and ONE last. */
export interface LinePattern {
  /** Ascending, x[0] = 0 and x[last] = ONE (empty only for a culled D3D11 factor). One
   * exception, kept to stay bit-exact with the reference: D3D11 fractional_even just above
   * f = 6 and f = 30 puts the point before the midpoint a few 2^-16 past it (see d3d11.ts). */
  x: number[];
  /** Per point: true when its position depends on the fractional part of the factor (drawn
   * red in the diagrams: the point is sliding or newly born). */
  moving: boolean[];
}

/** A triangle pattern over the barycentric domain. */
export interface TriPattern {
  /** Barycentrics, three fixed-point integers per vertex that sum to ONE exactly. */
  bary: number[];
  /** Index triples, all with the same (positive) orientation. */
  triangles: number[];
  vertexCount: number;
  triangleCount: number;
}

export const TRI_MODES = ['clamped', 'integer', 'pow2', 'fractional_odd', 'fractional_even'] as const;
export type TriMode = (typeof TRI_MODES)[number];
