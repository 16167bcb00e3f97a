/**
 * `npm run bench [-- --quick] [--models a,b] [--out BENCHMARKS.md]`: the compute tessellator per project model,
 * (`npm run bench -- --talk`: the talk's three tables at the talk's counts instead, bench/talk.ts)
 * at a fixed factor and adaptive, timed with GPU timestamps on whatever adapter Dawn finds
 * (SwiftShader here; a real GPU elsewhere). Prints a table and writes it to BENCHMARKS.md with
 * the machine it ran on.
 *
 * Absolute times mean little across machines, so the same run also times a trivial kernel that
 * only writes as many bytes as the pipeline's output, and reports the pipeline's efficiency as
 * the ratio of the two (the talk's pipeline reaches about 30 % of its GPU's write bound).
 * It also compares adaptive and fixed at the same bound (the fixed factor the adaptive rule needs at most).
 *
 * The Catmull-Clark table also takes the talk's four models (suzanne, bigguy, monsterfrog, imrod)
 * when ../shared/cages is present (third-party cages: read from there, never copied into the
 * project), and, where tools/osd-check/build-time.sh builds (g++ and libosd-dev), OpenSubdiv's
 * time for the same cage measured in the same run (tools/osd-check/osd_time.cpp), with the ratio.
 * --models limits both tables to the named models; with --models and no --out nothing is
 * written (a partial table must not replace BENCHMARKS.md).
 */
import { existsSync, readFileSync, writeFileSync, readdirSync } from 'node:fs';
import { guarded, InputError } from '../src/cli/boundary.ts';
import { checkOutputPath, readInputText } from '../src/cli/files.ts';
import { spawnSync } from 'node:child_process';
import { cpus, totalmem } from 'node:os';
import { createNodeDevice } from '../src/gpu/device/node-device.ts';
import { Tessellator } from '../src/gpu/tess/tessellator.ts';
import { prepareMesh, type PreparedMesh } from '../src/gpu/tess/prepare.ts';
import { headlessCamera, type HeadlessOptions } from '../src/gpu/tess/headless.ts';
import { readBuffer } from '../src/gpu/device/readback.ts';
import type { FactorParams } from '../src/gpu/contract/tessellated-mesh.ts';
import { adaptiveRuleOf } from '../src/gpu/tess/factors.ts';
import { phongEdgeFactors } from '../src/gpu/surface/phong.ts';
import { BYTES_PER_TRIANGLE, BYTES_PER_VERTEX } from '../src/gpu/tess/factors.ts';
import { bakeTables } from '../src/pattern/tables.ts';
import { faceCount, loadCage, type Cage } from '../src/mesh/index.ts';
import { buildCatmullClark, type CatmullClarkData } from '../src/gpu/cc/build.ts';
import { benchLightViewProj, timeDrawPasses } from './draw-timing.ts';
import { talkTables } from './talk.ts';
import { adapterNote, median, type Run, timeRebuild, timeTrivialWrite } from './timing.ts';
import { prepareAccSurface, type AccSurface as AccSurfaceData } from '../src/gpu/acc/surface.ts';
import { ACC_SCHEMES } from '../src/subdiv/acc.ts';
import { isAccSurface, SURFACE_SCHEMES, surfaceScheme, type SurfaceId } from '../src/gpu/surface/registry.ts';

/** The exact surface, every other column's yardstick (the registry's one exact limit). */
const EXACT = SURFACE_SCHEMES.find((s) => s.exactLimit)!.id;

const REPEATS = 5;

/** The talk's four models, third-party: read from here when present, never copied. */
const TALK_CAGES = '../shared/cages';
const TALK_MODELS = ['suzanne', 'bigguy', 'monsterfrog', 'imrod'];
/** A model whose Catmull-Clark preparation takes longer than this is left out of the table. */
const PREPARE_LIMIT_MS = 60_000;
/** Warm repeats of the CPU preparation (median reported). */
const PREPARE_REPEATS = 5;
/** OpenSubdiv runs per cage (median; cheap next to the rest). */
const OSD_REPEATS = 3;
/**
 * The one Catmull-Clark preparation call of the benchmark (CPU, topology only, per cage).
 * Throws for cages it cannot prepare (they are listed as left out).
 */
function prepareCatmullClark(cage: Cage, mesh: PreparedMesh): CatmullClarkData {
  return buildCatmullClark(cage, mesh);
}

