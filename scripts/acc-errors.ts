/**
 * The issue-10 error table: per cage and ACC scheme, the position error (/ bounding-box diagonal)
 * and normal error (degrees) against exact Catmull-Clark (src/subdiv) at the same (face, u, v),
 * max and RMS; control points stored per patch; and the across-edge position gap / normal jump.
 *
 *   node scripts/vite-run.mjs scripts/acc-errors.ts [samples per face, default 16] [--no-gpu] [--only=cube,torus]
 *
 * With a WebGPU adapter (Dawn; SwiftShader where there is no GPU: XDG_RUNTIME_DIR=/tmp
 * VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json) it also times the GPU patch build
 * (src/gpu/acc/patches.ts, wgsl/acc/build.wgsl) and, as a peer in the same run, the exact Catmull-Clark
 * patch build (src/gpu/tess/tessellator.ts encodePatchBuild): wall clock per build of 20 builds queued in
 * one submission, median of 5, after a warm-up. On SwiftShader only the ratio means anything.
 *
 * Cages: the test cages of tests/gpu/acc/acc.test.ts (cube and n-prisms after one CC step, on a 9×9
 * dyadic grid per face, to compare with the reference errors measured for this project there), the
 * project's models, and the talk models from ../shared/cages when present (read there, never
 * copied). Each scheme takes the cage as the demo gives it (src/subdiv/acc.ts accCage: the
 * Catmull-Clark steps its n-gons or semi-sharp creases need; the limit is the same, so the exact
 * reference is evaluated on that cage too, at a quarter of the samples per face per step: the
 * same samples per cage face). Cages a scheme refuses are listed with the reason. The normal jump
 * is over smooth edges (creases may jump).
 */
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { loadCage, type Cage } from '../src/mesh/index.ts';
import { ACC_SCHEMES, AccError, KIND_NAMES, accCage } from '../src/subdiv/acc.ts';
import { AccSurface } from '../src/subdiv/acc-evaluate.ts';
import { ExactAt, accErrors, ccStep, continuity, prism, smoothEdges } from '../tests/support/acc-checks.ts';
import { AccPatches } from '../src/gpu/acc/patches.ts';
import { Tessellator } from '../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../src/gpu/tess/prepare.ts';
import { buildCatmullClark } from '../src/gpu/cc/build.ts';
import { bakeTables } from '../src/pattern/tables.ts';
import { createNodeDevice } from '../src/gpu/device/node-device.ts';
import { cube, pentPrism } from '../tests/support/subdiv-fixtures.ts';
import { makeCage } from '../src/mesh/index.ts';

// The repository root: where it is run from (npm scripts and bench/gpu/run.sh run it there; a
// bundled copy cannot find it from its own path).
const root = process.cwd();
let perFace = 16;
let useGpu = true;

const REPS = 20,
  ROUNDS = 5;
/** Milliseconds per encoded build: REPS builds in one submission, median of ROUNDS, after a warm-up. */
async function wallMs(device: GPUDevice, encode: (enc: GPUCommandEncoder) => void): Promise<number> {
  const ms: number[] = [];
  for (let r = 0; r <= ROUNDS; r++) {
    const enc = device.createCommandEncoder({ label: 'acc-errors timing' });
    for (let i = 0; i < (r ? REPS : 1); i++) encode(enc);
    const t0 = performance.now();
    device.queue.submit([enc.finish()]);
    await device.queue.onSubmittedWorkDone();
    if (r) ms.push((performance.now() - t0) / REPS);
  }
  return ms.sort((a, b) => a - b)[Math.floor(ms.length / 2)];
}

let gpu: { device: GPUDevice; adapterName: string; cc: Tessellator } | undefined;

/** GPU patch-build ms of the exact Catmull-Clark peer for this cage, or why there is none. */
async function ccBuildMs(cage: Cage): Promise<number | string> {
  if (!gpu) return 'no GPU';
  try {
    const mesh = prepareMesh(cage);
    gpu.cc.setMesh(mesh, buildCatmullClark(cage, mesh));
    return await wallMs(gpu.device, (enc) => gpu!.cc.encodePatchBuild(enc));
  } catch (e) {
    return (e as Error).message.split('\n')[0].slice(0, 60);
  }
}

/** GPU patch-build ms of an ACC scheme (its own cage buffer, as the tessellator's: xyz f32). */
async function accBuildMs(cage: Cage, scheme: (typeof ACC_SCHEMES)[number]): Promise<number | undefined> {
  if (!gpu) return undefined;
  const device = gpu.device;
  const patches = new AccPatches(device, cage, scheme);
  const f = Float32Array.from(cage.positions);
  const buf = device.createBuffer({
    label: 'acc-errors cage',
    size: Math.max(16, f.byteLength),
    usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
  });
  device.queue.writeBuffer(buf, 0, f);
  const ms = await wallMs(device, (enc) => patches.encode(enc, buf));
  patches.destroy();
  buf.destroy();
  return ms;
}
const fmtMs = (x: number) => (x < 1 ? x.toFixed(3) : x.toFixed(2));

