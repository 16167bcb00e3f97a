/**
 * `npm run bench:instanced [-- --level L] [--surface phong|catmull-clark] [--models a,b] [--repeats N] [--rounds R] [--out BENCHMARKS.md]`: the
 * compute tessellator against the instanced power-of-two tessellator (src/gpu/instanced/instanced.ts), per
 * project model, at matched settings: the Phong surface (or with --surface catmull-clark the exact
 * limit, flat baseline off, on both: the instanced one through the compute tessellator's
 * evaluator, src/gpu/instanced/surface-cc.ts), compute fixed factor L and instanced
 * static level L (the same points on every cage triangle: tests/gpu/tess/tessellate-cli.node.test.ts
 * checks it; the same triangle count on quads, n-gons and triangles alike). Measured inside one
 * program, on one device, with GPU timestamps:
 *
 *   build ms      compute: its whole rebuild (factors … emit), once per change of the view or
 *                 cage; instanced: its level pass (levels, buckets, draw records); Catmull-Clark:
 *                 both include the patch build (the instanced one runs the lending tessellator's,
 *                 untimed there: the compute run's 'subdivision' stage of the same pass is added)
 *   lit pass      1920×1080 rgba8 + depth, no culling for both (the instanced tessellator's own
 *                 lit pipeline culls nothing); compute draws its stored buffers, instanced
 *                 evaluates the surface in the vertex shader
 *   shadow pass   2048² depth only; the same
 *   lit + 4 shadows, and per 1M triangles: a frame with four shadow-casting lights
 *   memory held   compute: the stored mesh (32 bytes a vertex, 12 a triangle; its work buffers and
 *                 capacity slack not counted); instanced: every buffer it holds (topology,
 *                 patterns, cage, level work and bucket lists, records, uniforms); Catmull-Clark:
 *                 both plus the tables and refined points they read (the compute tessellator's
 *                 static and cage arenas; the lending tessellator's arenas, its work included)
 *
 * Each cell is the smallest of R rounds (default 3; each round times compute then instanced, each
 * a median of N frames): SwiftShader shares the CPU with whatever else runs, and contention only
 * ever adds time.
 *
 * Writes its own section of BENCHMARKS.md (kept by `npm run bench`, which keeps the sections
 * other scripts write); with --models and no --out nothing is written.
 */
