// Seeded hostile input for the CLIs' CPU stages, in-process: the issue's corpus as seeds, mutated
// (huge, tiny and non-finite numbers, huge faces and valences, truncation, binary noise, UTF-16,
// terminal escapes, hostile arguments). Every run must end done or refused as bad input (exit 0 or
// 2, a message, no trace, no raw control byte) within a time bound, and what subdiv writes must be
// finite, and no case may raise the process's peak memory by more than a budget (CASE_PEAK_MIB).
// Deterministic: one seed, a fixed number of cases.
import { describe, expect, it } from 'vitest';
import { decodeHeightPng, encodeHeightPng, HeightMapError } from '../../src/mesh/heightmap-png.ts';
import { heightMapFromFunction } from '../../src/mesh/index.ts';
import { assertHandled, fan, ngon, pattern, put, type Run, subdiv, tempDir, tessellateCpu } from '../support/hostile-cli.ts';

// TESSELLAB_FUZZ_SEED / TESSELLAB_FUZZ_CASES explore further by hand; CI runs the fixed ones.
const SEED = Number(process.env.TESSELLAB_FUZZ_SEED ?? 0x7e55e1a);
const CASES = Number(process.env.TESSELLAB_FUZZ_CASES ?? 150);
/** The slowest run allowed (a fuzz case is small: this is a hang detector, not a benchmark). */
const RUN_MS = 8000;
/**
 * Memory: a sync run cannot be sampled while it runs, and the heap's size after it depends on
 * when the GC ran, so a case is measured by its peak: the process's high-water resident size
 * (process.resourceUsage().maxRSS, which only rises) before and after it. A case that allocated
 * more than the peak so far raises it by about that much, garbage or not; one that stays under the
 * peak raises nothing. The largest rise on the fixed seed is ~20 MiB (a valence-90 vertex), and
 * the issue's failures were gigabytes (a 16384² PNG: 2.4 GB; a 10,000-gon in subdiv: past 6 GB),
 * so 256 MiB a case leaves GC timing and allocator noise a wide margin and still catches them.
 * The whole file's peak, from the test's start, is held under 1 GiB (the issue's 2 GB per run
 * halved): a leak across cases shows there. Vitest's default pool runs a test file in its own
 * process, so other files' memory is not counted.
 */
const CASE_PEAK_MIB = 256;
const FILE_PEAK_MIB = 1024;

/** MiB the process's peak resident size has risen since `peakKiB` (a maxRSS reading). */
function peakGrowthMiB(peakKiB: number): number {
  return (process.resourceUsage().maxRSS - peakKiB) / 1024;
}

/** mulberry32: small, seedable, good enough to pick mutations. */
function rng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const CUBE =
  'v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n' +
  'f 1/1 4/2 3/3 2/4\nf 5/1 6/2 7/3 8/4\nf 1/1 2/2 6/3 5/4\nf 2/1 3/2 7/3 6/4\nf 3/1 4/2 8/3 7/4\nf 4/1 1/2 5/3 8/4\n' +
  't crease 2/1/0 0 1 2.5\nt corner 1/1/0 6 3\n';
const SHEET =
  'v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 1\nv 2 1 0\nv 0 2 0\nv 1 2 0\nv 2 2 0\nf 1 2 5 4\nf 2 3 6 5\nf 4 5 8\nf 4 8 7\nf 5 6 9 8\n';
const SEEDS = [CUBE, SHEET, ngon(24), fan(40), `${CUBE}t hole 2/0/0 0 1\n`];

// Extreme values, and some ordinary ones so that a mutant is sometimes a working cage.
const NUMBERS = [
  '0.5',
  '2',
  '-3',
  '1e39',
  '1e308',
  '-1e308',
  '1e-300',
  '5e-324',
  'NaN',
  'inf',
  '-0',
  '0',
  '1e12',
  '1.5e12',
  '4294967296',
  '-1',
  '1e-13',
  '3.4e38',
];
const NOISE = [
  '\u001b[2J',
  '\u001b]0;title\u0007',
  '\u009b',
  '\u0000',
  '\uFFFD',
  '\u202e',
  '\\',
  '#',
  '/',
  '//',
  'f',
  'v',
  't',
  '\r',
  '\t',
];

type Mutation = (text: string, r: () => number) => string;
const pick = <T>(r: () => number, xs: readonly T[]): T => xs[Math.floor(r() * xs.length)];

