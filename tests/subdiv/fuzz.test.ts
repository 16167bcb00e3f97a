// Throw thousands of mutated OBJ files at the loader (and the evaluator for
// whatever it accepts): every outcome must be a result or a CageError, quickly.
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { CageError, loadCage } from '../../src/mesh/index.ts';
import { Surface } from '../../src/subdiv/index.ts';

const SEED_FILES = [
  `v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nvt 0 0\nvn 0 0 1\n` +
    `f 5/1/1 6/1/1 7/1/1 8/1/1\nf 1 4 3 2\nf 1//1 2//1 6//1 5//1\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n` +
    `t crease 2/1/0 4 5 2.5\nt corner 1/1/0 6 10\nt hole 1/0/0 1\nt interpolateboundary 1/0/0 2\n`,
  `v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0.5\nv 1 1 1\nv 2 1 0\nv 0 2 0\nv 1 2 0.2\nv 2 2 0\n` +
    `f 1 2 5 4\nf 2 3 6 5\nf 4 5 8\nf 4 8 7\nf 5 6 9 8\nt crease 2/1/0 3 4 10\nt creasemethod 0/0/1 chaikin\n`,
  `v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 3 4\nf -4 -1 -3\nf 2 4 3 \\\n\n`,
];

const TOKENS = [
  'v',
  'vt',
  'vn',
  'f',
  't',
  'o',
  'g',
  's',
  '#',
  '\\',
  '/',
  '//',
  '-',
  '0',
  '1',
  '-1',
  '3',
  '99999999999',
  'nan',
  'inf',
  '1e999',
  '-0',
  '0.5',
  '1/1/1',
  '2//2',
  'crease',
  'corner',
  'hole',
  '2/1/0',
  '1/0/0',
  'chaikin',
  ' ',
  '\n',
  '\t',
  '\r\n',
  'x',
  '-2',
];

/** Mutations: delete / duplicate / swap lines, replace / insert tokens, truncate. */
const mutate = fc
  .tuple(
    fc.integer({ min: 0, max: SEED_FILES.length - 1 }),
    fc.array(fc.tuple(fc.integer({ min: 0, max: 6 }), fc.nat(), fc.nat(), fc.integer({ min: 0, max: TOKENS.length - 1 })), {
      minLength: 1,
      maxLength: 8,
    }),
  )
  .map(([s, ops]) => {
    let lines = SEED_FILES[s].split('\n');
    for (const [op, a, b, t] of ops) {
      const n = Math.max(1, lines.length);
      const i = a % n,
        j = b % n;
      switch (op) {
        case 0:
          lines.splice(i, 1);
          break;
        case 1:
          lines.splice(i, 0, lines[j] ?? '');
          break;
        case 2:
          [lines[i], lines[j]] = [lines[j] ?? '', lines[i] ?? ''];
          break;
        case 3: {
          const w = (lines[i] ?? '').split(' ');
          w[b % Math.max(1, w.length)] = TOKENS[t];
          lines[i] = w.join(' ');
          break;
        }
        case 4: {
          const w = (lines[i] ?? '').split(' ');
          w.splice(b % (w.length + 1), 0, TOKENS[t]);
          lines[i] = w.join(' ');
          break;
        }
        case 5:
          lines = lines.slice(0, i);
          break;
        default:
          lines[i] = (lines[i] ?? '').slice(0, b % 12);
          break;
      }
    }
    return lines.join('\n');
  });

function tryLoad(text: string): ReturnType<typeof loadCage> | null {
  try {
    return loadCage(text);
  } catch (e) {
    expect(e).toBeInstanceOf(CageError);
    const err = e as CageError;
    expect(err.issues.length).toBeGreaterThan(0);
    for (const i of err.issues) {
      expect(typeof i.message).toBe('string');
      expect(i.message.length).toBeGreaterThan(0);
      expect(Number.isInteger(i.line) && i.line >= 0).toBe(true);
    }
    return null;
  }
}

describe('fuzzing the cage loader', () => {
  it('never crashes or hangs on mutated files (and accepted cages evaluate)', () => {
    let accepted = 0;
    fc.assert(
      fc.property(mutate, (text) => {
        const t0 = performance.now();
        const r = tryLoad(text);
        if (r) {
          accepted++;
          const S = new Surface(r.cage, r.topology);
          const f = r.topology.nFaces - 1;
          if (S.hasLimitSurface(f)) {
            const p = S.evaluateSubFace(f, 0, 0.3, 0.6).P;
            expect(p.every((x) => Number.isFinite(x))).toBe(true);
            S.evaluateSubFace(f, 0, 0, 0);
          }
        }
        expect(performance.now() - t0).toBeLessThan(2000);
      }),
      { numRuns: 3000, seed: 20260 },
    );
    expect(accepted).toBeGreaterThan(50);
  });

  it('never crashes on random bytes', () => {
    fc.assert(
      fc.property(fc.string({ maxLength: 400 }), (s) => {
        tryLoad(s);
      }),
      { numRuns: 2000, seed: 7 },
    );
    fc.assert(
      fc.property(fc.array(fc.constantFrom(...TOKENS), { maxLength: 80 }), (toks) => {
        tryLoad(toks.join(' '));
      }),
      { numRuns: 2000, seed: 11 },
    );
  });

  it('handles huge indices, long lines and many continuations quickly', () => {
    const t0 = performance.now();
    tryLoad('v 0 0 0\n'.repeat(3) + 'f 1 2 ' + '3'.repeat(5000) + '\n');
    tryLoad('\\\n'.repeat(20000) + 'v 1 2 3\n');
    tryLoad('f ' + '1 '.repeat(20000) + '\n');
    tryLoad('v 0 0 0\n'.repeat(1000) + 'f ' + Array.from({ length: 1000 }, (_, i) => i + 1).join(' ') + '\n');
    expect(performance.now() - t0).toBeLessThan(5000);
  });
});