interface OsdTiming {
  faces: number;
  samples: number;
  ms_load: number;
  ms_setup: number;
  ms_eval: number;
  ms_total: number;
  /** Far's refiner, adaptive refinement at isolation 2 and patch table with Gregory basis end caps. */
  ms_far: number;
  far_patches: number;
}

/** Build tools/osd-check/osd_time (g++ against libosd); its path, or why there is none. */
function buildOsdTimer(): { bin: string } | { reason: string } {
  const r = spawnSync('bash', ['tools/osd-check/build-time.sh'], { encoding: 'utf8' });
  if (r.status !== 0) {
    const why = (r.stderr || r.error?.message || '').trim().split('\n').slice(-1)[0];
    return { reason: `the OpenSubdiv timing program did not build (${why || `exit ${r.status}`}); is libosd-dev installed?` };
  }
  return { bin: r.stdout.trim().split('\n').slice(-1)[0] };
}

/** OpenSubdiv on the same cage in its own process: load, exact surfaces of every face and
 * evaluation at 9×9 samples per (sub-)face, timed in-process; median of `repeats` runs. */
function timeOpenSubdiv(bin: string, objPath: string, repeats: number): OsdTiming | string {
  const runs: OsdTiming[] = [];
  for (let i = 0; i < repeats; i++) {
    const r = spawnSync(bin, [objPath], { encoding: 'utf8', timeout: 120_000 });
    if (r.status !== 0) return `osd_time failed on ${objPath}: ${(r.stderr || r.error?.message || `exit ${r.status}`).trim()}`;
    runs.push(JSON.parse(r.stdout) as OsdTiming);
  }
  runs.sort((a, b) => a.ms_total - b.ms_total);
  return runs[Math.floor(runs.length / 2)];
}

/** The fixed factor that meets the adaptive rule's bound everywhere it applies: the largest factor
 * the rule (src/gpu/tess/factors.ts: the edge term and the bulge term of the edge's triangles, on the
 * Phong surface, as the bench's tessellator) gives any edge in this view. */
function fixedFactorForAdaptive(mesh: PreparedMesh, o: HeadlessOptions): number {
  const rule = adaptiveRuleOf(headlessCamera(mesh, o));
  let most = 1;
  for (const f of phongEdgeFactors(mesh, rule)) most = Math.max(most, f);
  return most;
}

export async function main(argv: string[]): Promise<number> {
  return guarded('bench', argv, run, (line) => console.error(line));
}

const BENCH_OPTIONS = new Set(['--quick', '--out', '--models', '--talk', '--repeats']);
const BENCH_FLAGS = new Set(['--quick', '--talk']);

