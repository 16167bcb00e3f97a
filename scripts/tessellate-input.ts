/**
 * The tessellate CLI's input, everything checked before a GPU is asked for (scripts/tessellate-cli.ts):
 * the arguments, the model and the height map read and validated, the output paths writable.
 * No GPU module is loaded here, so the unit tests (tests/cli/) drive it with hostile input
 * in-process. Every refusal is an error the CLI's boundary (src/cli/boundary.ts) turns into one
 * line and exit code 2.
 */
import type { HeadlessOptions } from '../src/gpu/tess/headless.ts';
import type { HeightWrap } from '../src/mesh/heightmap.ts';
import { decodeHeightPng } from '../src/mesh/heightmap-png.ts';
import { type Cage, type CageIssue, faceCount, formatIssue, loadCage, MAX_COORDINATE, requireUvs } from '../src/mesh/index.ts';
import { isPow2Level } from '../src/pattern/pow2.ts';
import { MAX_FACTOR } from '../src/pattern/max-factor.ts';
import { isAccSurface, isSurfaceId, SURFACE_IDS, surfaceScheme } from '../src/gpu/surface/registry.ts';
import { checkOutputPath, readInputBytes, readInputText } from '../src/cli/files.ts';
import { InputError } from '../src/cli/boundary.ts';

export const USAGE = `usage: npm run tessellate -- model.obj (--fixed F | --adaptive [--lod S] [--eye x,y,z --target x,y,z | --demo-view]) (--out out.obj | --stats) [--params out.json|out.txt] [--surface catmull-clark|phong|bezier-acc|gregory-acc|pm-acc] [--flat-baseline] [--limit-px] [--capacity N] [--displacement map.png --scale S [--mid M] [--wrap repeat|clamp]]
       npm run tessellate -- model.obj --tessellator instanced (--level L | --adaptive [--lod S] [--eye x,y,z --target x,y,z]) (--out out.obj | --stats) [--params out.json|out.txt] [--surface phong|catmull-clark|bezier-acc|gregory-acc|pm-acc] [--displacement map.png --scale S [--mid M] [--wrap repeat|clamp]]`;

/** The largest --capacity: 2^28 vertices and triangles (3 GiB of output each); the device's
 * binding limit usually holds fewer (the run says so). */
export const MAX_CAPACITY = 1 << 28;

/** A bad argument: its message and the usage lines, exit code 2. */
export class UsageError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'UsageError';
  }
}

function vec3(text: string | undefined, what: string): [number, number, number] {
  const parts = (text ?? '').split(',').map((s) => Number(s.trim()));
  if (parts.length !== 3 || parts.some((x) => !Number.isFinite(x))) throw new UsageError(`${what}: expected x,y,z, got '${text}'`);
  // The camera goes to the GPU in 32-bit floats, as the model does (src/mesh/range.ts).
  if (parts.some((x) => Math.abs(x) > MAX_COORDINATE))
    throw new UsageError(`${what}: coordinates within ±${MAX_COORDINATE.toExponential().replace('+', '')}, got '${text}'`);
  return parts as [number, number, number];
}

