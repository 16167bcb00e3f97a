/** Names and number formats shared by the figures and the controls. */
import type { LineMode, TriMode } from '../pattern/types.ts';

export const LINE_MODE_LABEL: Record<LineMode, string> = {
  'pow2-snap': 'powers of two',
  'one-at-a-time': 'one at a time',
  even: 'even (weights)',
  'odd-first': 'odd before even',
  'slow-slide': 'slow slide',
  hable: 'Hable',
  integer: 'D3D11 integer',
  pow2: 'D3D11 pow2',
  fractional_odd: 'D3D11 fractional odd',
  fractional_even: 'D3D11 fractional even',
};

export const TRI_MODE_LABEL: Record<TriMode, string> = {
  clamped: 'clamped parallelogram',
  integer: 'D3D11 integer',
  pow2: 'D3D11 pow2',
  fractional_odd: 'D3D11 fractional odd',
  fractional_even: 'D3D11 fractional even',
};

/** A factor for display: 2 decimals. */
export function fmtFactor(f: number): string {
  return f.toFixed(2);
}

/** A position for display: simple fractions by name, else up to 3 decimals. */
export function fmtPos(v: number): string {
  const fr: [number, string][] = [
    [1 / 3, '1/3'],
    [2 / 3, '2/3'],
  ];
  for (const [x, s] of fr) if (Math.abs(v - x) < 5e-4) return s;
  return String(Math.round(v * 1000) / 1000);
}

export const plural = (n: number, one: string, many = `${one}s`) => `${n} ${n === 1 ? one : many}`;
