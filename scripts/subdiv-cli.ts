// tessellab subdivision reference CLI.
//   npm run subdiv -- --uniform N model.obj       JSON samples of the exact limit surface
//   npm run subdiv -- --points FILE model.obj     evaluate "f u v" or "f k s t" lines
//   npm run subdiv -- --refine L model.obj        uniformly refined mesh as OBJ
// Options: --file-options (honour t interpolateboundary / t creasemethod),
//          --boundary edge-and-corner|edge-only|none, --creasing uniform|chaikin, --check, --debug
// Bad input: a message and exit code 2 (src/cli/boundary.ts), as every CLI of the project.
import {
  CageError,
  type SubdivOptions,
  DEFAULT_OPTIONS,
  escapeControl,
  formatIssue,
  loadCage,
  makeCage,
  writeObj,
} from '../src/mesh/index.ts';
import { Surface, levelFromCage, refineUniform, uniformFaces, uniformSampleCount } from '../src/subdiv/index.ts';
import { endQuietlyOnClosedPipe, EXIT_BAD_INPUT, EXIT_OK, guardedSync, InputError } from '../src/cli/boundary.ts';
import { readInputText } from '../src/cli/files.ts';

const USAGE =
  'usage: subdiv [--uniform N | --points FILE | --refine L | --check] [--file-options] [--boundary edge-and-corner|edge-only|none] [--creasing uniform|chaikin] [--debug] model.obj';

/** A bad argument: its message and the usage line, exit code 2. */
class UsageError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'UsageError';
  }
}

/** --uniform writes ~150 bytes of JSON a sample (6 numbers), one line per face, each line written
 * as it is made: a line is one string (V8 caps strings at 512 MiB) and the whole has a budget. */
const BYTES_PER_SAMPLE = 150;
export const MAX_UNIFORM_LINE_BYTES = 256 * 1024 * 1024;
export const MAX_UNIFORM_BYTES = 2 * 1024 * 1024 * 1024;
/** --refine L holds the refined mesh in memory: faces × 4^L at most this many faces. */
export const MAX_REFINED_FACES = 4_000_000;

/** Where the CLI writes: the process's streams, or a test's strings. */
export interface SubdivIo {
  out: (text: string) => void;
  err: (text: string) => void;
}

const PROCESS_IO: SubdivIo = {
  out: (t) => process.stdout.write(t),
  err: (t) => process.stderr.write(t),
};

export function main(argv: string[], io: SubdivIo = PROCESS_IO): number {
  return guardedSync(
    'subdiv',
    argv,
    (a) => runWithUsage(a, io),
    (line) => io.err(`${line}\n`),
  );
}

function runWithUsage(argv: string[], io: SubdivIo): number {
  try {
    return run(argv, io);
  } catch (e) {
    if (e instanceof UsageError) {
      io.err(`subdiv: ${escapeControl(e.message)}\n${USAGE}\n`);
      return EXIT_BAD_INPUT;
    }
    throw e;
  }
}

function mib(bytes: number): string {
  return `${Math.round(bytes / 1024 / 1024)} MiB`;
}

