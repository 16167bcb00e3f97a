/**
 * `npm run bench -- --talk [--repeats N] [--models a,b] [--out BENCHMARKS.md]`: the talk's three
 * tables at the talk's triangle counts, this project's measured rows beside the talk's figures
 * (Hable, SIGGRAPH 2026, RTX 3070), on whatever adapter Dawn finds:
 *
 *   (a) "Compute cost only": the exact Catmull-Clark surface at the talk's counts (bigguy and
 *       monsterfrog at fixed 64, imrod at 39, suzanne at 128): output triangles, subdivision
 *       (the patch build), tessellation (everything after it), sub + tess, M triangles per ms, and
 *       the write-only kernel's time for the same output bytes with the efficiency against it;
 *   (b) "Cost per pass, ms per 1M triangles" on bigguy and monsterfrog: compute once, the first
 *       lit render, each shadow pass, 1 lit, 1 lit + 4 shadows (the build included, as in the
 *       talk's row), beside the per-pass peer, the instanced tessellator on the exact surface at
 *       level 64, which evaluates it again in every pass (as OpenSubdiv does with hardware
 *       tessellation);
 *   (c) "Comparison: Uniform" in M triangles per ms, the talk's Edge-Friend and DV21 figures
 *       quoted beside this project's;
 *   (d) the exact surface's tessellation against the Phong surface's at fixed 16, both measured
 *       here in the same run: what evaluating the exact limit costs over the cheapest surface.
 *
 * Third-party cages: read from ../shared/cages, never copied. Writes its own section of
 * BENCHMARKS.md (kept by `npm run bench`); the talk-scale runs live here, not in CI.
 */
