// tessellab subdivision reference CLI.
//   npm run subdiv -- --uniform N model.obj       JSON samples of the exact limit surface
//   npm run subdiv -- --points FILE model.obj     evaluate "f u v" or "f k s t" lines
//   npm run subdiv -- --refine L model.obj        uniformly refined mesh as OBJ
// Options: --file-options (honour t interpolateboundary / t creasemethod),
//          --boundary edge-and-corner|edge-only|none, --creasing uniform|chaikin, --check
import { readFileSync } from 'node:fs';
import { CageError, type SubdivOptions, DEFAULT_OPTIONS, loadCage, makeCage, writeObj } from '../src/mesh/index.ts';
import { Surface, levelFromCage, refineUniform, sampleUniform } from '../src/subdiv/index.ts';

function usage(msg?: string): never {
  if (msg) process.stderr.write(`subdiv: ${msg}\n`);
  process.stderr.write(
    'usage: subdiv [--uniform N | --points FILE | --refine L | --check] [--file-options] [--boundary edge-and-corner|edge-only|none] [--creasing uniform|chaikin] model.obj\n',
  );
  process.exit(64);
}

export function main(argv: string[]): number {
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
      opts.boundary = b;
      boundarySet = true;
    } else if (a === '--creasing') {
      const c = val();
      if (c !== 'uniform' && c !== 'chaikin') usage(`unknown creasing ${c}`);
      opts.creasing = c;
      creasingSet = true;
    } else if (a.startsWith('--')) usage(`unknown option ${a}`);
    else if (!model) model = a;
    else usage(`unexpected argument ${a}`);
  }
  if (!model) usage('no model given');
  let text: string;
  try {
    text = readFileSync(model, 'utf8');
  } catch (e) {
    process.stderr.write(`subdiv: cannot read ${model}: ${(e as Error).message}\n`);
    return 66;
  }
  let loaded: ReturnType<typeof loadCage>;
  try {
    loaded = loadCage(text);
  } catch (e) {
    if (e instanceof CageError) {
      process.stderr.write(`subdiv: ${model}: refused:\n${e.message}\n`);
      return 2;
    }
    throw e;
  }
  const { cage, topology, warnings } = loaded;
  for (const w of warnings) process.stderr.write(`subdiv: ${model}: warning: ${w.line ? `line ${w.line}: ` : ''}${w.message}\n`);
  if (fileOpts) {
    if (!boundarySet && cage.fileOptions.boundary) opts.boundary = cage.fileOptions.boundary;
    if (!creasingSet && cage.fileOptions.creasing) opts.creasing = cage.fileOptions.creasing;
  }
  if (check) {
    process.stdout.write(JSON.stringify({ ok: true, vertices: topology.nVerts, faces: topology.nFaces, edges: topology.nEdges }) + '\n');
    return 0;
  }
  const S = new Surface(cage, topology, opts);
  if (uniform > 0) {
    const out = sampleUniform(S, uniform);
    // One face per line keeps the output streamable and diffable.
    const parts = out.faces.map((f) => JSON.stringify(f));
    process.stdout.write(`{"faces":[\n${parts.join(',\n')}\n]}\n`);
    return 0;
  }
  if (pointsFile) {
    const lines = readFileSync(pointsFile, 'utf8').split(/\r?\n/);
    const res: unknown[] = [];
    for (let ln = 0; ln < lines.length; ln++) {
      const t = lines[ln].replace(/#.*/, '').trim();
      if (!t) continue;
      const x = t.split(/\s+/).map(Number);
      if (!(x.length === 3 || x.length === 4) || x.some((q) => !Number.isFinite(q))) {
        process.stderr.write(`subdiv: ${pointsFile}:${ln + 1}: expected "f u v" or "f k s t"\n`);
        return 65;
      }
      const [f, k, s, tt] = x.length === 3 ? [x[0], 0, x[1], x[2]] : x;
      try {
        if (x.length === 3 && S.faceSize(f) !== 4) throw new RangeError(`face ${f} is not a quad: give "f k s t"`);
        if (!S.hasLimitSurface(f)) throw new RangeError(`face ${f} is a hole`);
        const r = S.evaluateSubFace(f, k, s, tt);
        res.push({ f, k, s, t: tt, P: r.P, dPdu: r.dPdu, dPdv: r.dPdv, N: r.N, atVertex: r.atVertex, normalDefined: r.normalDefined });
      } catch (e) {
        process.stderr.write(`subdiv: ${pointsFile}:${ln + 1}: ${(e as Error).message}\n`);
        return 65;
      }
    }
    process.stdout.write(JSON.stringify({ points: res }) + '\n');
    return 0;
  }
  if (refineL >= 0) {
    const L = refineUniform(levelFromCage(cage, topology, opts), refineL);
    const faces: number[][] = [];
    for (let f = 0; f < L.he.nFaces; f++) faces.push(Array.from(L.he.faceIndices.subarray(L.he.faceOffsets[f], L.he.faceOffsets[f + 1])));
    const creases: [number, number, number][] = [];
    for (let e = 0; e < L.he.nEdges; e++)
      if (L.edgeSharp[e] > 0 && L.he.edgeFaceCount[e] === 2)
        creases.push([L.he.edgeVerts[2 * e], L.he.edgeVerts[2 * e + 1], L.edgeSharp[e]]);
    const corners: [number, number][] = [];
    for (let v = 0; v < L.he.nVerts; v++) if (L.vertSharp[v] > 0) corners.push([v, L.vertSharp[v]]);
    const holes: number[] = [];
    for (let f = 0; f < L.he.nFaces; f++) if (L.hole[f]) holes.push(f);
    const out = makeCage(L.pos, faces, { creases, corners, holes });
    out.fileOptions = { boundary: opts.boundary, creasing: opts.creasing };
    process.stdout.write(writeObj(out, `${model} refined ${refineL} level(s) by tessellab's Catmull-Clark reference`));
    return 0;
  }
  usage('nothing to do: give --uniform, --points, --refine or --check');
}

const isMain = process.argv[1] && /subdiv-cli\.ts$/.test(process.argv[1]);
if (isMain) process.exitCode = main(process.argv.slice(2));
