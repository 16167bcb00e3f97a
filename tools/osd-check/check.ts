// Cross-check tessellab's exact Catmull-Clark reference (`npm run subdiv -- --uniform N`)
// against OpenSubdiv's limit surface (tools/osd-check/osd_eval) on every cage given.
//   tsx tools/osd-check/check.ts --osd BIN [--res N] [--file-options] [--json OUT] PATH...
// PATH: .obj files or directories of them. Exits 1 if any accepted cage fails.
import { spawnSync } from 'node:child_process';
import { readFileSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import { CageError, type SubdivOptions, DEFAULT_OPTIONS, computeSharpness, loadCage } from '../../src/mesh/index.ts';

const TOL = 1e-7; // relative to the bounding-box diagonal
const NAMED_TOL = 1e-4; // OpenSubdiv's own inexact limits (darts, interior valence 2)

interface Samples {
  faces: { f: number; n: number; hole?: boolean; sub: { k: number; res: number; P: number[]; N: (number | null)[] }[] }[];
}

interface Row {
  cage: string;
  status: 'pass' | 'FAIL' | 'refused' | 'error';
  faces?: number;
  samples?: number;
  maxRel?: number;
  rmsRel?: number;
  at?: string;
  named?: number;
  namedMax?: number;
  namedWhere?: string;
  normalMaxDeg?: number;
  options?: string;
  note?: string;
}

const args = process.argv.slice(2);
let osd = '',
  res = 8,
  fileOptions = false,
  jsonOut = '',
  far = false;
const paths: string[] = [];
for (let i = 0; i < args.length; i++) {
  if (args[i] === '--osd') osd = args[++i];
  else if (args[i] === '--res') res = Number(args[++i]);
  else if (args[i] === '--file-options') fileOptions = true;
  else if (args[i] === '--json') jsonOut = args[++i];
  else if (args[i] === '--far') far = true;
  else paths.push(args[i]);
}
if (!osd) {
  console.error('need --osd BIN');
  process.exit(64);
}
const files: string[] = [];
for (const p of paths) {
  if (statSync(p).isDirectory())
    for (const f of readdirSync(p).sort()) {
      if (f.endsWith('.obj')) files.push(join(p, f));
    }
  else files.push(p);
}

const tsx = join(process.cwd(), 'node_modules', '.bin', 'tsx');
const rows: Row[] = [];
let failed = false;
for (const file of files) {
  const name = basename(file);
  const text = readFileSync(file, 'utf8');
  let loaded: ReturnType<typeof loadCage>;
  try {
    loaded = loadCage(text);
  } catch (e) {
    if (e instanceof CageError) {
      rows.push({
        cage: name,
        status: 'refused',
        note: e.issues[0] ? `${e.issues[0].line ? `line ${e.issues[0].line}: ` : ''}${e.issues[0].message}` : e.message,
      });
      continue;
    }
    throw e;
  }
  const { cage, topology: T } = loaded;
  const opts: SubdivOptions = { ...DEFAULT_OPTIONS };
  if (fileOptions) Object.assign(opts, cage.fileOptions);
  const optNote = (fileOptions ? `${opts.boundary}/${opts.creasing}` : 'defaults') + (far ? ' vs Far' : ' vs Bfr');
  const extra = fileOptions ? ['--file-options'] : [];
  const t0 = Date.now();
  const mine = spawnSync(tsx, ['scripts/subdiv-cli.ts', ...extra, '--uniform', String(res), file], {
    encoding: 'utf8',
    maxBuffer: 1 << 30,
  });
  const tMine = (Date.now() - t0) / 1000;
  const ref = spawnSync(osd, [...extra, ...(far ? ['--far'] : []), String(res), file], { encoding: 'utf8', maxBuffer: 1 << 30 });
  if (mine.status !== 0 || ref.status !== 0) {
    rows.push({
      cage: name,
      status: 'error',
      note: `tessellab exit ${mine.status}: ${mine.stderr.slice(0, 200)} / osd exit ${ref.status}: ${ref.stderr.slice(0, 200)}`,
    });
    failed = true;
    continue;
  }
  const A: Samples = JSON.parse(mine.stdout),
    B: Samples = JSON.parse(ref.stdout);
  // Bounding-box diagonal of the vertices used by faces.
  const lo = [Infinity, Infinity, Infinity],
    hi = [-Infinity, -Infinity, -Infinity];
  for (let h = 0; h < cage.faceIndices.length; h++) {
    const v = cage.faceIndices[h];
    for (let c = 0; c < 3; c++) {
      lo[c] = Math.min(lo[c], cage.positions[3 * v + c]);
      hi[c] = Math.max(hi[c], cage.positions[3 * v + c]);
    }
  }
  const diag = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  // Vertices where OpenSubdiv's own limit is approximate: darts (one infinitely
  // sharp edge once semi-sharpness has decayed) and interior valence-2 vertices.
  const sh = computeSharpness(cage, T, opts);
  const approx = new Map<number, string>();
  for (let v = 0; v < T.nVerts; v++) {
    const nf = T.vertHeOffsets[v + 1] - T.vertHeOffsets[v];
    if (!nf) continue;
    let inf = 0;
    for (let k = T.vertEdgeOffsets[v]; k < T.vertEdgeOffsets[v + 1]; k++) if (sh.edge[T.vertEdges[k]] >= 10) inf++;
    if (inf === 1 && sh.vertex[v] < 10) approx.set(v, 'dart');
    else if (!T.vertBoundary[v] && T.valence[v] === 2) approx.set(v, 'interior valence 2');
  }
  const row: Row = {
    cage: name,
    status: 'pass',
    faces: T.nFaces,
    samples: 0,
    maxRel: 0,
    rmsRel: 0,
    named: 0,
    namedMax: 0,
    normalMaxDeg: 0,
    options: optNote,
  };
  let sum2 = 0,
    count = 0;
  let problem = '';
  if (A.faces.length !== B.faces.length) problem = `face count ${A.faces.length} vs ${B.faces.length}`;
  for (let fi = 0; fi < A.faces.length && !problem; fi++) {
    const a = A.faces[fi],
      b = B.faces[fi];
    if (!!a.hole !== !!b.hole) {
      problem = `face ${fi}: hole mismatch`;
      break;
    }
    if (a.sub.length !== b.sub.length) {
      problem = `face ${fi}: sub-face count`;
      break;
    }
    const f0 = T.faceOffsets[fi];
    for (let s = 0; s < a.sub.length; s++) {
      const sa = a.sub[s],
        sb = b.sub[s];
      const R = sa.res;
      for (let j = 0; j <= R; j++)
        for (let i = 0; i <= R; i++) {
          const o = 3 * (j * (R + 1) + i);
          const d = Math.hypot(sa.P[o] - sb.P[o], sa.P[o + 1] - sb.P[o + 1], sa.P[o + 2] - sb.P[o + 2]) / diag;
          // Is this sample a cage vertex?
          let cv = -1;
          if (a.n === 4) {
            const c = i === 0 && j === 0 ? 0 : i === R && j === 0 ? 1 : i === R && j === R ? 2 : i === 0 && j === R ? 3 : -1;
            if (c >= 0) cv = T.faceIndices[f0 + c];
          } else if (i === 0 && j === 0) cv = T.faceIndices[f0 + sa.k];
          const why = cv >= 0 ? approx.get(cv) : undefined;
          if (why) {
            row.named!++;
            if (d > row.namedMax!) {
              row.namedMax = d;
              row.namedWhere = `face ${fi} sub ${sa.k} (${i},${j}) = vertex ${cv} (${why})`;
            }
            continue;
          }
          if (!(d <= row.maxRel!)) {
            row.maxRel = d;
            row.at = `face ${fi} sub ${sa.k} (${i},${j})`;
          }
          sum2 += d * d;
          count++;
          // Normals (information only): where both are defined, away from (sub-)face corners,
          // where OpenSubdiv's normals at irregular vertices are approximate.
          const na = sa.N,
            nb = sb.N;
          const subCorner = (i === 0 || i === R) && (j === 0 || j === R);
          if (!subCorner && na[o] !== null && nb[o] !== null) {
            const x = na.slice(o, o + 3) as number[],
              y = nb.slice(o, o + 3) as number[];
            const dot = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
            const cr = Math.hypot(x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]);
            const ang = (Math.atan2(cr, dot) * 180) / Math.PI;
            if (ang > row.normalMaxDeg!) row.normalMaxDeg = ang;
          }
        }
    }
  }
  row.samples = count;
  row.rmsRel = count ? Math.sqrt(sum2 / count) : 0;
  row.note = `tessellab ${tMine.toFixed(1)} s`;
  if (problem) {
    row.status = 'FAIL';
    row.note = problem;
  } else if (!(row.maxRel! <= TOL) || !(row.namedMax! <= NAMED_TOL)) row.status = 'FAIL';
  if (row.status !== 'pass') failed = true;
  rows.push(row);
  const e = (x?: number): string => (x === undefined ? '-' : x.toExponential(2));
  console.log(
    `${row.status.padEnd(7)} ${name.padEnd(34)} max ${e(row.maxRel)} rms ${e(row.rmsRel)} named ${row.named} (max ${e(row.namedMax)}) normal ${row.normalMaxDeg!.toExponential(1)} deg  ${row.note}${row.status !== 'pass' && row.at ? ` at ${row.at}` : ''}`,
  );
}
for (const r of rows)
  if (r.status === 'refused' || r.status === 'error') console.log(`${r.status.padEnd(7)} ${r.cage.padEnd(34)} ${r.note}`);
const pass = rows.filter((r) => r.status === 'pass').length;
console.log(
  `\n${pass} passed, ${rows.filter((r) => r.status === 'FAIL').length} failed, ${rows.filter((r) => r.status === 'error').length} errors, ${rows.filter((r) => r.status === 'refused').length} refused (tolerance ${TOL} x bbox diagonal)`,
);
if (jsonOut) writeFileSync(jsonOut, JSON.stringify(rows, null, 1));
process.exit(failed ? 1 : 0);