/** The n-prism (unit circle, z = ±1, n-gon caps), as tests/subdiv-fixtures pentPrism. */
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
/** Entry point for scripts/vite-run.mjs: prints the markdown table; the return value is the exit code. */
export async function main(argv: string[]): Promise<number> {
  perFace = Number(argv.find((a) => /^\d+$/.test(a)) ?? 16);
  useGpu = !argv.includes('--no-gpu');
  const only = argv.find((a) => a.startsWith('--only='))?.slice(7);
  if (useGpu) {
    try {
      const { device, adapterName } = await createNodeDevice();
      gpu = { device, adapterName, cc: Tessellator.create(device, bakeTables(64), { surface: 'catmull-clark' }) };
      console.error(`GPU: ${adapterName}`);
    } catch (e) {
      console.error(`no GPU timing: ${(e as Error).message}`);
    }
  }
  console.log(
    `| cage | scheme | max pos | RMS pos | max normal | RMS normal | points/patch (quad, tri) | patch kinds | edge gap | smooth-edge normal jump | samples | build ms (GPU) | exact CC build ms (same run) |`,
  );
  console.log(`|---|---|---|---|---|---|---|---|---|---|---|---|---|`);
  for (const { name, cage: make, grid } of cages) {
    if (only && !only.split(',').some((o) => name.startsWith(o))) continue;
    const given = make();
    const steps = accCage(given);
    const cage = steps.cage;
    let refs: ReturnType<ExactAt['at']>[] | undefined;
    let params: [number, number, number][] = [];
    let exactMs = 0;
    let ccMs: number | string | undefined;
    for (const scheme of ACC_SCHEMES) {
      let S: AccSurface;
      try {
        S = new AccSurface(cage, scheme);
      } catch (e) {
        if (!(e instanceof AccError)) throw e;
        console.log(`| ${name} | ${scheme} | refused: ${e.message.replace(/^[a-z-]+: /, '').split(';')[0]} | | | | | | | | | | |`);
        continue;
      }
      if (!refs) {
        const t0 = performance.now();
        const exact = new ExactAt(cage);
        params = grid ? grid9(cage) : perFaceSamples(cage, Math.max(1, Math.round(perFace / 4 ** steps.steps)));
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
      const c = continuity(S, undefined, 8, smoothEdges(cage, 1)); // semi-sharp σ ≥ 1 is built sharp
      const accMs = await accBuildMs(cage, scheme);
      ccMs ??= await ccBuildMs(given); // the exact surface builds on the cage itself
      const ccCell = typeof ccMs === 'number' ? fmtMs(ccMs) : `— (${ccMs})`;
      const accCell = accMs === undefined ? '—' : `${fmtMs(accMs)}${typeof ccMs === 'number' ? ` (${(accMs / ccMs).toFixed(2)}×)` : ''}`;
      const kindText = [...kinds]
        .sort((a, b) => a[0] - b[0])
        .map(([k, n]) => `${KIND_NAMES[k]} ${n}`)
        .join(', ');
      const ppp = `${quads ? (quadPts / quads).toFixed(1) : '–'}, ${tris ? (triPts / tris).toFixed(0) : '–'}`;
      const notes = [];
      if (steps.steps > 0) notes.push(`after ${steps.steps} Catmull-Clark step${steps.steps > 1 ? 's' : ''}`);
      if (T.warnings.some((w) => w.includes('semi-sharp'))) notes.push('semi-sharp: σ ≥ 1 built sharp');
      if (T.warnings.some((w) => w.includes('valence 2'))) notes.push('valence-2 vertices');
      const warn = notes.length ? ` (${notes.join('; ')})` : '';
      console.log(
        `| ${name}${warn} | ${scheme} | ${pct(e.maxP)} | ${pct(e.rmsP)} | ${e.maxN.toFixed(3)}° | ${e.rmsN.toFixed(3)}° | ${ppp} | ${kindText} | ${c.maxGap.toExponential(1)} | ${c.maxJumpDeg.toFixed(4)}° | ${e.samples}${e.nan ? ` (${e.nan} NaN)` : ''} | ${accCell} | ${ccCell} |`,
      );
      if (scheme === ACC_SCHEMES.at(-1)) console.error(`${name}: exact reference ${(exactMs / 1000).toFixed(1)} s`);
    }
  }
  if (gpu) {
    gpu.cc.destroy();
    gpu.device.destroy();
  }
  return 0;
}