export function parse(argv: string[]) {
  let model: string | undefined;
  const o: HeadlessOptions = { mode: 'adaptive' };
  let modeSeen = 0;
  let out: string | undefined;
  let params: string | undefined;
  let stats = false;
  let surface: string | undefined;
  let tessellator = 'compute';
  let level: number | undefined;
  let demoView = false;
  let limitPx = false;
  let displacement: string | undefined;
  let scale: number | undefined;
  let mid = 0.5;
  let wrap: HeightWrap = 'repeat';
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
        if (!(f >= 1 && f <= MAX_FACTOR)) throw new UsageError(`--fixed: a tess factor in [1, ${MAX_FACTOR}], got ${argv[i]}`);
        o.mode = 'fixed';
        o.fixedFactor = f;
        modeSeen++;
        break;
      }
      case '--tessellator':
        tessellator = value();
        if (tessellator !== 'compute' && tessellator !== 'instanced')
          throw new UsageError(`unknown tessellator '${tessellator}' (compute or instanced)`);
        break;
      case '--level': {
        const L = Number(value());
        if (!isPow2Level(L)) throw new UsageError(`--level: a power of two in [1, 64], got ${argv[i]}`);
        level = L;
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
      case '--demo-view':
        demoView = true;
        break;
      case '--displacement':
        displacement = value();
        break;
      case '--scale': {
        scale = Number(value());
        // Heights are (sample − mid)·S in [−S, S], added to positions in 32-bit floats.
        if (!(Math.abs(scale) <= MAX_COORDINATE))
          throw new UsageError(
            `--scale: a number within ±${MAX_COORDINATE.toExponential().replace('+', '')} (world units per unit of height), got ${argv[i]}`,
          );
        break;
      }
      case '--mid': {
        mid = Number(value());
        if (!(mid >= 0 && mid <= 1)) throw new UsageError(`--mid: a height in [0, 1], got ${argv[i]}`);
        break;
      }
      case '--wrap': {
        const w = value();
        if (w !== 'repeat' && w !== 'clamp') throw new UsageError(`--wrap: repeat or clamp, got ${w}`);
        wrap = w;
        break;
      }
      case '--limit-px':
        limitPx = true;
        break;
      case '--capacity': {
        // Output vertices and triangles the tessellator holds (each): past it the budget scales
        // the factors down, as the demo does within its own capacity.
        const n = Number(value());
        if (!Number.isInteger(n) || n < 1 || n > MAX_CAPACITY)
          throw new UsageError(`--capacity: output vertices and triangles, an integer in [1, ${MAX_CAPACITY}], got ${argv[i]}`);
        o.vertexCapacity = n;
        o.triangleCapacity = n;
        break;
      }
      default:
        if (a.startsWith('--')) throw new UsageError(`unknown option ${a}`);
        if (model) throw new UsageError(`one model only (got '${model}' and '${a}')`);
        model = a;
    }
  }
  if (!model) throw new UsageError('no model given');
  const instanced = tessellator === 'instanced';
  if (instanced && o.vertexCapacity !== undefined) throw new UsageError('--capacity applies to the compute tessellator');
  if (instanced) {
    if (o.mode === 'fixed') throw new UsageError('--tessellator instanced takes --level L (a power of two), not --fixed');
    if (surface !== undefined && !isSurfaceId(surface))
      throw new UsageError(`--tessellator instanced: --surface ${SURFACE_IDS.join(', ')} (got ${surface})`);
    if (o.flatBaseline) throw new UsageError('--flat-baseline applies to the compute tessellator only');
  } else if (level !== undefined)
    throw new UsageError('--level applies to --tessellator instanced (the compute tessellator takes --fixed F)');
  if (modeSeen !== 1)
    throw new UsageError(instanced ? 'give exactly one of --level L or --adaptive' : 'give exactly one of --fixed F or --adaptive');
  if (!out && !stats) throw new UsageError('--out (or --stats) is required');
  surface ??= instanced ? 'phong' : 'catmull-clark';
  if (!isSurfaceId(surface)) throw new UsageError(`unknown surface '${surface}' (${SURFACE_IDS.join(', ')})`);
  const scheme = surfaceScheme(surface);
  const acc = instanced && isAccSurface(surface) ? surface : undefined;
  // The instanced tessellator takes its ACC scheme as `acc`; the compute tessellator as its surface.
  o.surface = acc ? 'phong' : surface;
  if ((demoView || limitPx) && instanced) throw new UsageError('--demo-view and --limit-px apply to the compute tessellator');
  if (limitPx && !scheme.exactLimit) throw new UsageError('--limit-px measures against the exact Catmull-Clark surface only');
  if (demoView && (o.eye || o.target)) throw new UsageError('--demo-view is a camera: not with --eye or --target');
  if (o.flatBaseline && !scheme.flatBaseline) throw new UsageError('--flat-baseline applies to the Catmull-Clark surface only');
  if ((o.mode === 'fixed' || level !== undefined) && (o.lodScale || o.eye || o.target))
    throw new UsageError('--lod, --eye and --target apply to --adaptive only');
  if (displacement === undefined && (scale !== undefined || argv.includes('--mid') || argv.includes('--wrap')))
    throw new UsageError('--scale, --mid and --wrap go with --displacement map.png');
  if (displacement !== undefined && scale === undefined)
    throw new UsageError('--displacement needs --scale S (world units per unit of height)');
  const disp = displacement === undefined ? undefined : { path: displacement, scale: scale as number, midLevel: mid, wrap };
  return {
    model,
    o,
    out,
    params,
    stats,
    instanced,
    level,
    acc,
    demoView,
    limitPx,
    disp,
    instancedCC: instanced && scheme.instancedKind === 'lent-limit',
  };
}

export type TessellateArgs = ReturnType<typeof parse>;

export interface TessellateInput {
  args: TessellateArgs;
  cage: Cage;
  /** The loader's remarks (unused vertices, zero-area faces …) and the CLI's, to print before the run. */
  warnings: string[];
}

/**
 * Parse argv, read and check the model (and height map), and check the outputs can be written:
 * everything that can fail before the GPU run. Throws UsageError, InputError, CageError,
 * LimitError or HeightMapError.
 */
export function loadInput(argv: string[]): TessellateInput {
  const args = parse(argv);
  // Outputs first: a missing folder is found now, not after the run.
  if (args.out) checkOutputPath(args.out, '--out');
  if (args.params) checkOutputPath(args.params, '--params');
  const loaded = loadCage(readInputText(args.model, 'model'));
  const { cage } = loaded;
  const warnings = loaded.warnings.map((w: CageIssue) => `${args.model}: warning: ${formatIssue(w)}`);
  let drawn = 0;
  const holes = new Set(cage.holes);
  for (let f = 0; f < faceCount(cage); f++) if (!holes.has(f)) drawn++;
  if (drawn === 0) throw new InputError(`${args.model}: every face is a hole (t hole): nothing to tessellate`);
  if (args.o.eye && args.o.target && args.o.eye.every((x, i) => x === args.o.target?.[i]))
    warnings.push('warning: --eye and --target are the same point: the view has no direction (an identity view is used)');
  if (args.disp) {
    const map = decodeHeightPng(readInputBytes(args.disp.path, 'height map'));
    requireUvs(cage);
    args.o.displacement = { map, scale: args.disp.scale, midLevel: args.disp.midLevel, wrap: args.disp.wrap };
  }
  return { args, cage, warnings };
}

/** Throws an InputError naming the first output vertex (1-based) with a NaN or an infinity among
 * the first `vertexCount` of `positions` (xyz each): both tessellators check their output with it
 * before anything is written or counted (--stats too), so a NaN is never an output. */
export function refuseNonFiniteOutput(model: string, positions: ArrayLike<number>, vertexCount: number): void {
  for (let i = 0; i < 3 * vertexCount; i++)
    if (!Number.isFinite(positions[i]))
      throw new InputError(
        `${model}: output vertex ${Math.floor(i / 3) + 1} is not finite: nothing written (the model, --scale or the camera is beyond 32-bit floats)`,
      );
}