const MUTATIONS: [string, Mutation][] = [
  // A number token (a coordinate, an index, a sharpness) swapped for an extreme one.
  [
    'number',
    (t, r) => {
      const hits = [...t.matchAll(/-?\d+(\.\d+)?(e-?\d+)?/g)];
      if (!hits.length) return t;
      const h = pick(r, hits);
      return t.slice(0, h.index) + pick(r, NUMBERS) + t.slice((h.index ?? 0) + h[0].length);
    },
  ],
  // Every coordinate scaled by an extreme factor.
  [
    'scale',
    (t, r) =>
      t.replace(
        /^v (.*)$/gm,
        (_, xyz: string) =>
          `v ${xyz
            .split(' ')
            .map((x) => `${x}${pick(r, ['e39', 'e-300', 'e11', 'e-20'])}`)
            .join(' ')}`,
      ),
  ],
  // A huge face (past the GPU build's 64 corners, past the loader's 1,024) or a huge valence (a fan
  // past a workgroup) appended. Sizes from a list: the CPU reference's time grows with their square.
  [
    'huge face',
    (t, r) =>
      `${t}\n${ngon(pick(r, [65, 200, 1025, 1500])).replace(
        /^f (.*)$/m,
        (_, c: string) =>
          `f ${c
            .split(' ')
            .map((i) => `${-Number(i)}`)
            .reverse()
            .join(' ')}`,
      )}`,
  ],
  ['huge valence', (t, r) => fan(pick(r, [64, 65, 150])) + t.replace(/^[vf] .*$/gm, '')],
  // Truncated at any byte.
  ['truncate', (t, r) => t.slice(0, Math.floor(r() * t.length))],
  // Binary noise and terminal escapes spliced in.
  [
    'noise',
    (t, r) => {
      const at = Math.floor(r() * t.length);
      const junk =
        r() < 0.5 ? pick(r, NOISE) : String.fromCharCode(...Array.from({ length: 1 + Math.floor(r() * 16) }, () => Math.floor(r() * 256)));
      return t.slice(0, at) + junk + t.slice(at);
    },
  ],
  // Lines duplicated, dropped or swapped (faces before vertices, repeated tags).
  [
    'lines',
    (t, r) => {
      const ls = t.split('\n');
      const i = Math.floor(r() * ls.length);
      const j = Math.floor(r() * ls.length);
      const op = r();
      if (op < 0.33) ls.splice(i, 0, ls[j]);
      else if (op < 0.66) ls.splice(i, 1);
      else [ls[i], ls[j]] = [ls[j], ls[i]];
      return ls.join('\n');
    },
  ],
];

/** The text as bytes: mostly UTF-8, sometimes UTF-16 with its BOM, or UTF-16 cut mid-character. */
function encode(text: string, r: () => number): Uint8Array {
  const x = r();
  if (x < 0.8) return new TextEncoder().encode(text);
  const units = new Uint8Array(Uint16Array.from([...text].map((c) => c.charCodeAt(0))).buffer);
  const le = new Uint8Array([0xff, 0xfe, ...units]);
  return x < 0.95 ? le : le.subarray(0, le.length - 1);
}

/** Arguments a user (or a script gone wrong) might give with the file. */
function tessellateArgs(model: string, out: string, map: string, r: () => number): string[] {
  // Half the runs ordinary, so the file's mutations reach the preparation, not only the argument checks.
  if (r() < 0.5) return [model, '--fixed', '2', '--surface', pick(r, ['catmull-clark', 'phong', 'gregory-acc']), '--out', out];
  const surface = pick(r, ['catmull-clark', 'phong', 'bezier-acc', 'gregory-acc', 'pm-acc', 'loop', '']);
  const mode = pick(r, [
    ['--fixed', pick(r, ['2', '64', '65', '0', 'NaN', '1e308'])],
    ['--adaptive', '--eye', pick(r, ['1,2,3', '1e39,0,0', '0,0,0', 'NaN,1,1', '1,2']), '--target', pick(r, ['0,0,0', '1e-300,0,0'])],
    ['--tessellator', 'instanced', '--level', pick(r, ['4', '3', '128'])],
  ]);
  const disp = r() < 0.25 ? ['--displacement', map, '--scale', pick(r, ['0.1', '1e308', '-1e12', 'NaN'])] : [];
  return [model, ...mode, ...(surface ? ['--surface', surface] : []), '--out', out, ...disp];
}

function subdivArgs(model: string, points: string, r: () => number): string[] {
  if (r() < 0.5) return r() < 0.5 ? ['--check', model] : ['--uniform', '1', model];
  return [
    ...pick(r, [['--check'], ['--uniform', pick(r, ['1', '2', '0', '4097'])], ['--refine', pick(r, ['1', '9'])], ['--points', points]]),
    model,
  ];
}

/** Hostile PNGs: a whole map with one byte flipped, cut short, or with its declared size changed. */
function hostilePng(r: () => number): Uint8Array {
  const png = encodeHeightPng(heightMapFromFunction(16, 8, r() < 0.5 ? 8 : 16, (u, v) => u * v)).slice();
  const x = r();
  if (x < 0.4) png[Math.floor(r() * png.length)] ^= 1 << Math.floor(r() * 8);
  else if (x < 0.7) return png.subarray(0, Math.floor(r() * png.length));
  else new DataView(png.buffer).setUint32(16 + 4 * Math.floor(r() * 2), pick(r, [0, 1, 65535, 16384, 2 ** 31]));
  return png;
}

