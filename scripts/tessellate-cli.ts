/**
 * `npm run tessellate -- model.obj (--fixed F | --adaptive [--lod S] [--eye x,y,z --target x,y,z])
 *   (--out out.obj | --stats) [--params out.json|out.txt] [--surface catmull-clark|phong] [--flat-baseline]`
 * Runs the GPU tessellation pipeline in Node (Dawn, any adapter; SwiftShader when there is no
 * GPU) and writes the welded mesh: by default on the exact Catmull-Clark limit surface (with
 * --flat-baseline, blended towards the flat cage at low factors as the demo does). --params writes every output vertex's source cage face and
 * parameter in the CPU reference's addressing: JSON `{"params": [[f,u,v] | [f,k,s,t], ...]}`, or
 * with a .txt name the `f u v` / `f k s t` lines that `npm run subdiv -- --points` reads.
 * --stats prints one JSON line on stdout: {"faces" (cage faces), "cpuPrepMs" (the CPU
 * Catmull-Clark preparation per topology), "gpuBytes" (GPU memory of the subdivision data),
 * "subdivisionMs", "tessellationMs" (GPU timestamps of the one rebuild: the patch build, and
 * everything after it; null without timestamp queries), "vertices", "triangles", "adapter"}.
 * Bad input: a message and exit code 2.
 */
import { readFileSync, writeFileSync, existsSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { loadCage, CageError } from '../src/mesh/index.ts';
import { createNodeDevice, SWIFTSHADER_ICD } from '../src/gpu/node-device.ts';
import { tessellateOnce, meshToObj, vertexParams, paramsToText, type HeadlessOptions } from '../src/gpu/headless.ts';
import { prepareMesh, type PreparedMesh } from '../src/gpu/prepare.ts';
import { buildCatmullClark, type CatmullClarkData } from '../src/gpu/cc/build.ts';
import { faceCount, type Cage } from '../src/mesh/index.ts';

const USAGE = `usage: npm run tessellate -- model.obj (--fixed F | --adaptive [--lod S] [--eye x,y,z --target x,y,z]) (--out out.obj | --stats) [--params out.json|out.txt] [--surface catmull-clark|phong] [--flat-baseline]`;

/** The CLI's one Catmull-Clark preparation call (CPU, topology only, per cage). */
function prepareCatmullClark(cage: Cage, mesh: PreparedMesh): CatmullClarkData {
  return buildCatmullClark(cage, mesh);
}

class UsageError extends Error {}

function vec3(text: string | undefined, what: string): [number, number, number] {
  const parts = (text ?? '').split(',').map((s) => Number(s.trim()));
  if (parts.length !== 3 || parts.some((x) => !Number.isFinite(x))) throw new UsageError(`${what}: expected x,y,z, got '${text}'`);
  return parts as [number, number, number];
}

function parse(argv: string[]) {
  let model: string | undefined;
  const o: HeadlessOptions = { mode: 'adaptive' };
  let modeSeen = 0;
  let out: string | undefined;
  let params: string | undefined;
  let stats = false;
  let surface = 'catmull-clark';
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const value = () => {
      const v = argv[++i];
      if (v === undefined || v.startsWith('--')) throw new UsageError(`${a} needs a value`);
      return v;
    };
    switch (a) {
      case '--fixed': {
        const f = Number(value());
        if (!(f >= 1 && f <= 64)) throw new UsageError(`--fixed: a tess factor in [1, 64], got ${argv[i]}`);
        o.mode = 'fixed';
        o.fixedFactor = f;
        modeSeen++;
        break;
      }
      case '--adaptive':
        o.mode = 'adaptive';
        modeSeen++;
        break;
      case '--lod': {
        const s = Number(value());
        if (!(s > 0) || !Number.isFinite(s)) throw new UsageError(`--lod: a positive number, got ${argv[i]}`);
        o.lodScale = s;
        break;
      }
      case '--eye':
        o.eye = vec3(value(), '--eye');
        break;
      case '--target':
        o.target = vec3(value(), '--target');
        break;
      case '--out':
        out = value();
        break;
      case '--params':
        params = value();
        break;
      case '--stats':
        stats = true;
        break;
      case '--surface':
        surface = value();
        break;
      case '--flat-baseline':
        o.flatBaseline = true;
        break;
      default:
        if (a.startsWith('--')) throw new UsageError(`unknown option ${a}`);
        if (model) throw new UsageError(`one model only (got '${model}' and '${a}')`);
        model = a;
    }
  }
  if (!model) throw new UsageError('no model given');
  if (modeSeen !== 1) throw new UsageError('give exactly one of --fixed F or --adaptive');
  if (!out && !stats) throw new UsageError('--out (or --stats) is required');
  if (surface !== 'phong' && surface !== 'catmull-clark') throw new UsageError(`unknown surface '${surface}' (catmull-clark or phong)`);
  o.surface = surface;
  if (o.flatBaseline && surface !== 'catmull-clark') throw new UsageError('--flat-baseline applies to the Catmull-Clark surface only');
  if (o.mode === 'fixed' && (o.lodScale || o.eye || o.target)) throw new UsageError('--lod, --eye and --target apply to --adaptive only');
  return { model, o, out, params, stats };
}