import { readdirSync, readFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { createNodeDevice } from '../src/gpu/device/node-device.ts';
import { Tessellator } from '../src/gpu/tess/tessellator.ts';
import { prepareMesh, type PreparedMesh } from '../src/gpu/tess/prepare.ts';
import { headlessCamera } from '../src/gpu/tess/headless.ts';
import { BYTES_PER_TRIANGLE, BYTES_PER_VERTEX } from '../src/gpu/tess/factors.ts';
import { readBuffer } from '../src/gpu/device/readback.ts';
import { bakeTables } from '../src/pattern/tables.ts';
import { loadCage } from '../src/mesh/index.ts';
import { InstancedTessellator } from '../src/gpu/instanced/instanced.ts';
import type { LevelParams } from '../src/gpu/instanced/instanced-options.ts';
import { BUCKETS } from '../src/gpu/instanced/buffer-layouts.ts';
import { prepareInstanced } from '../src/gpu/instanced/prepare-patches.ts';
import { ccSourceBytes, ccSurfaceTessellator } from '../src/gpu/instanced/surface-cc.ts';
import { buildCatmullClark } from '../src/gpu/cc/build.ts';
import { isSurfaceId, SURFACE_IDS, surfaceScheme } from '../src/gpu/surface/registry.ts';
import { isPow2Level } from '../src/pattern/pow2.ts';
import { benchLightViewProj, timeDrawPasses } from './draw-timing.ts';
import { adapterNote, isSwiftShader, timeRebuild, writeSection } from './timing.ts';

const SECTIONS = {
  phong: '## Compute against instanced tessellation, pass by pass',
  'catmull-clark': '## Compute against instanced tessellation on the exact Catmull-Clark surface, pass by pass',
} as const;

function median(xs: number[]): number {
  return [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
}

/** The instanced tessellator's level pass, shadow pass and lit pass, each timed, `repeats` times after a warm-up. */
export async function timeInstanced(
  device: GPUDevice,
  it: InstancedTessellator,
  mesh: PreparedMesh,
  lp: LevelParams,
  repeats: number,
): Promise<{ buildMs: number; litMs: number; shadowMs: number; triangles: number }> {
  const cam = headlessCamera(mesh, { mode: 'fixed' });
  it.writeFrame({ viewProj: cam.viewProj, lightViewProj: benchLightViewProj(mesh), eye: cam.eye });
  const texture = (label: string, size: [number, number], format: GPUTextureFormat) =>
    device.createTexture({ label, size, format, usage: GPUTextureUsage.RENDER_ATTACHMENT });
  const color = texture('bench instanced colour', [1920, 1080], 'rgba8unorm');
  const depth = texture('bench instanced depth', [1920, 1080], 'depth32float');
  const shadowMap = texture('bench instanced shadow map', [2048, 2048], 'depth32float');
  const querySet = device.createQuerySet({ label: 'bench instanced timestamps', type: 'timestamp', count: 6 });
  const resolve = device.createBuffer({
    label: 'bench instanced timestamps',
    size: 48,
    usage: GPUBufferUsage.QUERY_RESOLVE | GPUBufferUsage.COPY_SRC,
  });
  const samples: number[][] = [[], [], []];
  for (let i = 0; i < repeats + 1; i++) {
    const enc = device.createCommandEncoder({ label: 'bench instanced frame' });
    it.encodeLevels(enc, lp, { querySet, beginningOfPassWriteIndex: 0, endOfPassWriteIndex: 1 });
    const sp = enc.beginRenderPass({
      label: 'bench instanced shadow pass',
      colorAttachments: [],
      depthStencilAttachment: {
        view: shadowMap.createView({ label: 'bench instanced shadow view' }),
        depthClearValue: 1,
        depthLoadOp: 'clear',
        depthStoreOp: 'store',
      },
      timestampWrites: { querySet, beginningOfPassWriteIndex: 2, endOfPassWriteIndex: 3 },
    });
    it.encodeDraw(sp, 'shadow');
    sp.end();
    const lit = enc.beginRenderPass({
      label: 'bench instanced lit pass',
      colorAttachments: [
        { view: color.createView({ label: 'bench instanced colour view' }), clearValue: [0, 0, 0, 1], loadOp: 'clear', storeOp: 'store' },
      ],
      depthStencilAttachment: {
        view: depth.createView({ label: 'bench instanced depth view' }),
        depthClearValue: 1,
        depthLoadOp: 'clear',
        depthStoreOp: 'store',
      },
      timestampWrites: { querySet, beginningOfPassWriteIndex: 4, endOfPassWriteIndex: 5 },
    });
    it.encodeDraw(lit, 'lit');
    lit.end();
    enc.resolveQuerySet(querySet, 0, 6, resolve, 0);
    device.queue.submit([enc.finish()]);
    const t = new BigUint64Array(await readBuffer(device, resolve, 48));
    if (i > 0) for (let k = 0; k < 3; k++) samples[k].push(Number(t[2 * k + 1] - t[2 * k]) / 1e6);
  }
  const records = new Uint32Array(await readBuffer(device, it.drawArgs, 20 * BUCKETS));
  let triangles = 0;
  for (let b = 0; b < BUCKETS; b++) triangles += (records[5 * b] / 3) * records[5 * b + 1];
  for (const x of [color, depth, shadowMap]) x.destroy();
  querySet.destroy();
  resolve.destroy();
  return { buildMs: median(samples[0]), shadowMs: median(samples[1]), litMs: median(samples[2]), triangles };
}

function option(argv: string[], name: string): string | undefined {
  const i = argv.indexOf(name);
  return i >= 0 ? argv[i + 1] : undefined;
}

export async function main(argv: string[]): Promise<number> {
  const level = Number(option(argv, '--level') ?? 16);
  if (!isPow2Level(level)) {
    console.error(`bench:instanced: --level: a power of two in [1, 64], got ${option(argv, '--level')}`);
    return 2;
  }
  const surface = option(argv, '--surface') ?? 'phong';
  // The surfaces the instanced tessellator evaluates from a cage alone or from a lending compute
  // tessellator (an ACC surface needs its patches built: not benchmarked here).
  const benched = SURFACE_IDS.filter((id) => surfaceScheme(id).instancedKind !== 'acc');
  if (!isSurfaceId(surface) || !benched.includes(surface)) {
    console.error(`bench:instanced: --surface ${benched.join(' or ')}, got ${surface}`);
    return 2;
  }
  const SECTION = SECTIONS[surface as keyof typeof SECTIONS];
  const cc = surfaceScheme(surface).instancedKind === 'lent-limit';
  const repeats = Number(option(argv, '--repeats') ?? 3);
  const rounds = Number(option(argv, '--rounds') ?? 3);
  const only = option(argv, '--models')
    ?.split(',')
    .map((m) => m.trim().replace(/\.obj$/, ''))
    .filter(Boolean);
  const outFile = option(argv, '--out') ?? (only ? undefined : 'BENCHMARKS.md');
  const { device, adapterName } = await createNodeDevice(['disable-dawn-features=timestamp_quantization']);
  if (!device.features.has('timestamp-query')) {
    console.error('bench:instanced: this adapter has no timestamp queries; nothing to measure');
    return 1;
  }
  const models = readdirSync('public/models')
    .filter((f) => f.endsWith('.obj'))
    .map((f) => f.replace('.obj', ''))
    .sort()
    .filter((m) => !only || only.includes(m));
  const compute = Tessellator.create(device, bakeTables(64), { surface, flatBaseline: false });
  const instanced = new InstancedTessellator(device, { surface: surfaceScheme(surface).instancedKind });
  const header =
    '| model | cage faces | patches | tessellator | tris drawn | build ms | lit pass ms | shadow pass ms | lit + 4 shadows ms | lit + 4 shadows per 1M tris | memory held |';
  const rule = '|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|';
  const rows: string[] = [];
  console.log(header);
  console.log(rule);
  const kib = (b: number) => `${(b / 1024).toFixed(0)} KiB`;
  for (const name of models) {
    const cage = loadCage(readFileSync(`public/models/${name}.obj`, 'utf8')).cage;
    const mesh = prepareMesh(cage);
    const im = prepareInstanced(cage, mesh);
    const faces = cage.faceOffsets.length - 1;
    const cam = headlessCamera(mesh, { mode: 'fixed' });
    const best = { cBuild: Infinity, cLit: Infinity, cShadow: Infinity, iBuild: Infinity, iLit: Infinity, iShadow: Infinity };
    let c = { vertices: 0, triangles: 0 };
    let iTris = 0;
    let ccData: ReturnType<typeof buildCatmullClark> | undefined;
    try {
      ccData = cc ? buildCatmullClark(cage, mesh) : undefined;
    } catch (e) {
      console.log(`| ${name} | ${faces} | ${im.patchCount} | refused: ${(e as Error).message} |`);
      continue;
    }
    const source = ccData ? ccSurfaceTessellator(device, mesh, ccData) : undefined;
    let ccBytes = { compute: 0, instanced: 0 };
    for (let round = 0; round < rounds; round++) {
      const cr = await timeRebuild(device, compute, mesh, { mode: 'fixed', fixedFactor: level, surface }, repeats, ccData);
      const cd = await timeDrawPasses(device, compute.output, cam.viewProj, benchLightViewProj(mesh), repeats, 'none');
      instanced.setMesh(im, source);
      const ir = await timeInstanced(device, instanced, mesh, { mode: 'static', level }, repeats);
      c = cr;
      iTris = ir.triangles;
      if (source) ccBytes = { compute: compute.staticBuffer.size + compute.cageBuffer.size, instanced: ccSourceBytes(source) };
      best.cBuild = Math.min(best.cBuild, cr.total);
      best.cLit = Math.min(best.cLit, cd.litMs);
      best.cShadow = Math.min(best.cShadow, cd.shadowMs);
      best.iBuild = Math.min(best.iBuild, ir.buildMs + (cr.stages.subdivision ?? 0));
      best.iLit = Math.min(best.iLit, ir.litMs);
      best.iShadow = Math.min(best.iShadow, ir.shadowMs);
    }
    const frame = (lit: number, shadow: number) => lit + 4 * shadow;
    const line = (who: string, tris: number, build: number, lit: number, shadow: number, bytes: number) =>
      `| ${name} | ${faces} | ${im.patchCount} | ${who} | ${tris} | ${build.toFixed(3)} | ${lit.toFixed(3)} | ${shadow.toFixed(3)} | ${frame(lit, shadow).toFixed(3)} | ${((frame(lit, shadow) * 1e6) / tris).toFixed(2)} | ${kib(bytes)} |`;
    const rowsHere = [
      line(
        `compute, factor ${level}`,
        c.triangles,
        best.cBuild,
        best.cLit,
        best.cShadow,
        c.vertices * BYTES_PER_VERTEX + c.triangles * BYTES_PER_TRIANGLE + ccBytes.compute,
      ),
      line(`instanced, level ${level}`, iTris, best.iBuild, best.iLit, best.iShadow, instanced.gpuBytes + ccBytes.instanced),
    ];
    source?.destroy();
    for (const r of rowsHere) console.log(r);
    rows.push(...rowsHere);
  }
  compute.destroy();
  instanced.destroy();
  device.destroy();

  const section = `${SECTION}

Written by \`npm run bench:instanced -- --level ${level}${cc ? ' --surface catmull-clark' : ''}\` on ${new Date().toISOString().slice(0, 10)} (${adapterName}; GPU timestamps;
each cell the smallest of ${rounds} rounds, each a median of ${repeats} frames after a warm-up: under SwiftShader the CPU is
shared with whatever else runs, and contention only adds time; load average ${loadavg()[0].toFixed(1)} on ${cpus().length} cores as the run
ended). The talk's comparison against a per-pass tessellator, inside one program:
the compute tessellator builds once and every pass draws its stored mesh; the instanced power-of-two tessellator
(NVIDIA 2009) keeps no mesh and evaluates the surface again in the vertex shader of every pass. Matched settings:
${cc ? "the exact Catmull-Clark limit (flat baseline off; the instanced tessellator runs the compute tessellator's evaluator over its tables and refined points)" : 'the Phong surface'}, compute fixed factor ${level} against instanced static level ${level} (the same points on every cage
triangle, so the same triangle count). *build ms*: compute, its whole rebuild (needed when the view or cage
changes); instanced, its level pass (levels, buckets, draw records)${cc ? " plus the patch build (the compute run's subdivision stage: the same pass on the same data)" : ''}. *lit pass*: 1920×1080, no culling for
either; *shadow pass*: 2048², depth only. *memory held*: compute, its stored mesh (32 bytes a vertex, 12 a
triangle; work buffers and capacity slack not counted); instanced, every buffer it holds${cc ? '; both plus the Catmull-Clark tables and refined points they read' : ''}. ${
    isSwiftShader(adapterName)
      ? `On SwiftShader (a
CPU rasteriser) the vertex shader's cost is paid per vertex on the CPU: the ratios between rows are what
carry over, not the milliseconds (a real GPU's tables: the section 'On a real GPU', bench/gpu/).`
      : adapterNote(adapterName)
  }

${header}
${rule}
${rows.join('\n')}
`;
  if (outFile) writeSection(outFile, SECTION, section);
  else console.log('\n--models without --out: nothing written');
  return 0;
}
