// Uniform sampling of the limit surface, in the CLI's JSON layout.
import type { Surface } from './evaluate.ts';

export interface SubFaceSamples {
  k: number;
  res: number;
  /** xyz of sample (i,j) at (i/res, j/res), stored at index j*(res+1)+i. */
  P: number[];
  N: number[];
}

export interface FaceSamples {
  f: number;
  n: number;
  hole?: boolean;
  sub: SubFaceSamples[];
}

/** What sampling every face at resolution N makes, from the counts alone: the samples in all, and
 * in the largest face (an n-gon has n sub-faces), for a caller to bound its output first. */
export function uniformSampleCount(S: Surface, N: number): { samples: number; largestFace: number } {
  let samples = 0;
  let largestFace = 0;
  for (let f = 0; f < S.faceCount; f++) {
    if (!S.hasLimitSurface(f)) continue;
    const n = S.faceSize(f);
    const face = (n === 4 ? 1 : n) * (N + 1) * (N + 1);
    samples += face;
    largestFace = Math.max(largestFace, face);
  }
  return { samples, largestFace };
}

/** Sample every face (every sub-face of non-quads) on an (N+1)^2 grid. */
export function sampleUniform(S: Surface, N: number): { faces: FaceSamples[] } {
  return { faces: [...uniformFaces(S, N)] };
}

/** The same, one face at a time: a caller can write each and let it go. */
export function* uniformFaces(S: Surface, N: number): Generator<FaceSamples> {
  if (!(Number.isInteger(N) && N >= 1 && N <= 4096)) throw new RangeError(`resolution ${N} must be an integer in 1..4096`);
  for (let f = 0; f < S.faceCount; f++) {
    const n = S.faceSize(f);
    if (!S.hasLimitSurface(f)) {
      yield { f, n, hole: true, sub: [] };
      continue;
    }
    const ev = S.faceEvaluator(f);
    const sub: SubFaceSamples[] = [];
    for (let k = 0; k < (n === 4 ? 1 : n); k++) {
      const P: number[] = new Array(3 * (N + 1) * (N + 1));
      const Nn: number[] = new Array(3 * (N + 1) * (N + 1));
      for (let j = 0; j <= N; j++) {
        for (let i = 0; i <= N; i++) {
          const r = ev.evaluate(k, i / N, j / N);
          const o = 3 * (j * (N + 1) + i);
          P[o] = r.P[0];
          P[o + 1] = r.P[1];
          P[o + 2] = r.P[2];
          Nn[o] = r.N[0];
          Nn[o + 1] = r.N[1];
          Nn[o + 2] = r.N[2];
        }
      }
      sub.push({ k, res: N, P, N: Nn });
    }
    yield { f, n, sub };
  }
}