export async function main(argv: string[]): Promise<number> {
  let args: ReturnType<typeof parse>;
  let cage: ReturnType<typeof loadCage>['cage'];
  try {
    args = parse(argv);
    if (!existsSync(args.model)) throw new UsageError(`no such file: ${args.model}`);
    cage = loadCage(readFileSync(args.model, 'utf8')).cage;
  } catch (e) {
    if (e instanceof UsageError) {
      console.error(`tessellate: ${e.message}\n${USAGE}`);
      return 2;
    }
    if (e instanceof CageError) {
      console.error(`tessellate: ${argv.find((a) => !a.startsWith('--'))}: ${e.message}`);
      return 2;
    }
    throw e;
  }
  let device: GPUDevice;
  let adapterName: string;
  try {
    // --stats reads GPU timestamps: unquantised, as the benchmark reads them.
    ({ device, adapterName } = await createNodeDevice(args.stats ? ['disable-dawn-features=timestamp_quantization'] : []));
  } catch (e) {
    // No GPU: run again on SwiftShader, if it is installed.
    if (!process.env.VK_ICD_FILENAMES && existsSync(SWIFTSHADER_ICD)) {
      const r = spawnSync(process.execPath, process.argv.slice(1), {
        stdio: 'inherit',
        env: { ...process.env, VK_ICD_FILENAMES: SWIFTSHADER_ICD },
      });
      return r.status ?? 1;
    }
    console.error(`tessellate: ${(e as Error).message}`);
    return 1;
  }
  const mesh = prepareMesh(cage);
  const started = performance.now();
  const cc = args.o.surface === 'catmull-clark' ? prepareCatmullClark(cage, mesh) : undefined;
  const cpuPrepMs = performance.now() - started;
  const r = await tessellateOnce(device, cage, args.o, undefined, { mesh, cc });
  if (args.out)
    writeFileSync(
      args.out,
      meshToObj(
        r,
        `tessellab: ${args.model}, ${args.o.surface} surface, ${args.o.mode}${args.o.mode === 'fixed' ? ` ${args.o.fixedFactor}` : ''}, ${adapterName}`,
      ),
    );
  if (args.params) {
    const p = vertexParams(r, cage);
    writeFileSync(
      args.params,
      args.params.endsWith('.txt')
        ? paramsToText(p)
        : JSON.stringify({
            vertexCount: p.length,
            params: p.map((x) => (x === null ? null : 'u' in x ? [x.face, x.u, x.v] : [x.face, x.k, x.s, x.t])),
          }) + '\n',
    );
  }
  if (args.stats) {
    const timed = Object.keys(r.timings).length > 0;
    const total = Object.values(r.timings).reduce((a, b) => a + b, 0);
    const subdivision = r.timings.subdivision ?? 0;
    console.log(
      JSON.stringify({
        faces: faceCount(cage),
        cpuPrepMs: Number(cpuPrepMs.toFixed(3)),
        gpuBytes: cc ? cc.gpuBytes : 0,
        subdivisionMs: timed ? Number(subdivision.toFixed(4)) : null,
        tessellationMs: timed ? Number((total - subdivision).toFixed(4)) : null,
        vertices: r.out.vertexCount,
        triangles: r.out.triangleCount,
        adapter: adapterName,
      }),
    );
  }
  const wrote = [args.out, args.params].filter(Boolean).join(' and ');
  console.error(
    `tessellate: ${r.out.vertexCount} vertices, ${r.out.triangleCount} triangles (${r.mesh.triangleCount} cage triangles) on ${adapterName}${wrote ? `; wrote ${wrote}` : ''}`,
  );
  device.destroy();
  return 0;
}