function run(argv: string[], io: SubdivIo): number {
  const usage = (msg: string): never => {
    throw new UsageError(msg);
  };
  let uniform = -1,
    refineL = -1,
    pointsFile = '',
    model = '',
    check = false,
    fileOpts = false;
  const opts: SubdivOptions = { ...DEFAULT_OPTIONS };
  let boundarySet = false,
    creasingSet = false;
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const val = (): string => {
      if (i + 1 >= argv.length) usage(`${a} needs a value`);
      return argv[++i];
    };
    if (a === '--uniform') {
      uniform = Number(val());
      if (!Number.isInteger(uniform) || uniform < 1 || uniform > 4096) usage('--uniform needs an integer 1..4096');
    } else if (a === '--refine') {
      refineL = Number(val());
      if (!Number.isInteger(refineL) || refineL < 0 || refineL > 8) usage('--refine needs an integer 0..8');
    } else if (a === '--points') pointsFile = val();
    else if (a === '--check') check = true;
    else if (a === '--file-options') fileOpts = true;
    else if (a === '--boundary') {
      const b = val();
      if (b !== 'edge-and-corner' && b !== 'edge-only' && b !== 'none') usage(`unknown boundary mode ${b}`);
      opts.boundary = b as SubdivOptions['boundary'];
      boundarySet = true;
    } else if (a === '--creasing') {
      const c = val();
      if (c !== 'uniform' && c !== 'chaikin') usage(`unknown creasing ${c}`);
      opts.creasing = c as SubdivOptions['creasing'];
      creasingSet = true;
    } else if (a.startsWith('--')) usage(`unknown option ${a}`);
    else if (!model) model = a;
    else usage(`unexpected argument ${a}`);
  }
  if (!model) usage('no model given');
  if (uniform < 0 && refineL < 0 && !pointsFile && !check) usage('nothing to do: give --uniform, --points, --refine or --check');
  // The points file is read before the work, so a missing one is found at once.
  const pointsText = pointsFile ? readInputText(pointsFile, '--points file') : '';
  const text = readInputText(model, 'model');
  let loaded: ReturnType<typeof loadCage>;
  try {
    loaded = loadCage(text);
  } catch (e) {
    if (e instanceof CageError) throw new InputError(`${model}: refused:\n${e.message}`);
    throw e;
  }
  const { cage, topology, warnings } = loaded;
  for (const w of warnings) io.err(escapeControl(`subdiv: ${model}: warning: ${formatIssue(w)}\n`));
  if (fileOpts) {
    if (!boundarySet && cage.fileOptions.boundary) opts.boundary = cage.fileOptions.boundary;
    if (!creasingSet && cage.fileOptions.creasing) opts.creasing = cage.fileOptions.creasing;
  }
  if (check) {
    io.out(JSON.stringify({ ok: true, vertices: topology.nVerts, faces: topology.nFaces, edges: topology.nEdges }) + '\n');
    return EXIT_OK;
  }
  const S = new Surface(cage, topology, opts);
  if (uniform > 0) {
    // Sizes from counts, before any sample is made.
    const { samples, largestFace } = uniformSampleCount(S, uniform);
    if (largestFace * BYTES_PER_SAMPLE > MAX_UNIFORM_LINE_BYTES || samples * BYTES_PER_SAMPLE > MAX_UNIFORM_BYTES)
      throw new InputError(
        `--uniform ${uniform}: ${samples} samples would write about ${mib(samples * BYTES_PER_SAMPLE)} of JSON (${mib(largestFace * BYTES_PER_SAMPLE)} for one face); ` +
          `at most ${mib(MAX_UNIFORM_BYTES)} (${mib(MAX_UNIFORM_LINE_BYTES)} a face): lower N`,
      );
    // One face per line keeps the output streamable and diffable; each is written as it is made.
    io.out('{"faces":[\n');
    let first = true;
    for (const face of uniformFaces(S, uniform)) {
      for (const sub of face.sub)
        for (const x of sub.P)
          if (!Number.isFinite(x)) throw new InputError(`face ${face.f}: a limit point is not finite (the model is beyond 64-bit floats)`);
      // An undefined normal (a cone point) is NaN, written as null: JSON has no NaN.
      io.out(`${first ? '' : ',\n'}${JSON.stringify(face)}`);
      first = false;
    }
    io.out('\n]}\n');
    return EXIT_OK;
  }
  if (pointsFile) {
    const lines = pointsText.split(/\r?\n/);
    const res: unknown[] = [];
    for (let ln = 0; ln < lines.length; ln++) {
      const t = lines[ln].replace(/#.*/, '').trim();
      if (!t) continue;
      const x = t.split(/\s+/).map(Number);
      if (!(x.length === 3 || x.length === 4) || x.some((q) => !Number.isFinite(q)))
        throw new InputError(`${pointsFile}:${ln + 1}: expected "f u v" or "f k s t"`);
      const [f, k, s, tt] = x.length === 3 ? [x[0], 0, x[1], x[2]] : x;
      if (!(Number.isInteger(f) && f >= 0 && f < S.faceCount))
        throw new InputError(`${pointsFile}:${ln + 1}: face ${f} does not exist (the model has faces 0..${S.faceCount - 1})`);
      try {
        if (x.length === 3 && S.faceSize(f) !== 4) throw new RangeError(`face ${f} is not a quad: give "f k s t"`);
        if (!S.hasLimitSurface(f)) throw new RangeError(`face ${f} is a hole`);
        const r = S.evaluateSubFace(f, k, s, tt);
        res.push({ f, k, s, t: tt, P: r.P, dPdu: r.dPdu, dPdv: r.dPdv, N: r.N, atVertex: r.atVertex, normalDefined: r.normalDefined });
      } catch (e) {
        // The evaluator's RangeErrors name the face or the parameter the line gave.
        if (e instanceof RangeError) throw new InputError(`${pointsFile}:${ln + 1}: ${e.message}`);
        throw e;
      }
    }
    io.out(JSON.stringify({ points: res }) + '\n');
    return EXIT_OK;
  }
  const refinedFaces = topology.nFaces * 4 ** refineL;
  if (refinedFaces > MAX_REFINED_FACES)
    throw new InputError(
      `--refine ${refineL}: ${topology.nFaces} faces would become ${refinedFaces}, more than the ${MAX_REFINED_FACES} held: lower L`,
    );
  const L = refineUniform(levelFromCage(cage, topology, opts), refineL);
  const faces: number[][] = [];
  for (let f = 0; f < L.he.nFaces; f++) faces.push(Array.from(L.he.faceIndices.subarray(L.he.faceOffsets[f], L.he.faceOffsets[f + 1])));
  const creases: [number, number, number][] = [];
  for (let e = 0; e < L.he.nEdges; e++)
    if (L.edgeSharp[e] > 0 && L.he.edgeFaceCount[e] === 2) creases.push([L.he.edgeVerts[2 * e], L.he.edgeVerts[2 * e + 1], L.edgeSharp[e]]);
  const corners: [number, number][] = [];
  for (let v = 0; v < L.he.nVerts; v++) if (L.vertSharp[v] > 0) corners.push([v, L.vertSharp[v]]);
  const holes: number[] = [];
  for (let f = 0; f < L.he.nFaces; f++) if (L.hole[f]) holes.push(f);
  const out = makeCage(L.pos, faces, { creases, corners, holes });
  out.fileOptions = { boundary: opts.boundary, creasing: opts.creasing };
  io.out(writeObj(out, `${escapeControl(model, { newlines: false })} refined ${refineL} level(s) by tessellab's Catmull-Clark reference`));
  return EXIT_OK;
}

const isMain = process.argv[1] && /subdiv-cli\.ts$/.test(process.argv[1]);
if (isMain) {
  endQuietlyOnClosedPipe();
  process.exitCode = main(process.argv.slice(2));
}
