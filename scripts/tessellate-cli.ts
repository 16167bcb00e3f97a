/**
 * `npm run tessellate -- model.obj (--fixed F | --adaptive [--lod S] [--eye x,y,z --target x,y,z])
 *   (--out out.obj | --stats) [--params out.json|out.txt] [--surface catmull-clark|phong|bezier-acc|gregory-acc|pm-acc]
 *   [--flat-baseline] [--demo-view] [--limit-px] [--capacity N] [--displacement map.png --scale S [--mid M] [--wrap repeat|clamp]]`
 * `npm run tessellate -- model.obj --tessellator instanced (--level L | --adaptive [--lod S] [--eye … --target …]) …`
 * Runs the GPU tessellation pipeline in Node (Dawn, any adapter; SwiftShader when there is no
 * GPU) and writes the welded mesh: by default on the exact Catmull-Clark limit surface (with
 * --flat-baseline, blended towards the flat cage at low factors as the demo does). --params writes every output vertex's source cage face and
 * parameter in the CPU reference's addressing: JSON `{"params": [[f,u,v] | [f,k,s,t], ...]}`, or
 * with a .txt name the `f u v` / `f k s t` lines that `npm run subdiv -- --points` reads.
 * --stats prints one JSON line on stdout: {"faces" (cage faces), "cpuPrepMs" (the CPU
 * Catmull-Clark preparation per topology), "gpuBytes" (GPU memory of the subdivision data),
 * "subdivisionMs", "tessellationMs" (GPU timestamps of the one rebuild: the patch build, and
 * everything after it; null without timestamp queries), "vertices", "triangles", "adapter"}.
 *
 * `--tessellator instanced` runs the instanced power-of-two tessellator (src/gpu/instanced/instanced.ts)
 * instead: its level pass (static `--level L`, L a power of two in 1..64, or `--adaptive`: each
 * edge's level by the compute tessellator's adaptive factor rule at the same camera and --lod,
 * rounded up to a power of two: the two tessellators' counts compare), then a compute pass that
 * runs the draw's own WGSL vertex function over every instance of every bucket; the copies on
 * shared cage edges are welded by their cage parameter (weldInstanced) and the snap's collapsed
 * triangles left out, so the OBJ and --params are what a draw shows. Surfaces: phong (default),
 * the three ACC schemes (--surface bezier-acc | gregory-acc | pm-acc; closed quad and triangle
 * cages) and the exact Catmull-Clark limit (--surface catmull-clark: the compute tessellator's
 * evaluator over its buffers, src/gpu/instanced/surface-cc.ts; its CPU preparation is in "cpuPrepMs", its
 * tables and refined points in "gpuBytes"). Its --stats line has "tessellator": "instanced",
 * "patches", "levelsMs" and "evaluateMs" (GPU timestamps of the two passes; "tessellationMs" is
 * their sum, "subdivisionMs" null), "drawnTriangles" (what a draw rasterises, collapsed ones
 * included) and "weldGap" (the largest distance between the two sides' copies of a point, over
 * the model's size).
 * The compute tessellator also takes the three ACC schemes as its surface (closed or open quad and
 * triangle cages; n-gons and holes are refused with exit code 2). --demo-view uses the demo's first
 * view (its default orbit fitted to a 1280×720 canvas) as the camera; --limit-px (Catmull-Clark)
 * measures how far the output vertices that face the eye are from the exact limit surface, in
 * pixels of that camera (scripts/limit-distance.ts), into --stats as "limitPx" {max, p99, vertices},
 * and the drawn triangles between them (their edge midpoints and centroids, along the limit normal)
 * as "displayedPx" {max, p99, samples}.
 * --capacity N: the output vertices and triangles (each) the compute tessellator holds, default
 * 16,777,216 (the talk's largest count fits), at most what one storage binding of the adapter
 * holds (the device is made with the adapter's largest limits); a tessellation past it has its
 * factors scaled down by the budget, said on stderr ("budgetScale" in --stats).
 * --displacement map.png --scale S moves every output vertex along the surface normal by
 * h = (sample − M)·S (M = --mid, default 0.5), the map (8 or 16-bit PNG, greyscale or its red
 * channel) sampled bilinearly at the cage's uvs (the model needs vt on every face corner),
 * --wrap repeat (default) or clamp; any surface of either tessellator (src/gpu/tess/displacement-map.ts; the
 * instanced one displaces in its vertex function through a lending compute tessellator's arenas,
 * src/gpu/instanced/displace-vertex.ts; its --adaptive levels do not count the heights).
 * Bad input: a message and exit code 2.
 */
import { existsSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { CageError, escapeControl, LimitError } from '../src/mesh/index.ts';
import { cageTooLarge } from '../src/gpu/tess/arenas.ts';
import { outputCapacity } from '../src/gpu/tess/factors.ts';
import { MAX_FACTOR } from '../src/gpu/contract/constants.ts';
import { EXIT_BAD_INPUT, EXIT_INTERNAL, EXIT_OK, guarded, InputError, isInputError } from '../src/cli/boundary.ts';
import { writeOutput } from '../src/cli/files.ts';
import { loadInput, refuseNonFiniteOutput, type TessellateArgs, USAGE, UsageError } from './tessellate-input.ts';
import { createNodeDevice, SWIFTSHADER_ICD } from '../src/gpu/device/node-device.ts';
import { tessellateOnce, meshToObj, vertexParams, paramsToText, headlessCamera, withoutUnusedVertices } from '../src/gpu/tess/headless.ts';
import { prepareMesh, type PreparedMesh } from '../src/gpu/tess/prepare.ts';
import { buildCatmullClark, type CatmullClarkData } from '../src/gpu/cc/build.ts';
import { faceCount, type Cage } from '../src/mesh/index.ts';
import { tessellateInstanced, InstancedTessellator } from '../src/gpu/instanced/instanced.ts';
import { factorRuleLevels, type LevelParams } from '../src/gpu/instanced/instanced-options.ts';
import { prepareInstanced, refuseInstancedOverLimit } from '../src/gpu/instanced/prepare-patches.ts';
import { weldInstanced, weldedToObj, weldedVertexParams } from '../src/gpu/instanced/headless-output.ts';
import { AccPatches } from '../src/gpu/acc/patches.ts';
import { ccSourceBytes, ccSurfaceTessellator } from '../src/gpu/instanced/surface-cc.ts';
import { displacementLender } from '../src/gpu/instanced/displace-vertex.ts';
import { prepareDisplacement } from '../src/gpu/tess/displacement-map.ts';
import { isAccSurface, type SurfaceId, surfaceScheme } from '../src/gpu/surface/registry.ts';
import { prepareAccSurface, type AccSurface } from '../src/gpu/acc/surface.ts';
import { demoView, displayedDistancePx, limitDistancePx } from './limit-distance.ts';

/** The CLI's one Catmull-Clark preparation call (CPU, topology only, per cage). */
function prepareCatmullClark(cage: Cage, mesh: PreparedMesh): CatmullClarkData {
  return buildCatmullClark(cage, mesh);
}

/** A device lent by the caller, with its adapter's name: main runs on it and leaves it alive. The
 * CLI tests run many cases in one process on one lent device, so each pipeline compiles once
 * (tests/support/tessellate-cli.ts). */
export interface LentDevice {
  device: GPUDevice;
  adapterName: string;
}

export async function main(argv: string[], lent?: LentDevice): Promise<number> {
  // console.error, not process.stderr: the in-process tests capture the console.
  return guarded(
    'tessellate',
    argv,
    (a) => run(a, lent),
    (line) => console.error(line),
  );
}

async function run(argv: string[], lent?: LentDevice): Promise<number> {
  let input: ReturnType<typeof loadInput>;
  try {
    input = loadInput(argv);
  } catch (e) {
    if (e instanceof UsageError) {
      console.error(`tessellate: ${escapeControl(e.message)}\n${USAGE}`);
      return EXIT_BAD_INPUT;
    }
    // The model's name before a cage's line-numbered issues.
    if (e instanceof CageError) throw new InputError(`${argv.find((a) => !a.startsWith('--'))}: ${e.message}`);
    throw e;
  }
  const { args, cage } = input;
  for (const w of input.warnings) console.error(escapeControl(`tessellate: ${w}`));
  let device: GPUDevice;
  let adapterName: string;
  try {
    // --stats reads GPU timestamps: unquantised, as the benchmark reads them.
    ({ device, adapterName } = lent ?? (await createNodeDevice(args.stats ? ['disable-dawn-features=timestamp_quantization'] : [])));
  } catch (e) {
    // No GPU: run again on SwiftShader, if it is installed.
    if (!process.env.VK_ICD_FILENAMES && existsSync(SWIFTSHADER_ICD)) {
      const r = spawnSync(process.execPath, process.argv.slice(1), {
        stdio: 'inherit',
        env: { ...process.env, VK_ICD_FILENAMES: SWIFTSHADER_ICD },
      });
      return r.status ?? 1;
    }
    console.error(`tessellate: no GPU: ${(e as Error).message}`);
    return EXIT_INTERNAL;
  }
  try {
    return args.instanced ? await runInstanced(device, adapterName, cage, args) : await runCompute(device, adapterName, cage, args);
  } finally {
    // A failure mid-run (a limit found by a build) still frees the device's memory.
    if (!lent) device.destroy();
  }
}

/** The cage `surface` tessellates in place of `cage` (SurfaceScheme.surfaceCage), and, when it is
 * another one, why, on stderr. */
function surfaceCageSaid(cage: Cage, surface: SurfaceId, model: string): Cage {
  const sc = surfaceScheme(surface).surfaceCage(cage);
  if (sc.note) console.error(`tessellate: ${model}: ${surfaceScheme(surface).name}: ${sc.note}`);
  return sc.cage;
}

/** The compute tessellator: the surface's preparation, one rebuild, the readback, the outputs. */
async function runCompute(device: GPUDevice, adapterName: string, cage: Cage, args: TessellateArgs): Promise<number> {
  // The cage the surface tessellates: an ACC scheme refines a cage with n-gons once (said here).
  cage = surfaceCageSaid(cage, args.o.surface ?? 'catmull-clark', args.model);
  // From the face sizes, before a preparation that grows with them: a cage whose scratch buffer
  // alone exceeds the device's binding limit is refused now, not after a minute and gigabytes.
  const tooLarge = cageTooLarge(cage, MAX_FACTOR, device.limits.maxStorageBufferBindingSize);
  if (tooLarge) throw new LimitError(`${args.model}: ${tooLarge}`);
  const mesh = prepareMesh(cage);
  const started = performance.now();
  let cc: CatmullClarkData | undefined;
  let acc: AccSurface | undefined;
  try {
    cc = args.o.surface && surfaceScheme(args.o.surface).patchBuild === 'refinement' ? prepareCatmullClark(cage, mesh) : undefined;
    acc = args.o.surface && isAccSurface(args.o.surface) ? prepareAccSurface(device, cage, mesh, args.o.surface) : undefined;
  } catch (e) {
    throw modelError(args.model, e);
  }
  const cpuPrepMs = performance.now() - started;
  // The demo's first view (src/gpu/render/camera.ts fitOrbit on a 1280×720 canvas), as the camera.
  if (args.demoView) Object.assign(args.o, demoView(mesh));
  const capacity = outputCapacity(device.limits, args.o);
  if (args.o.vertexCapacity !== undefined && capacity.vertexCapacity < args.o.vertexCapacity)
    console.error(
      `tessellate: --capacity ${args.o.vertexCapacity}: this device holds ${capacity.vertexCapacity} (its storage binding limit)`,
    );
  const r = await tessellateOnce(device, cage, args.o, undefined, { mesh, cc, acc });
  if (r.out.scale < 1)
    console.error(
      `tessellate: the tessellation would pass the capacity of ${capacity.triangleCapacity} triangles or vertices: its factors were scaled by ${r.out.scale.toPrecision(3)} (--capacity N holds more)`,
    );
  // Checked before anything is written or counted (--stats too): a NaN is not an output.
  refuseNonFiniteOutput(args.model, r.out.positions, r.out.vertexCount);
  // --limit-px: in pixels of the camera the run used (the same headlessCamera tessellateOnce made).
  const cam = args.limitPx ? headlessCamera(mesh, args.o) : undefined;
  const limit = cam ? limitDistancePx(cage, mesh, r.out, cam) : undefined;
  const displayed = cam ? displayedDistancePx(cage, mesh, r.out, cam) : undefined;
  acc?.patches.destroy();
  // The cage's unused vertices go through the pipeline; the loader's warning says they are ignored: not written.
  const { r: written, kept } = withoutUnusedVertices(r);
  if (args.out)
    writeChecked(
      args.out,
      '--out',
      meshToObj(
        written,
        `tessellab: ${args.model}, ${args.o.surface} surface, ${args.o.mode}${args.o.mode === 'fixed' ? ` ${args.o.fixedFactor}` : ''}${args.disp ? `, displaced by ${args.disp.path} (scale ${args.disp.scale}, mid ${args.disp.midLevel}, ${args.disp.wrap})` : ''}, ${adapterName}`,
      ),
    );
  if (args.params) {
    const params = vertexParams(r, cage);
    writeParams(args.params, kept ? Array.from(kept, (v) => params[v]) : params);
  }
  if (args.stats) {
    const timed = Object.keys(r.timings).length > 0;
    const total = Object.values(r.timings).reduce((a, b) => a + b, 0);
    const subdivision = r.timings.subdivision ?? 0;
    console.log(
      JSON.stringify({
        faces: faceCount(cage),
        cpuPrepMs: Number(cpuPrepMs.toFixed(3)),
        gpuBytes: cc ? cc.gpuBytes : acc ? acc.patches.patchBuffer.size + acc.patches.pointBuffer.size + acc.patches.staticBuffer.size : 0,
        subdivisionMs: timed ? Number(subdivision.toFixed(4)) : null,
        tessellationMs: timed ? Number((total - subdivision).toFixed(4)) : null,
        vertices: written.out.vertexCount,
        triangles: r.out.triangleCount,
        capacity: capacity.triangleCapacity,
        budgetScale: r.out.scale,
        ...(limit && displayed
          ? {
              limitPx: { max: Number(limit.maxPx.toFixed(4)), p99: Number(limit.p99Px.toFixed(4)), vertices: limit.count },
              displayedPx: { max: Number(displayed.maxPx.toFixed(4)), p99: Number(displayed.p99Px.toFixed(4)), samples: displayed.count },
            }
          : {}),
        adapter: adapterName,
      }),
    );
  } else if (limit && displayed) {
    console.error(
      `tessellate: vertices facing the eye are at most ${limit.maxPx.toFixed(3)} px (p99 ${limit.p99Px.toFixed(3)}) from the exact limit; ` +
        `the drawn triangles between them (edge midpoints, centroids) at most ${displayed.maxPx.toFixed(3)} px (p99 ${displayed.p99Px.toFixed(3)})`,
    );
  }
  const wrote = [args.out, args.params].filter(Boolean).join(' and ');
  console.error(
    `tessellate: ${written.out.vertexCount} vertices, ${r.out.triangleCount} triangles (${r.mesh.triangleCount} cage triangles) on ${adapterName}${wrote ? `; wrote ${wrote}` : ''}`,
  );
  return EXIT_OK;
}

/** A refusal by a surface's build (AccError, LimitError), with the model's name; other errors as they are. */
function modelError(model: string, e: unknown): unknown {
  return isInputError(e) ? new InputError(`${model}: ${e.message}`) : e;
}

/** Write an output after checking it holds no NaN or infinity (an output that cannot be read back
 * is refused, exit code 2, rather than written). */
function writeChecked(path: string, what: string, text: string): void {
  const bad = /\b(NaN|-?Infinity)\b/.exec(text);
  if (bad) {
    const line = text.slice(0, bad.index).split('\n').length;
    throw new InputError(
      `${what} ${path}: not written: the output has non-finite values (${bad[1]} on its line ${line}); the model, --scale or the camera is beyond 32-bit floats`,
    );
  }
  writeOutput(path, text, what);
}

function writeParams(path: string, p: ReturnType<typeof vertexParams>): void {
  writeChecked(
    path,
    '--params',
    path.endsWith('.txt')
      ? paramsToText(p)
      : JSON.stringify({
          vertexCount: p.length,
          params: p.map((x) => (x === null ? null : 'u' in x ? [x.face, x.u, x.v] : [x.face, x.k, x.s, x.t])),
        }) + '\n',
  );
}

/** `--tessellator instanced`: levels, the draw's vertex function in compute, the weld. */
async function runInstanced(device: GPUDevice, adapterName: string, cage: Cage, args: TessellateArgs): Promise<number> {
  if (args.acc) cage = surfaceCageSaid(cage, args.acc, args.model);
  // From the face sizes (and --level), before the preparation, as runCompute does: a cage whose
  // patch records, level lists or static-level output exceed the binding limit is refused now.
  try {
    refuseInstancedOverLimit(cage, device.limits.maxStorageBufferBindingSize, args.level);
  } catch (e) {
    throw modelError(args.model, e);
  }
  const mesh = prepareMesh(cage);
  const started = performance.now();
  const im = prepareInstanced(cage, mesh);
  // The exact surface: the compute tessellator's Catmull-Clark tables, its buffers lent.
  let cc: CatmullClarkData | undefined;
  try {
    cc = args.instancedCC ? prepareCatmullClark(cage, mesh) : undefined;
  } catch (e) {
    throw modelError(args.model, e);
  }
  const cpuPrepMs = performance.now() - started;
  let lp: LevelParams;
  if (args.level !== undefined) lp = { mode: 'static', level: args.level };
  else {
    // The compute tessellator's adaptive camera (1080 px high, 16:9) and its factor rule (the same
    // screen-space measure and LOD scale), each edge's factor rounded up to a power of two.
    lp = factorRuleLevels(headlessCamera(mesh, args.o));
  }
  let acc: AccPatches | undefined;
  if (args.acc) {
    try {
      acc = new AccPatches(device, cage, args.acc);
    } catch (e) {
      throw modelError(args.model, e);
    }
  }
  // Displacement: the arenas of a lending compute tessellator (src/gpu/instanced/displace-vertex.ts), on
  // Catmull-Clark the surface's own lender.
  const d = args.o.displacement;
  const dispData = d ? prepareDisplacement(cage, mesh, d.map, d.wrap) : undefined;
  const settings = d ? { scale: d.scale, midLevel: d.midLevel, enabled: true } : undefined;
  const tess = new InstancedTessellator(device, {
    surface: acc ? 'acc' : cc ? 'lent-limit' : 'evalSurface',
    displacement: d !== undefined,
  });
  const ccSource = cc ? ccSurfaceTessellator(device, mesh, cc, dispData, settings) : undefined;
  const lender = dispData && !cc ? displacementLender(device, mesh, dispData, settings) : undefined;
  let r: Awaited<ReturnType<typeof tessellateInstanced>>;
  try {
    r = await tessellateInstanced(device, cage, mesh, lp, tess, im, acc ?? ccSource, lender);
  } catch (e) {
    tess.destroy();
    ccSource?.destroy();
    lender?.destroy();
    throw modelError(args.model, e);
  }
  const gpuBytes =
    tess.gpuBytes +
    (acc ? acc.patchBuffer.size + acc.pointBuffer.size + acc.staticBuffer.size : 0) +
    (ccSource ? ccSourceBytes(ccSource) : 0) +
    (lender ? lender.paramsBuffer.size + lender.staticBuffer.size + lender.cageBuffer.size : 0);
  tess.destroy();
  acc?.destroy();
  ccSource?.destroy();
  lender?.destroy();
  const surfaceName = args.acc ?? (cc ? 'catmull-clark' : 'phong');
  const w = weldInstanced(im, r.out);
  // Checked before anything is written or counted (--stats too), as runCompute does. The cage's
  // unused vertices need no dropping here: the weld's vertices all come from patches.
  refuseNonFiniteOutput(args.model, w.positions, w.vertexCount);
  const what =
    (args.level !== undefined ? `level ${args.level}` : `adaptive (lod ${args.o.lodScale ?? 1})`) +
    (d ? `, displaced (scale ${d.scale}, mid ${d.midLevel}, ${d.wrap})` : '');
  if (args.out)
    writeChecked(
      args.out,
      '--out',
      weldedToObj(w, `tessellab: ${args.model}, instanced tessellator, ${surfaceName} surface, ${what}, ${adapterName}`),
    );
  if (args.params) writeParams(args.params, weldedVertexParams(im, cage, r.out, w));
  if (args.stats) {
    const t = r.out.timings;
    const timed = t.levels !== undefined && t.evaluate !== undefined;
    console.log(
      JSON.stringify({
        tessellator: 'instanced',
        faces: faceCount(cage),
        patches: im.patchCount,
        cpuPrepMs: Number(cpuPrepMs.toFixed(3)),
        gpuBytes,
        subdivisionMs: null,
        tessellationMs: timed ? Number((t.levels + t.evaluate).toFixed(4)) : null,
        levelsMs: timed ? Number(t.levels.toFixed(4)) : null,
        evaluateMs: timed ? Number(t.evaluate.toFixed(4)) : null,
        vertices: w.vertexCount,
        triangles: w.triangleCount,
        drawnTriangles: r.out.triangleCount,
        weldGap: Number((w.gap / mesh.size).toExponential(3)),
        adapter: adapterName,
      }),
    );
  }
  const wrote = [args.out, args.params].filter(Boolean).join(' and ');
  console.error(
    `tessellate: instanced, ${surfaceName}, ${what}: ${w.vertexCount} vertices, ${w.triangleCount} triangles (${r.out.triangleCount} drawn, ${w.collapsed} collapsed by the snap; ${im.patchCount} patches) on ${adapterName}${wrote ? `; wrote ${wrote}` : ''}`,
  );
  return 0;
}