async function run(argv: string[]): Promise<number> {
  // Arguments and the output path checked before the GPU is asked for.
  for (let i = 0; i < argv.length; i++) {
    if (!BENCH_OPTIONS.has(argv[i]))
      throw new InputError(`unknown argument ${argv[i]} (--quick, --models a,b, --out FILE; --talk [--repeats N])`);
    if (!BENCH_FLAGS.has(argv[i]) && (argv[++i] === undefined || argv[i].startsWith('--')))
      throw new InputError(`${argv[i - 1]} needs a value`);
  }
  if (argv.includes('--talk')) return talkTables(argv); // bench/talk.ts: the talk's tables at its counts
  const quick = argv.includes('--quick');
  const outIdx = argv.indexOf('--out');
  const modelsIdx = argv.indexOf('--models');
  const only =
    modelsIdx >= 0
      ? new Set(
          (argv[modelsIdx + 1] ?? '')
            .split(',')
            .map((m) => m.trim().replace(/\.obj$/, ''))
            .filter(Boolean),
        )
      : undefined;
  const outFile = outIdx >= 0 ? argv[outIdx + 1] : only ? undefined : 'BENCHMARKS.md';
  if (outFile) checkOutputPath(outFile, '--out');
  const fixedFactor = quick ? 8 : 16;
  const repeats = quick ? 2 : REPEATS;

  const models = readdirSync('public/models')
    .filter((f) => f.endsWith('.obj'))
    .sort()
    .filter((f) => !only || only.has(f.replace('.obj', '')));
  // The Catmull-Clark table: the project's models, then the talk's where ../shared is present.
  const ccModels: { name: string; path: string }[] = models.map((f) => ({ name: f.replace('.obj', ''), path: `public/models/${f}` }));
  if (existsSync(TALK_CAGES)) {
    for (const name of TALK_MODELS) {
      const path = `${TALK_CAGES}/${name}.obj`;
      if ((!only || only.has(name)) && existsSync(path)) ccModels.push({ name, path });
    }
  } else console.log(`note: ${TALK_CAGES} not found; the talk's four models are left out`);
  if (only) {
    const known = new Set(ccModels.map((m) => m.name));
    const unknown = [...only].filter((m) => !known.has(m));
    if (unknown.length) {
      throw new InputError(`unknown model(s) ${unknown.join(', ')}`);
    }
  }
  const { device, adapterName } = await createNodeDevice(['disable-dawn-features=timestamp_quantization']);
  if (!device.features.has('timestamp-query')) {
    console.error('bench: this adapter has no timestamp queries; nothing to measure');
    return 1;
  }
  const tess = Tessellator.create(device, bakeTables(64));
  const osd = buildOsdTimer();
  if ('reason' in osd) console.log(`note: no OpenSubdiv column: ${osd.reason}`);
  const rows: string[] = [];
  const lodScale = 4;
  const adaptive: HeadlessOptions = { mode: 'adaptive', lodScale };
  const header =
    '| model | cage tris | mode | out verts | out tris | bulge ms | factors + count + scan ms | plan ms | emit (weld included) ms | total ms | Mtris/ms | write-bound ms | efficiency |';
  const rule = '|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|';
  const equalError: string[] = [];
  console.log(header);
  console.log(rule);
  for (const file of models) {
    const cage = loadCage(readFileSync(`public/models/${file}`, 'utf8')).cage;
    const mesh = prepareMesh(cage);
    const runs: [string, HeadlessOptions][] = [
      [`fixed ${fixedFactor}`, { mode: 'fixed', fixedFactor }],
      [`adaptive (lod ${lodScale})`, adaptive],
    ];
    const measured: Record<string, Run> = {};
    for (const [label, o] of runs) {
      const r = await timeRebuild(device, tess, mesh, o, repeats);
      measured[label] = r;
      const bytes = r.vertices * BYTES_PER_VERTEX + r.triangles * BYTES_PER_TRIANGLE;
      const bound = await timeTrivialWrite(device, bytes, repeats);
      const s = r.stages;
      const row = `| ${file.replace('.obj', '')} | ${mesh.triangleCount} | ${label} | ${r.vertices} | ${r.triangles} | ${(s.factors ?? 0).toFixed(3)} | ${(s['count+budget'] ?? 0).toFixed(3)} | ${(s.plan ?? 0).toFixed(3)} | ${(s.tessellate ?? 0).toFixed(3)} | ${r.total.toFixed(3)} | ${(r.triangles / r.total / 1e6).toFixed(4)} | ${bound.toFixed(3)} | ${((100 * bound) / r.total).toFixed(1)} % |`;
      console.log(row);
      rows.push(row);
    }
    // The fixed factor that meets the adaptive rule's bound everywhere it applies.
    const F = fixedFactorForAdaptive(mesh, adaptive);
    const eq = await timeRebuild(device, tess, mesh, { mode: 'fixed', fixedFactor: F }, 1);
    const a = measured[`adaptive (lod ${lodScale})`];
    equalError.push(
      `| ${file.replace('.obj', '')} | ${F.toFixed(2)} | ${eq.vertices} | ${eq.triangles} | ${a.vertices} | ${a.triangles} | ${((100 * a.triangles) / eq.triangles).toFixed(0)} % |`,
    );
  }
  tess.destroy();

  // Every surface of the compute tessellator on the same cage at the same fixed factor: the
  // tessellation's stages (the patch builds apart: the exact surface's is timed, the ACC build
  // runs outside the tessellator's timed passes; BENCHMARKS.md's ACC section times it).
  const surfaceRows: string[] = [];
  const surfaceTess = new Map<string, Tessellator>();
  const surfaceOf = (surface: 'phong' | 'catmull-clark' | (typeof ACC_SCHEMES)[number]) => {
    let t = surfaceTess.get(surface);
    if (!t) surfaceTess.set(surface, (t = Tessellator.create(device, bakeTables(64), { surface, flatBaseline: false })));
    return t;
  };
  // Round-robin: one rebuild of every surface per round, medians over the rounds, so that a
  // shared machine's changing load falls on all of them alike.
  const rounds = Math.max(repeats, REPEATS);
  for (const file of models) {
    const cage = loadCage(readFileSync(`public/models/${file}`, 'utf8')).cage;
    const mesh = prepareMesh(cage);
    const cam = headlessCamera(mesh, { mode: 'fixed', fixedFactor });
    // Each surface on the cage it tessellates (an ACC scheme's after the Catmull-Clark steps its
    // n-gons or semi-sharp creases need, src/subdiv/acc.ts accCage), at the factor that keeps the
    // cage's edges cut as finely (halved per step: each step halves the edges).
    type Entry = {
      name: SurfaceId;
      tess: Tessellator;
      mesh: PreparedMesh;
      cam: FactorParams;
      steps: number;
      acc?: AccSurfaceData;
      samples: Record<string, number>[];
    };
    const entries: Entry[] = [];
    const refused = new Set<SurfaceId>();
    let ccData: CatmullClarkData | undefined;
    try {
      ccData = prepareCatmullClark(cage, mesh);
    } catch {
      refused.add(EXACT);
    }
    for (const name of ['phong', 'catmull-clark', ...ACC_SCHEMES] as const) {
      if (refused.has(name)) continue;
      let acc: AccSurfaceData | undefined;
      let own = { mesh, cam, steps: 0 };
      if (isAccSurface(name)) {
        try {
          const sc = surfaceScheme(name).surfaceCage(cage);
          if (sc.steps > 0) {
            const m = prepareMesh(sc.cage);
            own = {
              mesh: m,
              cam: headlessCamera(m, { mode: 'fixed', fixedFactor: Math.max(1, fixedFactor / 2 ** sc.steps) }),
              steps: sc.steps,
            };
          }
          acc = prepareAccSurface(device, sc.cage, own.mesh, name);
        } catch {
          refused.add(name);
          continue;
        }
      }
      entries.push({ name, tess: surfaceOf(name), acc, samples: [], ...own });
    }
    for (let round = 0; round < rounds + 1; round++) {
      for (const e of entries) {
        // Each tessellator holds one mesh at a time: set it again (CPU-side packing; not timed).
        e.tess.setMesh(e.mesh, surfaceScheme(e.name).patchBuild === 'refinement' ? ccData : undefined, e.acc);
        const enc = device.createCommandEncoder({ label: 'bench surface rebuild' });
        e.tess.encode(enc, e.cam);
        device.queue.submit([enc.finish()]);
        await device.queue.onSubmittedWorkDone(); // as timeRebuild: before the timestamp read's deadline starts
        const t = await e.tess.readTimings();
        if (round > 0) e.samples.push(t); // the first round warms up
      }
    }
    const ms: Record<string, { tess: number; build: number; tris: number; steps: number }> = {};
    for (const e of entries) {
      // Each surface has its own tessellator, whose last round above was this entry's rebuild.
      const tris = new Uint32Array(await readBuffer(device, e.tess.output.counts, 16))[1];
      const stages = Object.keys(e.samples[0] ?? {});
      const med = (k: string) => median(e.samples.map((x) => x[k] ?? 0));
      const build = stages.includes('subdivision') ? med('subdivision') : 0;
      ms[e.name] = { tess: stages.filter((k) => k !== 'subdivision').reduce((a, k) => a + med(k), 0), build, tris, steps: e.steps };
      e.acc?.patches.destroy();
    }
    const exact = ms[EXACT];
    const cell = (name: SurfaceId) => {
      const m = ms[name];
      if (!m) return 'refused';
      if (surfaceScheme(name).patchBuild === 'refinement') return `${m.tess.toFixed(3)} + ${m.build.toFixed(3)} build`;
      // On its own cage: the ratio per output triangle, and how many there were.
      const ratio = exact ? (m.tess / m.tris / (exact.tess / exact.tris)).toFixed(2) : undefined;
      const note = m.steps > 0 ? ` after ${m.steps} step${m.steps > 1 ? 's' : ''}: ${m.tris} tris` : '';
      return `${m.tess.toFixed(3)}${ratio ? ` (${ratio}×${m.steps > 0 ? ' per tri' : ''})` : ''}${note}`;
    };
    const row = `| ${file.replace('.obj', '')} | ${mesh.triangleCount} | ${ms.phong?.tris ?? '—'} | ${(['phong', 'catmull-clark', ...ACC_SCHEMES] as const).map(cell).join(' | ')} |`;
    console.log(row);
    surfaceRows.push(row);
  }
  for (const t of surfaceTess.values()) t.destroy();

  // Catmull-Clark: the talk's table (subdivision = the patch build from the cage, tessellation =
  // everything after it), and the draw passes per million triangles.
  const cc = Tessellator.create(device, bakeTables(64), { surface: 'catmull-clark' });
  const talk: string[] = [];
  const draws: string[] = [];
  const stageRows: string[] = [];
  const skipped: string[] = [];
  for (const { name, path } of ccModels) {
    const cage = loadCage(readInputText(path, 'model')).cage;
    const faces = faceCount(cage);
    const o = 'bin' in osd ? timeOpenSubdiv(osd.bin, path, OSD_REPEATS) : undefined;
    if (typeof o === 'string') console.log(`note: ${o}`);
    const osdMs = o && typeof o !== 'string' ? o.ms_total : undefined;
    const farMs = o && typeof o !== 'string' ? o.ms_far : undefined;
    const fmt = (x: number) => x.toFixed(x < 10 ? 2 : 1);
    const ratio = (a: number | undefined, b: number) => (a === undefined ? '—' : `${(a / b).toFixed(1)}×`);
    // OpenSubdiv's exact surfaces against the warm preparation; Far's adaptive patches against the
    // cold one (the cage's first call in this run; a user pays a fresh process's, which is more).
    const osdCells = (warmMs: number | undefined, coldMs?: number) =>
      osdMs === undefined || farMs === undefined
        ? '— | — | — | —'
        : `${fmt(osdMs)} | ${ratio(warmMs, osdMs)} | ${fmt(farMs)} | ${ratio(coldMs, farMs)}`;
    const mesh = prepareMesh(cage);
    const started = performance.now();
    let data: CatmullClarkData;
    try {
      data = prepareCatmullClark(cage, mesh);
    } catch (e) {
      const why = `${name}: Catmull-Clark preparation failed: ${(e as Error).message}`;
      console.log(`skipped ${why}`);
      skipped.push(why);
      talk.push(`| ${name} | ${faces} |${' — |'.repeat(11)} skipped | — | ${osdCells(undefined)} |`);
      console.log(talk[talk.length - 1]);
      continue;
    }
    const buildMs = performance.now() - started;
    if (buildMs > PREPARE_LIMIT_MS) {
      const why = `${name}: Catmull-Clark preparation took ${(buildMs / 1000).toFixed(0)} s (limit ${PREPARE_LIMIT_MS / 1000} s)`;
      console.log(`skipped ${why}`);
      skipped.push(why);
      talk.push(`| ${name} | ${faces} |${' — |'.repeat(11)} ${buildMs.toFixed(0)} | — | ${osdCells(buildMs, buildMs)} |`);
      console.log(talk[talk.length - 1]);
      continue;
    }
    // The first preparation above is cold (the JIT has not seen the code yet); the table reports
    // it and the median of PREPARE_REPEATS warm ones, and compares the warm one with OpenSubdiv.
    const warm: number[] = [];
    for (let i = 0; i < PREPARE_REPEATS; i++) {
      const t0 = performance.now();
      prepareCatmullClark(cage, mesh);
      warm.push(performance.now() - t0);
    }
    const warmMs = warm.sort((a, b) => a - b)[warm.length >> 1];
    const run = (o: HeadlessOptions) => timeRebuild(device, cc, mesh, o, repeats, data);
    const adaptiveRun = await run(adaptive);
    const fixedRun = await run({ mode: 'fixed', fixedFactor }); // last, so the draw passes see it
    const sub = fixedRun.stages.subdivision ?? 0;
    const tessMs = fixedRun.total - sub;
    talk.push(
      `| ${name} | ${faces} | ${fixedRun.triangles} | ${sub.toFixed(3)} | ${tessMs.toFixed(3)} | ${fixedRun.total.toFixed(3)} | ${(fixedRun.triangles / fixedRun.total / 1e6).toFixed(4)} | ${fixedRun.vertices} | ${adaptiveRun.vertices} | ${((100 * adaptiveRun.vertices) / fixedRun.vertices).toFixed(0)} % | ${fixedRun.triangles} | ${adaptiveRun.triangles} | ${((100 * adaptiveRun.triangles) / fixedRun.triangles).toFixed(0)} % | ${buildMs.toFixed(0)} / ${warmMs.toFixed(0)} | ${Math.round(data.gpuBytes / faces)} | ${osdCells(warmMs, buildMs)} |`,
    );
    const st = (k: string) => (fixedRun.stages[k] ?? 0).toFixed(3);
    stageRows.push(
      `| ${name} | ${fixedRun.triangles} | ${st('subdivision')} | ${st('factors')} | ${st('count+budget')} | ${st('plan')} | ${st('tessellate')} |`,
    );
    const cam = headlessCamera(mesh, { mode: 'fixed', fixedFactor });
    const { litMs, shadowMs } = await timeDrawPasses(device, cc.output, cam.viewProj, benchLightViewProj(mesh), repeats);
    const perM = 1e6 / fixedRun.triangles;
    draws.push(
      `| ${name} | ${fixedRun.triangles} | ${(fixedRun.total * perM).toFixed(2)} | ${(litMs * perM).toFixed(2)} | ${(shadowMs * perM).toFixed(2)} | ${((litMs + 4 * shadowMs) * perM).toFixed(2)} |`,
    );
    console.log(talk[talk.length - 1]);
  }
  cc.destroy();
  device.destroy();

  const osdNote =
    'bin' in osd
      ? `*OpenSubdiv ms* is OpenSubdiv (libosd) on the same cage in the same run, in its own process on the same machine
(tools/osd-check/osd_time.cpp, timed in-process, median of ${OSD_REPEATS}): reading the OBJ, the topology refiner and Bfr
surface factory, an exact \`Bfr::Surface<double>\` (approximation level 10) for every face, and 9×9 evaluations per
(sub-)face. *warm CPU prep / OpenSubdiv* is the ratio of the two CPU times (issue 9's target: ≤ 1). *Far adaptive ms*
is what an engine on OpenSubdiv's adaptive patches prepares once per topology, timed in the same program from the parsed
cage: \`Far::TopologyRefiner\`, \`RefineAdaptive\` at isolation level 2 and \`Far::PatchTableFactory\` with Gregory basis end
caps; *cold CPU prep / Far* sets the cage's first preparation in this run against it (issue 31's target, ≤ 1, is
for a fresh process, as \`npm run tessellate -- … --stats\` pays it; here the models before it have warmed the JIT).
`
      : `(No OpenSubdiv column: ${osd.reason})
`;
  const machine = `${cpus()[0]?.model ?? 'unknown CPU'} (${cpus().length} cores, ${(totalmem() / 2 ** 30).toFixed(0)} GiB)`;
  const doc = `# Benchmarks

Written by \`npm run bench\` on ${new Date().toISOString().slice(0, 10)}.

- **Adapter:** ${adapterName}
- **Machine:** ${machine}
- **Bytes per output:** ${BYTES_PER_VERTEX} per vertex (position, normal, barycentrics, source triangle), ${BYTES_PER_TRIANGLE} per triangle (indices).
- Times are GPU timestamps (Dawn, timestamp quantization off), medians of ${repeats} rebuilds after a warm-up. The camera is a three-quarter view framing the model, 1080 px high, 45° field of view.
- **write-bound ms** is a kernel that only writes the same number of bytes; **efficiency** = write-bound / total. ${adapterNote(adapterName)}

## Compute tessellation per model

${header}
${rule}
${rows.join('\n')}

## Tessellation per surface at matched factors

Every surface of the compute tessellator on the same cage, fixed factor ${fixedFactor} (so the same
pattern: the same output counts), tessellation ms (factors, counts, weld, emit with the surface
evaluated per vertex) and in brackets the ratio to exact Catmull-Clark's: medians of ${Math.max(repeats, REPEATS)} rounds
that rebuild every surface once each (round-robin, after a warm-up round). The patch builds are
apart: the exact surface's is given after its "+"; the ACC build runs outside the tessellator's
timed passes (its time is in the ACC section below). Flat baseline off. On SwiftShader only the
ratios mean anything. An ACC scheme tessellates the cage after the Catmull-Clark steps its n-gons or
semi-sharp creases need (src/subdiv/acc.ts accCage, as the demo does), at the factor halved per step; its
cell then says how many triangles that made, and its ratio is per output triangle. *refused*: the
scheme does not take the cage.

| model | cage tris | out tris | Phong ms | Catmull-Clark ms | Bezier ACC ms | Gregory ACC ms | Pm ACC ms |
|---|---:|---:|---:|---:|---:|---:|---:|
${surfaceRows.join('\n')}

## Catmull-Clark: the talk's table

The exact limit surface (flat baseline on, as in the demo). *subdivision* is the patch build
(control points and vertex limits from the cage positions, every frame for a deforming cage);
*tessellation* is everything after it (factors from the limit positions and normals, counts,
budget, weld, plan, emit with the surface evaluated per vertex). Fixed factor ${fixedFactor}; adaptive at
LOD ${lodScale}. *CPU prep ms* is the one-off CPU preparation per topology (src/gpu/cc/build.ts: topology only),
the first call and the median of ${PREPARE_REPEATS} more; *GPU bytes / face* is the subdivision data the GPU holds
(static words and the points, slices and limits the patch build writes) per cage face.
${osdNote}
| model | cage faces | out tris (fixed) | subdivision ms | tessellation ms | sub + tess ms | Mtris/ms | fixed verts | adaptive verts | adaptive / fixed | fixed tris | adaptive tris | adaptive / fixed | CPU prep ms (cold / warm) | GPU bytes / face | OpenSubdiv ms (same machine) | warm CPU prep / OpenSubdiv | Far adaptive ms | cold CPU prep / Far |
|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
${talk.join('\n')}
${skipped.length ? `\nLeft out: ${skipped.join('; ')}.\n` : ''}
## Catmull-Clark by stage

The same fixed-factor rebuilds as the talk's table, stage by stage (GPU ms, medians): where the
tessellation's time goes once the surface is the exact limit (emit evaluates it per vertex, the
weld's corner and edge vertices included; the bulge evaluates it at four points a triangle; the
factors read the vertex limits). The rebuild is one chain of dispatches whatever the budget:
bulge, factors + count + scan (two: the budget is chosen in the second), plan, emit (two), after the patch build's.

| model | out tris | subdivision | bulge | factors + count + scan | plan | emit (weld included) |
|---|---:|---:|---:|---:|---:|---:|
${stageRows.join('\n')}

## Drawing the stored mesh: ms per 1M triangles

Built once, drawn by every pass (the talk's point against re-tessellating per pass): a lit pass
(1920×1080, Lambert) and a depth-only shadow pass (2048²), both \`drawIndexedIndirect\` from the
tessellator's buffers, on the fixed-factor Catmull-Clark mesh.

| model | tris | build (sub + tess) per 1M | lit pass per 1M | shadow pass per 1M | lit + 4 shadows per 1M |
|---|---:|---:|---:|---:|---:|
${draws.join('\n')}

## Adaptive against fixed at the same bound

The adaptive rule (src/gpu/tess/factors.ts) asks for every visible edge's Phong chord error to be at most 1/${lodScale} px, counted for equal segments (Hable's line has longer ones inside an octave), and for as many segments as the surface's bulge inside each cage triangle on screen needs (the bulge term: sampled at four points, k = sqrt(10·lod·bulge px)); edges off screen, or facing away with no triangle on screen beside them, drop to factor 1. The fixed factor below is the largest the rule gives any edge in this view: the smallest fixed factor that meets the same bound everywhere.

| model | fixed factor for the same error | fixed verts | fixed tris | adaptive verts | adaptive tris | adaptive / fixed |
|---|---:|---:|---:|---:|---:|---:|
${equalError.join('\n')}
`;
  if (outFile) {
    // Sections written by other scripts (e.g. scripts/displacement-storage.ts) are kept as they are.
    const kept = existsSync(outFile)
      ? readFileSync(outFile, 'utf8')
          .split(/^(?=## )/m)
          .filter((sec) => sec.startsWith('## ') && !doc.includes(sec.split('\n')[0]))
      : [];
    writeFileSync(outFile, kept.length ? `${doc}\n${kept.join('').trimEnd()}\n` : doc);
    console.log(`\nwritten to ${outFile}`);
  } else console.log('\n--models without --out: nothing written');
  return 0;
}
