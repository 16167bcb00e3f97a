/**
 * The issue-10 error table: per cage and ACC scheme, the position error (/ bounding-box diagonal)
 * and normal error (degrees) against exact Catmull-Clark (src/subdiv) at the same (face, u, v),
 * max and RMS; control points stored per patch; and the across-edge position gap / normal jump.
 *
 *   npx tsx scripts/acc-errors.ts [samples per face, default 16]
 *
 * Cages: the notes' §5 test cages (cube and n-prisms after one CC step, on the notes' 9×9 dyadic
 * grid per face, to compare with the notes' numbers), the project's models, and the talk models
 * from ../shared/cages when present (read there, never copied). Cages a scheme refuses (n-gons,
 * boundaries) are listed with the reason.
 */
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { loadCage, type Cage } from '../src/mesh/index.ts';
import { ACC_SCHEMES, AccError, AccSurface, KIND_NAMES } from '../src/subdiv/acc.ts';
import { ExactAt, accErrors, ccStep, continuity, prism } from '../tests/acc-checks.ts';
import { cube, pentPrism } from '../tests/subdiv-fixtures.ts';
import { makeCage } from '../src/mesh/index.ts';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const perFace = Number(process.argv[2] ?? 16);

/** The notes' n-prism (unit circle, z = ±1, n-gon caps), as tests/subdiv-fixtures pentPrism. */
function flatPrism(n: number): Cage {
  if (n === 5) return pentPrism();
  const p: number[] = [];
  for (const z of [-1, 1]) for (let i = 0; i < n; i++) p.push(Math.cos((2 * Math.PI * i) / n), Math.sin((2 * Math.PI * i) / n), z);
  const f: number[][] = [[...Array(n).keys()].map((i) => n + i), [...Array(n).keys()].map((i) => n - 1 - i)];
  for (let i = 0; i < n; i++) f.push([i, (i + 1) % n, n + ((i + 1) % n), n + i]);
  return makeCage(p, f);
}

function grid9(cage: Cage): [number, number, number][] {
  const out: [number, number, number][] = [];
  for (let f = 0; f < cage.faceOffsets.length - 1; f++)
    for (let j = 0; j <= 8; j++) for (let i = 0; i <= 8; i++) out.push([f, i / 8, j / 8]);
  return out;
}

/** Per face: its corners and `n` random points (face-ordered, so the exact evaluator's cache works). */
function perFaceSamples(cage: Cage, n: number, seed = 3): [number, number, number][] {
  let s = seed;
  const rnd = () => (s = (s * 16807) % 2147483647) / 2147483647;
  const out: [number, number, number][] = [];
  for (let f = 0; f < cage.faceOffsets.length - 1; f++) {
    const tri = cage.faceOffsets[f + 1] - cage.faceOffsets[f] === 3;
    const corners = tri
      ? [
          [0, 0],
          [1, 0],
          [0, 1],
        ]
      : [
          [0, 0],
          [1, 0],
          [1, 1],
          [0, 1],
        ];
    for (const [u, v] of corners) out.push([f, u, v]);
    for (let i = 0; i < n; i++) {
      let u = rnd(),
        v = rnd();
      if (tri && u + v > 1) {
        u = 1 - u;
        v = 1 - v;
      }
      out.push([f, u, v]);
    }
  }
  return out;
}

const cages: { name: string; cage: () => Cage; grid: boolean }[] = [
  { name: 'cube (1 CC step)', cage: () => ccStep(cube()), grid: true },
  { name: 'pent. prism (1 CC step)', cage: () => ccStep(flatPrism(5)), grid: true },
  { name: 'hex. prism (1 CC step)', cage: () => ccStep(flatPrism(6)), grid: true },
  { name: 'oct. prism (1 CC step)', cage: () => ccStep(flatPrism(8)), grid: true },
  { name: 'wavy 8-prism (1 CC step)', cage: () => ccStep(prism(8)), grid: true },
];
for (const m of ['creature', 'torus', 'creased-box', 'icosphere', 'gear', 'pawn', 'sheet']) {
  cages.push({ name: m, cage: () => loadCage(readFileSync(join(root, 'public/models', `${m}.obj`), 'utf8')).cage, grid: false });
}
for (const m of ['suzanne', 'bigguy', 'monsterfrog', 'imrod']) {
  const p = join(root, '..', 'shared', 'cages', `${m}.obj`);
  if (existsSync(p)) cages.push({ name: `${m} (shared)`, cage: () => loadCage(readFileSync(p, 'utf8')).cage, grid: false });
}

const pct = (x: number) => `${(100 * x).toFixed(3)}%`;
console.log(
  `| cage | scheme | max pos | RMS pos | max normal | RMS normal | points/patch (quad, tri) | patch kinds | edge gap | edge normal jump | samples |`,
);
console.log(`|---|---|---|---|---|---|---|---|---|---|---|`);
for (const { name, cage: make, grid } of cages) {
  const cage = make();
  let refs: ReturnType<ExactAt['at']>[] | undefined;
  let params: [number, number, number][] = [];
  let exactMs = 0;
  for (const scheme of ACC_SCHEMES) {
    let S: AccSurface;
    try {
      S = new AccSurface(cage, scheme);
    } catch (e) {
      if (!(e instanceof AccError)) throw e;
      console.log(`| ${name} | ${scheme} | refused: ${e.message.replace(/^[a-z-]+: /, '').split(';')[0]} | | | | | | | | |`);
      continue;
    }
    if (!refs) {
      const t0 = performance.now();
      const exact = new ExactAt(cage);
      params = grid ? grid9(cage) : perFaceSamples(cage, perFace);
      refs = params.map(([f, u, v]) => exact.at(f, u, v));
      exactMs = performance.now() - t0;
    }
    const e = accErrors(S, refs, params);
    const T = S.topology;
    const kinds = new Map<number, number>();
    let quadPts = 0,
      quads = 0,
      triPts = 0,
      tris = 0;
    for (let f = 0; f < T.nPatches; f++) {
      const k = T.patches[2 * f];
      kinds.set(k, (kinds.get(k) ?? 0) + 1);
      const n = (f + 1 < T.nPatches ? T.patches[2 * f + 3] : T.nPoints) - T.patches[2 * f + 1];
      if (T.faceSize[f] === 4) {
        quadPts += n;
        quads++;
      } else {
        triPts += n;
        tris++;
      }
    }
    const c = continuity(S, undefined, 8);
    const kindText = [...kinds]
      .sort((a, b) => a[0] - b[0])
      .map(([k, n]) => `${KIND_NAMES[k]} ${n}`)
      .join(', ');
    const ppp = `${quads ? (quadPts / quads).toFixed(1) : '–'}, ${tris ? (triPts / tris).toFixed(0) : '–'}`;
    const warn = T.warnings.length ? ' (creases ignored)' : '';
    console.log(
      `| ${name}${warn} | ${scheme} | ${pct(e.maxP)} | ${pct(e.rmsP)} | ${e.maxN.toFixed(3)}° | ${e.rmsN.toFixed(3)}° | ${ppp} | ${kindText} | ${c.maxGap.toExponential(1)} | ${c.maxJumpDeg.toFixed(4)}° | ${e.samples}${e.nan ? ` (${e.nan} NaN)` : ''} |`,
    );
    if (scheme === 'pm-acc') console.error(`${name}: exact reference ${(exactMs / 1000).toFixed(1)} s`);
  }
}