import { existsSync, readFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { createNodeDevice } from '../src/gpu/device/node-device.ts';
import { Tessellator } from '../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../src/gpu/tess/prepare.ts';
import { headlessCamera } from '../src/gpu/tess/headless.ts';
import { BYTES_PER_TRIANGLE, BYTES_PER_VERTEX } from '../src/gpu/tess/factors.ts';
import { bakeTables } from '../src/pattern/tables.ts';
import { MAX_FACTOR } from '../src/pattern/max-factor.ts';
import { POW2_LEVELS } from '../src/pattern/pow2.ts';
import { loadCage } from '../src/mesh/index.ts';
import { buildCatmullClark } from '../src/gpu/cc/build.ts';
import { InstancedTessellator } from '../src/gpu/instanced/instanced.ts';
import { prepareInstanced } from '../src/gpu/instanced/prepare-patches.ts';
import { ccSurfaceTessellator } from '../src/gpu/instanced/surface-cc.ts';
import { surfaceScheme } from '../src/gpu/surface/registry.ts';
import { benchLightViewProj, timeDrawPasses } from './draw-timing.ts';
import { timeInstanced } from './instanced.ts';
import { adapterNote, timeRebuild, timeTrivialWrite, writeSection } from './timing.ts';

export const TALK_SECTION = "## The talk's tables at the talk's counts";

/** The talk's models, the fixed factor that reaches its count, and its figures (RTX 3070). */
const TALK = [
  { name: 'suzanne', factor: MAX_FACTOR, tris: 15.9e6, sub: 0.037, tess: 3.368, edgeFriend: 6.69, dv21: 2.22 },
  { name: 'bigguy', factor: 64, tris: 11.9e6, sub: 0.025, tess: 2.171, edgeFriend: 8.03, dv21: 2.21 },
  { name: 'monsterfrog', factor: 64, tris: 10.6e6, sub: 0.028, tess: 2.014, edgeFriend: 6.87, dv21: 2.24 },
  { name: 'imrod', factor: 39, tris: 14.2e6, sub: 0.139, tess: 3.243, edgeFriend: 7.05, dv21: 2.2 },
] as const;
/** The talk's "cost per pass" (ms per 1M triangles), quoted as it gives them: adaptive compute
 * (once, first lit, each shadow, 1 lit, 1 lit + 4 shadows), then OpenSubdiv (a pass, 1 lit + 4). */
const TALK_PER_PASS = {
  bigguy: { once: 0.18, lit: 0.18, shadow: 0.11, lit1: 0.36, lit4: 0.82, osd: 0.5, osd4: 2.51 },
  monsterfrog: { once: 0.19, lit: 0.18, shadow: 0.12, lit1: 0.37, lit4: 0.85, osd: 0.51, osd4: 2.57 },
} as const;
const CAGES = '../shared/cages';
/** The fixed factor of table (d). */
const PHONG_FACTOR = 16;
/** Rounds of the exact-against-Phong table (d), each surface's fastest kept. */
const AGAINST_PHONG_ROUNDS = 5;

function option(argv: string[], name: string): string | undefined {
  const i = argv.indexOf(name);
  return i >= 0 ? argv[i + 1] : undefined;
}

export async function talkTables(argv: string[]): Promise<number> {
  if (!existsSync(CAGES)) {
    console.error(`bench --talk: ${CAGES} not found (the talk's cages are third-party and not in the project)`);
    return 2;
  }
  const only = option(argv, '--models')?.split(',').filter(Boolean);
  const repeats = Number(option(argv, '--repeats') ?? 2);
  const outFile = option(argv, '--out') ?? (only ? undefined : 'BENCHMARKS.md');
  const { device, adapterName } = await createNodeDevice(['disable-dawn-features=timestamp_quantization']);
  if (!device.features.has('timestamp-query')) {
    console.error('bench --talk: this adapter has no timestamp queries; nothing to measure');
    return 1;
  }
  const capacity = 1 << 24; // 16.7 M vertices and triangles: the talk's largest count fits
  const cc = Tessellator.create(device, bakeTables(MAX_FACTOR), {
    surface: 'catmull-clark',
    vertexCapacity: capacity,
    triangleCapacity: capacity,
  });
  const phong = Tessellator.create(device, bakeTables(MAX_FACTOR), {
    surface: 'phong',
    vertexCapacity: 1 << 22,
    triangleCapacity: 1 << 22,
  });
  const instanced = new InstancedTessellator(device, { surface: surfaceScheme('catmull-clark').instancedKind });
  const level = POW2_LEVELS[POW2_LEVELS.length - 1];
  const compute: string[] = [];
  const perPass: string[] = [];
  const uniform: string[] = [];
  const againstPhong: string[] = [];
  for (const t of TALK.filter((m) => !only || only.includes(m.name))) {
    const cage = loadCage(readFileSync(`${CAGES}/${t.name}.obj`, 'utf8')).cage;
    const mesh = prepareMesh(cage);
    const data = buildCatmullClark(cage, mesh);
    const run = await timeRebuild(device, cc, mesh, { mode: 'fixed', fixedFactor: t.factor }, repeats, data);
    const sub = run.stages.subdivision ?? 0;
    const tess = run.total - sub;
    const bound = await timeTrivialWrite(device, run.vertices * BYTES_PER_VERTEX + run.triangles * BYTES_PER_TRIANGLE, repeats);
    const rate = run.triangles / run.total / 1e6;
    const talkRate = t.tris / (t.sub + t.tess) / 1e6;
    compute.push(
      `| ${t.name} | ${(t.tris / 1e6).toFixed(1)} M | ${t.sub.toFixed(3)} | ${t.tess.toFixed(3)} | ${(t.sub + t.tess).toFixed(3)} | ${talkRate.toFixed(2)} | ${t.factor} | ${(run.triangles / 1e6).toFixed(2)} M | ${sub.toFixed(3)} | ${tess.toFixed(3)} | ${run.total.toFixed(3)} | ${rate.toPrecision(3)} | ${bound.toFixed(3)} | ${((100 * bound) / run.total).toFixed(1)} % |`,
    );
    uniform.push(`| ${t.name} | ${t.edgeFriend.toFixed(2)} | ${talkRate.toFixed(2)} | ${t.dv21.toFixed(2)} | ${rate.toPrecision(3)} |`);
    console.log(compute[compute.length - 1]);
    // (d): tessellation only (the exact surface's patch build is its own column above). The two
    // surfaces in turn, AGAINST_PHONG_ROUNDS times, each surface's fastest round: on SwiftShader a
    // round's median moves by 5-20 % with the machine's other work, and in turn both see the same.
    let exactTess = Infinity,
      phongTess = Infinity,
      tris = 0;
    for (let round = 0; round < AGAINST_PHONG_ROUNDS; round++) {
      const exact16 = await timeRebuild(device, cc, mesh, { mode: 'fixed', fixedFactor: PHONG_FACTOR }, repeats, data);
      const phong16 = await timeRebuild(device, phong, mesh, { mode: 'fixed', fixedFactor: PHONG_FACTOR }, repeats);
      exactTess = Math.min(exactTess, exact16.total - (exact16.stages.subdivision ?? 0));
      phongTess = Math.min(phongTess, phong16.total);
      tris = exact16.triangles;
    }
    againstPhong.push(
      `| ${t.name} | ${(tris / 1e6).toFixed(2)} M | ${exactTess.toFixed(3)} | ${phongTess.toFixed(3)} | ${(exactTess / phongTess).toFixed(2)} |`,
    );
    console.log(againstPhong[againstPhong.length - 1]);
    const talkPass = TALK_PER_PASS[t.name as keyof typeof TALK_PER_PASS];
    if (talkPass) {
      const cam = headlessCamera(mesh, { mode: 'fixed', fixedFactor: t.factor });
      const draw = await timeDrawPasses(device, cc.output, cam.viewProj, benchLightViewProj(mesh), repeats, 'none');
      const source = ccSurfaceTessellator(device, mesh, data);
      instanced.setMesh(prepareInstanced(cage, mesh), source);
      const peer = await timeInstanced(device, instanced, mesh, { mode: 'static', level }, repeats);
      source.destroy();
      const perM = (ms: number, tris: number) => ((ms * 1e6) / tris).toFixed(3);
      const n = run.triangles;
      // Compute: built once a frame, then every pass draws the stored mesh. Instanced: its level
      // pass and the patch build once, then every pass evaluates the surface again.
      const peerOnce = peer.buildMs + sub;
      perPass.push(
        `| ${t.name} | talk: adaptive compute (RTX 3070) | ${(t.tris / 1e6).toFixed(1)} M | ${talkPass.once} | ${talkPass.lit} | ${talkPass.shadow} | ${talkPass.lit1} | ${talkPass.lit4} |`,
        `| ${t.name} | talk: OpenSubdiv, hardware tessellation (RTX 3070) | ${(t.tris / 1e6).toFixed(1)} M | 0 | ${talkPass.osd} | ${talkPass.osd} | ${talkPass.osd} | ${talkPass.osd4} |`,
        `| ${t.name} | compute, factor ${t.factor} | ${(n / 1e6).toFixed(2)} M | ${perM(run.total, n)} | ${perM(draw.litMs, n)} | ${perM(draw.shadowMs, n)} | ${perM(run.total + draw.litMs, n)} | ${perM(run.total + draw.litMs + 4 * draw.shadowMs, n)} |`,
        `| ${t.name} | instanced, level ${level} (per pass) | ${(peer.triangles / 1e6).toFixed(2)} M | ${perM(peerOnce, peer.triangles)} | ${perM(peer.litMs, peer.triangles)} | ${perM(peer.shadowMs, peer.triangles)} | ${perM(peerOnce + peer.litMs, peer.triangles)} | ${perM(peerOnce + peer.litMs + 4 * peer.shadowMs, peer.triangles)} |`,
      );
      for (const r of perPass.slice(-2)) console.log(r);
    }
  }
  cc.destroy();
  phong.destroy();
  instanced.destroy();
  device.destroy();

  const section = `${TALK_SECTION}

Written by \`npm run bench -- --talk\` on ${new Date().toISOString().slice(0, 10)} (${adapterName}; GPU timestamps, medians of ${repeats}
rebuilds or frames after a warm-up; load average ${loadavg()[0].toFixed(1)} on ${cpus().length} cores as the run ended). ${adapterNote(adapterName)}
The exact Catmull-Clark limit at the talk's triangle counts (flat baseline on, as the demo), beside
the talk's figures (RTX 3070). The talk's cages are read from ../shared/cages, never copied.

### Compute cost only

*subdivision*: the patch build from the cage; *tessellation*: everything after it (factors, counts,
budget, plan, emit with the weld: positions, normals, barycentrics and topology). *write-bound*:
a kernel that only writes the same output bytes, on the same adapter; *efficiency* is its time over
the pipeline's (the talk's reaches about 30 %).

| model | talk tris | talk sub ms | talk tess ms | talk sub + tess ms | talk M tris/ms | factor | tris | subdivision ms | tessellation ms | sub + tess ms | M tris/ms | write-bound ms | efficiency |
|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
${compute.join('\n')}

### Cost per pass, ms per 1M triangles

*once*: the build a frame needs before its passes (compute: the whole rebuild; instanced: its
level pass and the patch build); *first lit*: 1920×1080, no culling; *each shadow*: 2048², depth
only; the last two columns include *once*, as the talk's rows do. The instanced tessellator keeps
no mesh: every pass evaluates the exact surface again in its vertex shader, as OpenSubdiv's
hardware tessellation does (the talk's OpenSubdiv rows; * each shadow pass costs a full pass).

| model | tessellator | tris | once | first lit | each shadow | 1 lit | 1 lit + 4 shadows |
|---|---|---:|---:|---:|---:|---:|---:|
${perPass.join('\n')}

### Comparison: uniform, M triangles per ms

Edge-Friend and DV21 (uniform Catmull-Clark, positions only) and the talk's adaptive pipeline, as
the talk measured them on its RTX 3070, beside this project's sub + tess rate above (the full
adaptive pipeline at a fixed factor: positions, normals, topology).

| model | Edge-Friend (talk) | talk (adaptive) | DV21 (talk) | this project |
|---|---:|---:|---:|---:|
${uniform.join('\n')}

### The exact surface against Phong, fixed ${PHONG_FACTOR}

Tessellation only (factors, counts, budget, plan, emit; not the exact surface's patch build),
the same pipeline on both surfaces, measured in this run: the exact limit's evaluation is the
difference (the throughput issue asks for at most 1.2 on bigguy). The two in turn, ${AGAINST_PHONG_ROUNDS}
rounds, each one's fastest (a round's median moves by 5-20 % on SwiftShader on a loaded 2-core machine); the exact surface's
passes compiled for the cage (no n-gon, crease or phantom code where it has none).

| model | tris | exact Catmull-Clark ms | Phong ms | exact ÷ Phong |
|---|---:|---:|---:|---:|
${againstPhong.join('\n')}
`;
  if (outFile) writeSection(outFile, TALK_SECTION, section);
  else console.log('\n--models without --out: nothing written');
  return 0;
}