function assertFiniteJson(run: Run, what: string): void {
  if (run.code !== 0 || !run.out.startsWith('{')) return;
  // JSON writes NaN and infinities as null; an undefined normal (a cone point) is the one null allowed.
  const parsed = JSON.parse(run.out) as { faces?: unknown; points?: { P: (number | null)[] }[] };
  // --check writes the face count; --uniform the faces' samples.
  const faces = Array.isArray(parsed.faces) ? (parsed.faces as { sub: { P: (number | null)[] }[] }[]) : [];
  for (const f of faces)
    for (const s of f.sub)
      expect(
        s.P.every((x) => typeof x === 'number' && Number.isFinite(x)),
        what,
      ).toBe(true);
  for (const p of parsed.points ?? [])
    expect(
      p.P.every((x) => typeof x === 'number' && Number.isFinite(x)),
      what,
    ).toBe(true);
}

describe(`hostile input, seeded (seed ${SEED.toString(16)}, ${CASES} cases)`, () => {
  it('every CLI run ends done or refused in words, in bounded time, with finite output', async () => {
    const r = rng(SEED);
    const dir = tempDir();
    const out = `${dir}/out.obj`;
    const tally = { done: 0, refused: 0 };
    const filePeak0 = process.resourceUsage().maxRSS;
    for (let c = 0; c < CASES; c++) {
      let text = pick(r, SEEDS);
      const applied: string[] = [];
      for (let m = 1 + Math.floor(r() * 2); m > 0; m--) {
        const [name, mutate] = pick(r, MUTATIONS);
        text = mutate(text, r);
        applied.push(name);
      }
      const model = put(dir, `case${c}.obj`, encode(text, r));
      const map = put(dir, `case${c}.png`, hostilePng(r));
      const points = put(
        dir,
        `case${c}.txt`,
        pick(r, ['0 0.5 0.5\n', '0 0 0.5 0.5\n', '1e308 0 0\n', 'NaN 0 0\n', '0 2 0.5\n', '\u001b[2J\n']),
      );
      const what = `case ${c} (${applied.join(', ')})`;
      const peak0 = process.resourceUsage().maxRSS;
      const runs: Run[] = [await tessellateCpu(...tessellateArgs(model, out, map, r)), subdiv(...subdivArgs(model, points, r))];
      for (const run of runs) {
        assertHandled(run, what);
        expect(run.ms, what).toBeLessThan(RUN_MS);
        assertFiniteJson(run, what);
        tally[run.code === 0 ? 'done' : 'refused']++;
      }
      expect(peakGrowthMiB(peak0), `${what}: MiB the process's peak memory rose by`).toBeLessThan(CASE_PEAK_MIB);
    }
    expect(peakGrowthMiB(filePeak0), "MiB the process's peak memory rose by over all cases").toBeLessThan(FILE_PEAK_MIB);
    if (process.env.TESSELLAB_FUZZ_SEED) console.log(tally, `peak memory +${peakGrowthMiB(filePeak0).toFixed(0)} MiB`);
    // The corpus must exercise both outcomes, or the mutations have stopped reaching the work.
    expect(tally.done).toBeGreaterThan(CASES / 4);
    expect(tally.refused).toBeGreaterThan(CASES / 4);
  });

  it('the pattern CLI and the PNG decoder: results or their own errors', () => {
    const r = rng(SEED + 1);
    const dir = tempDir();
    for (let c = 0; c < 120; c++) {
      const n = () => pick(r, ['1', '64', '65', '0', '-1', '1e308', 'NaN', '0.000063', '3.5', '', '1,2']);
      const argv = pick(r, [
        ['line', '--mode', pick(r, ['hable', 'integer', 'pow2', 'fractional_odd', 'x']), '--factor', n()],
        ['line', '--mode', 'hable', '--sweep', `${n()},${n()},${n()}`],
        ['tri', '--mode', pick(r, ['clamped', 'fractional_even', 'integer']), '--factors', `${n()},${n()},${n()}`, '--inside', n()],
        ['tri', '--mode', 'clamped', '--factors-file', put(dir, `f${c}.txt`, `${n()},${n()},${n()};${n()},0,1\n\u001b[2J\n`)],
        ['line', '--mode', 'hable', '--factor', '3', '--max-factor', n()],
      ]);
      const peak0 = process.resourceUsage().maxRSS;
      const run = pattern(...argv);
      assertHandled(run, argv.join(' '));
      expect(run.ms).toBeLessThan(RUN_MS);
      expect(peakGrowthMiB(peak0), argv.join(' ')).toBeLessThan(CASE_PEAK_MIB);
    }
    for (let c = 0; c < 200; c++) {
      const peak0 = process.resourceUsage().maxRSS;
      try {
        const map = decodeHeightPng(hostilePng(r));
        expect(map.width * map.height).toBe(map.data.length);
      } catch (e) {
        expect(e).toBeInstanceOf(HeightMapError);
      }
      expect(peakGrowthMiB(peak0), `PNG ${c}`).toBeLessThan(CASE_PEAK_MIB);
    }
  });
});
