/**
 * Compares src/pattern/d3d11.ts with the D3D11 reference tessellator's golden output, point for
 * point and index for index.
 *
 *   npm run check:golden -- [dir]     (default: ../shared/golden, relative to the repo root)
 *
 * Exit status: 0 all cases match, 1 any mismatch, 2 the directory or a golden file is missing.
 * Run by CI, not by `npm test` (a fresh clone has no ../shared).
 */
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { d3d11Line, d3d11Triangle, d3d11TriCounts } from '../src/pattern/d3d11';
import { ONE } from '../src/pattern/fixed';
import { D3D11_PARTITIONINGS, type D3D11Partitioning } from '../src/pattern/types';

type Factor = number | string;

interface LineCase {
  family: string;
  partitioning: string;
  factor: Factor;
  points: number[];
}

interface TriCase {
  family: string;
  partitioning: string;
  factors: [Factor, Factor, Factor];
  inside: Factor;
  points: [number, number, number][];
  triangles: [number, number, number][];
  vertexCount: number;
  triangleCount: number;
}

const repoRoot = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const dir = process.argv[2] ? resolve(process.cwd(), process.argv[2]) : join(repoRoot, '../shared/golden');
const lineFile = join(dir, 'd3d11-line.json');
const triFile = join(dir, 'd3d11-tri.json');

if (!existsSync(dir) || !existsSync(lineFile) || !existsSync(triFile)) {
  console.error(`golden: directory ${dir} (with d3d11-line.json and d3d11-tri.json) not found`);
  process.exit(2);
}

/** Non-finite factors are stored as strings. */
function factorValue(f: Factor): number {
  if (typeof f === 'number') return f;
  if (f === 'NaN') return NaN;
  if (f === 'Infinity') return Infinity;
  if (f === '-Infinity') return -Infinity;
  throw new Error(`unknown factor ${JSON.stringify(f)}`);
}

function partitioningOf(p: string): D3D11Partitioning {
  if ((D3D11_PARTITIONINGS as readonly string[]).includes(p)) return p as D3D11Partitioning;
  throw new Error(`unknown partitioning ${p}`);
}

/** Golden doubles are exact multiples of 2^-16; scaled to fixed point (a value that is not
 * stays fractional, so it can never match and shows up as is). */
const toFixed = (t: number) => t * ONE;

const MAX_DETAILS = 5;
const details: string[] = [];
const note = (s: string) => {
  if (details.length < MAX_DETAILS) details.push(s);
};

/** First index where two arrays differ, or -1. */
function firstDiff(a: readonly number[], b: readonly number[]): number {
  const n = Math.max(a.length, b.length);
  for (let i = 0; i < n; i++) if (a[i] !== b[i]) return i;
  return -1;
}

const lines = JSON.parse(readFileSync(lineFile, 'utf8')) as LineCase[];
let lineOk = 0;
for (const c of lines) {
  const p = partitioningOf(c.partitioning);
  const got = d3d11Line(p, factorValue(c.factor)).x;
  const want = c.points.map(toFixed);
  const i = firstDiff(got, want);
  if (i < 0) {
    lineOk++;
    continue;
  }
  note(
    `line ${c.family} ${p} f=${c.factor}: ${got.length} points, expected ${want.length}; ` +
      `first difference at [${i}]: got ${got[i]}, expected ${want[i]}\n` +
      `    got      ${got.join(' ')}\n    expected ${want.join(' ')}`,
  );
}

const tris = JSON.parse(readFileSync(triFile, 'utf8')) as TriCase[];
let triOk = 0;
for (const c of tris) {
  const p = partitioningOf(c.partitioning);
  const factors = c.factors.map(factorValue) as [number, number, number];
  const inside = factorValue(c.inside);
  const got = d3d11Triangle(p, factors, inside);
  const counts = d3d11TriCounts(p, factors, inside);
  const label = `tri ${c.family} ${p} (${c.factors.join(', ')}) / ${c.inside}`;
  const problems: string[] = [];
  if (got.vertexCount !== c.vertexCount || got.triangleCount !== c.triangleCount) {
    problems.push(`counts ${got.vertexCount}/${got.triangleCount}, expected ${c.vertexCount}/${c.triangleCount}`);
  }
  if (counts.vertexCount !== c.vertexCount || counts.triangleCount !== c.triangleCount) {
    problems.push(`closed form ${counts.vertexCount}/${counts.triangleCount}, expected ${c.vertexCount}/${c.triangleCount}`);
  }
  const wantBary = c.points.flat().map(toFixed);
  const pi = firstDiff(got.bary, wantBary);
  if (pi >= 0) {
    const v = Math.floor(pi / 3);
    problems.push(
      `point ${v}: got (${got.bary.slice(3 * v, 3 * v + 3).join(', ')}), ` + `expected (${wantBary.slice(3 * v, 3 * v + 3).join(', ')})`,
    );
  }
  const wantTris = c.triangles.flat();
  const ti = firstDiff(got.triangles, wantTris);
  if (ti >= 0) {
    const t = Math.floor(ti / 3);
    problems.push(
      `triangle ${t}: got [${got.triangles.slice(3 * t, 3 * t + 3).join(', ')}], ` +
        `expected [${wantTris.slice(3 * t, 3 * t + 3).join(', ')}]`,
    );
  }
  if (problems.length === 0) triOk++;
  else note(`${label}: ${problems.join('; ')}`);
}

console.log(`golden: ${lineOk}/${lines.length} line cases, ${triOk}/${tris.length} triangle cases match`);
if (details.length > 0) {
  console.log(`first mismatches:\n  ${details.join('\n  ')}`);
}
process.exit(lineOk === lines.length && triOk === tris.length ? 0 : 1);
