// Wavefront OBJ reader/writer for subdivision cages, with OpenSubdiv's
// regression-shape tag lines (`t crease 2/1/0 v0 v1 s`, 0-based indices).
import { CageError, type CageIssue } from './errors.ts';
import { escapeControl } from './text.ts';
import {
  type Cage,
  type CornerTag,
  type CreaseTag,
  type RawTag,
  type SubdivOptions,
  SHARPNESS_INFINITE,
  normaliseSharpness,
} from './types.ts';

export interface ParseResult {
  cage: Cage;
  /** Non-fatal remarks (ignored statements, unused vertices ...). */
  warnings: CageIssue[];
}

const FLOAT_RE = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;
const INT_RE = /^[+-]?\d+$/;
const IGNORED = new Set([
  'o',
  'g',
  's',
  'usemtl',
  'mtllib',
  'l',
  'p',
  'vp',
  'cstype',
  'deg',
  'bmat',
  'step',
  'curv',
  'curv2',
  'surf',
  'parm',
  'trim',
  'hole',
  'scrv',
  'sp',
  'end',
  'con',
  'mg',
  'bevel',
  'c_interp',
  'd_interp',
  'lod',
  'maplib',
  'usemap',
  'shadow_obj',
  'trace_obj',
  'ctech',
  'stech',
]);
/** OBJ statements that only matter for rendering, silently accepted. */
const SILENT = new Set(['o', 'g', 's', 'usemtl', 'mtllib']);

function parseFloatTok(tok: string): number | string {
  if (!FLOAT_RE.test(tok)) {
    const low = tok.toLowerCase();
    if (/^[+-]?(nan|inf|infinity)$/.test(low)) return `non-finite number "${tok}"`;
    return `"${clip(tok)}" is not a number`;
  }
  const x = Number(tok);
  if (!Number.isFinite(x)) return `number "${clip(tok)}" overflows to infinity`;
  return x;
}

/** A token quoted in a message: cut short, its control characters escaped (a file's bytes must not
 * drive the terminal or the page that shows the message). */
function clip(s: string): string {
  return escapeControl(s.length > 24 ? s.slice(0, 21) + '...' : s, { newlines: false });
}

interface PendingFace {
  v: number[];
  vt: number[];
  vn: number[];
  line: number;
}

/**
 * Parse OBJ text into a cage. Throws `CageError` (listing every problem with its
 * line) for malformed input; never throws anything else, never loops forever.
 * Topological validation (manifoldness, winding, crease edges) is in `buildTopology`.
 */
export function parseObj(text: string): ParseResult {
  const errors: CageIssue[] = [];
  const warnings: CageIssue[] = [];
  const err = (line: number, message: string): void => {
    if (errors.length < 1000) errors.push({ line, message });
  };
  const pos: number[] = [];
  const vLines: number[] = [];
  const uvs: number[] = [];
  const nrm: number[] = [];
  const faces: PendingFace[] = [];
  const creases: CreaseTag[] = [];
  const corners: CornerTag[] = [];
  const holes: number[] = [];
  const holeLines: number[] = [];
  const rawTags: RawTag[] = [];
  const fileOptions: Partial<SubdivOptions> = {};
  const ignoredSeen = new Set<string>();
  if (typeof text !== 'string') throw new CageError([{ line: 0, message: 'input is not text' }]);

  const physical = text.split(/\r\n|\n|\r/);
  let i = 0;
  while (i < physical.length) {
    const lineNo = i + 1;
    let logical = physical[i++];
    // Line continuation: a trailing backslash joins the next physical line.
    while (/\\\s*$/.test(logical) && i < physical.length) {
      logical = logical.replace(/\\\s*$/, ' ') + physical[i++];
    }
    if (/\\\s*$/.test(logical)) logical = logical.replace(/\\\s*$/, ' ');
    const hash = logical.indexOf('#');
    if (hash >= 0) logical = logical.slice(0, hash);
    const toks = logical.trim().split(/\s+/);
    if (toks.length === 0 || toks[0] === '') continue;
    const kw = toks[0];
    const args = toks.slice(1);
    switch (kw) {
      case 'v': {
        if (args.length < 3) {
          err(lineNo, `vertex needs 3 coordinates, got ${args.length}`);
          break;
        }
        if (args.length > 7) {
          err(lineNo, `vertex has ${args.length} values (expected 3, 4 or 6/7 with colour)`);
          break;
        }
        const xyz: number[] = [];
        let ok = true;
        for (let k = 0; k < args.length; k++) {
          const x = parseFloatTok(args[k]);
          if (typeof x === 'string') {
            err(lineNo, `vertex coordinate ${k + 1}: ${x}`);
            ok = false;
            break;
          }
          if (k < 3) xyz.push(x);
        }
        // Keep the vertex (possibly as 0,0,0) so later indices still line up.
        pos.push(ok ? xyz[0] : 0, ok ? xyz[1] : 0, ok ? xyz[2] : 0);
        vLines.push(lineNo);
        break;
      }
      case 'vt': {
        if (args.length < 1 || args.length > 3) {
          err(lineNo, `texture coordinate needs 1-3 values, got ${args.length}`);
          uvs.push(0, 0);
          break;
        }
        const u = parseFloatTok(args[0]);
        const v = args.length > 1 ? parseFloatTok(args[1]) : 0;
        if (typeof u === 'string') err(lineNo, `texture coordinate: ${u}`);
        if (typeof v === 'string') err(lineNo, `texture coordinate: ${v}`);
        uvs.push(typeof u === 'number' ? u : 0, typeof v === 'number' ? v : 0);
        break;
      }
      case 'vn': {
        if (args.length !== 3) {
          err(lineNo, `normal needs 3 values, got ${args.length}`);
          nrm.push(0, 0, 0);
          break;
        }
        for (const a of args) {
          const x = parseFloatTok(a);
          if (typeof x === 'string') {
            err(lineNo, `normal: ${x}`);
            nrm.push(0);
          } else nrm.push(x);
        }
        break;
      }
      case 'f': {
        if (args.length < 3) {
          err(lineNo, `face needs at least 3 corners, got ${args.length}`);
          break;
        }
        const face: PendingFace = { v: [], vt: [], vn: [], line: lineNo };
        let ok = true;
        const nv = pos.length / 3,
          nt = uvs.length / 2,
          nn = nrm.length / 3;
        for (const a of args) {
          const parts = a.split('/');
          if (parts.length > 3 || parts[0] === '') {
            err(lineNo, `malformed face corner "${clip(a)}" (expected v, v/vt, v//vn or v/vt/vn)`);
            ok = false;
            break;
          }
          const idx = [-1, -1, -1];
          for (let p = 0; p < parts.length; p++) {
            const s = parts[p];
            if (s === '' && p > 0) continue;
            if (!INT_RE.test(s)) {
              err(lineNo, `malformed face corner "${clip(a)}": "${clip(s)}" is not an integer index`);
              ok = false;
              break;
            }
            const n = Number(s);
            const count = p === 0 ? nv : p === 1 ? nt : nn;
            const what = p === 0 ? 'vertex' : p === 1 ? 'texture coordinate' : 'normal';
            if (n === 0) {
              err(lineNo, `${what} index 0 is invalid (OBJ indices start at 1)`);
              ok = false;
              break;
            }
            if (n < 0) {
              if (-n > count) {
                err(lineNo, `relative ${what} index ${n} is out of range (only ${count} defined so far)`);
                ok = false;
                break;
              }
              idx[p] = count + n;
            } else {
              if (!Number.isSafeInteger(n)) {
                err(lineNo, `${what} index ${clip(s)} is out of range`);
                ok = false;
                break;
              }
              idx[p] = n - 1; // range checked at the end (forward references allowed)
            }
          }
          if (!ok) break;
          face.v.push(idx[0]);
          face.vt.push(idx[1]);
          face.vn.push(idx[2]);
        }
        if (ok) faces.push(face);
        break;
      }
      case 't':
        parseTag(args, lineNo, err, warnings, { creases, corners, holes, holeLines, rawTags, fileOptions }, logical.trim());
        break;
      default:
        if (IGNORED.has(kw)) {
          if (!SILENT.has(kw) && !ignoredSeen.has(kw)) {
            ignoredSeen.add(kw);
            warnings.push({ line: lineNo, message: `"${kw}" statements are ignored` });
          }
        } else {
          err(lineNo, `unknown statement "${clip(kw)}"`);
        }
    }
  }

  const nv = pos.length / 3,
    nt = uvs.length / 2,
    nn = nrm.length / 3;
  for (const f of faces) {
    for (let j = 0; j < f.v.length; j++) {
      if (f.v[j] >= nv) err(f.line, `vertex index ${f.v[j] + 1} is out of range (${nv} vertices)`);
      if (f.vt[j] >= nt) err(f.line, `texture coordinate index ${f.vt[j] + 1} is out of range (${nt} defined)`);
      if (f.vn[j] >= nn) err(f.line, `normal index ${f.vn[j] + 1} is out of range (${nn} defined)`);
    }
    // A face may repeat a vertex (OpenSubdiv's "quad pole" and pinched faces, even a quad of one
    // vertex): src/mesh/manifold.ts splits such corners apart where OpenSubdiv's rules keep them
    // apart (sharp), and refuses the face where they are joined.
  }
  for (const c of creases) {
    if (c.v0 >= nv || c.v1 >= nv) err(c.line, `crease vertex index out of range (0-based, ${nv} vertices)`);
    else if (c.v0 === c.v1) err(c.line, `crease from vertex ${c.v0} to itself`);
  }
  for (const c of corners) if (c.v >= nv) err(c.line, `corner vertex index ${c.v} out of range (0-based, ${nv} vertices)`);
  for (let k = 0; k < holes.length; k++)
    if (holes[k] >= faces.length) err(holeLines[k], `hole face index ${holes[k]} out of range (0-based, ${faces.length} faces)`);
  if (faces.length === 0 && errors.length === 0) err(0, pos.length === 0 ? 'empty file: no vertices and no faces' : 'no faces');
  if (errors.length > 0) {
    errors.sort((a, b) => a.line - b.line);
    throw new CageError(errors);
  }

  let total = 0;
  for (const f of faces) total += f.v.length;
  const faceOffsets = new Int32Array(faces.length + 1);
  const faceIndices = new Int32Array(total);
  const faceUv = new Int32Array(total);
  const faceNrm = new Int32Array(total);
  const faceLines = new Int32Array(faces.length);
  let k = 0;
  faces.forEach((f, fi) => {
    faceLines[fi] = f.line;
    for (let j = 0; j < f.v.length; j++) {
      faceIndices[k] = f.v[j];
      faceUv[k] = f.vt[j];
      faceNrm[k] = f.vn[j];
      k++;
    }
    faceOffsets[fi + 1] = k;
  });
  return {
    cage: {
      positions: Float64Array.from(pos),
      faceOffsets,
      faceIndices,
      uvs: Float64Array.from(uvs),
      faceUvIndices: faceUv,
      normals: Float64Array.from(nrm),
      faceNormalIndices: faceNrm,
      creases,
      corners,
      holes,
      holeLines,
      fileOptions,
      rawTags,
      faceLines,
      vertexLines: Int32Array.from(vLines),
    },
    warnings,
  };
}

interface TagSink {
  creases: CreaseTag[];
  corners: CornerTag[];
  holes: number[];
  holeLines: number[];
  rawTags: RawTag[];
  fileOptions: Partial<SubdivOptions>;
}

function parseTag(
  args: string[],
  line: number,
  err: (l: number, m: string) => void,
  warnings: CageIssue[],
  sink: TagSink,
  text: string,
): void {
  if (args.length < 2) {
    err(line, 'tag needs a name and counts "nInt/nFloat/nString"');
    return;
  }
  const name = args[0];
  const m = /^(\d+)\/(\d+)\/(\d+)$/.exec(args[1]);
  if (!m) {
    err(line, `tag "${clip(name)}": counts "${clip(args[1])}" are not of the form nInt/nFloat/nString`);
    return;
  }
  const ni = Number(m[1]),
    nf = Number(m[2]),
    ns = Number(m[3]);
  const rest = args.slice(2);
  if (ni + nf + ns !== rest.length) {
    err(line, `tag "${clip(name)}": counts ${args[1]} announce ${ni + nf + ns} values but ${rest.length} follow`);
    return;
  }
  const ints: number[] = [];
  for (let k = 0; k < ni; k++) {
    const s = rest[k];
    if (!INT_RE.test(s)) {
      err(line, `tag "${clip(name)}": "${clip(s)}" is not an integer`);
      return;
    }
    const n = Number(s);
    if (n < 0 || !Number.isSafeInteger(n)) {
      err(line, `tag "${clip(name)}": index ${clip(s)} is negative or too large (tag indices are 0-based)`);
      return;
    }
    ints.push(n);
  }
  const floats: number[] = [];
  for (let k = 0; k < nf; k++) {
    const x = parseFloatTok(rest[ni + k]);
    if (typeof x === 'string') {
      err(line, `tag "${clip(name)}": ${x}`);
      return;
    }
    floats.push(x);
  }
  const strs = rest.slice(ni + nf);
  switch (name) {
    case 'crease': {
      if (ni < 2 || ni % 2 !== 0) {
        err(line, `crease tag needs pairs of vertex indices, got ${ni} integers`);
        return;
      }
      if (nf !== 1 && nf !== ni / 2) {
        err(line, `crease tag needs 1 sharpness or one per edge, got ${nf}`);
        return;
      }
      for (let k = 0; k < ni; k += 2) {
        const s = nf === 1 ? floats[0] : floats[k / 2];
        if (s < 0) {
          err(line, `crease sharpness ${s} is negative`);
          return;
        }
        sink.creases.push({ v0: ints[k], v1: ints[k + 1], sharpness: normaliseSharpness(s), line });
      }
      return;
    }
    case 'corner': {
      if (ni < 1) {
        err(line, 'corner tag needs at least one vertex index');
        return;
      }
      if (nf !== 1 && nf !== ni) {
        err(line, `corner tag needs 1 sharpness or one per vertex, got ${nf}`);
        return;
      }
      for (let k = 0; k < ni; k++) {
        const s = nf === 1 ? floats[0] : floats[k];
        if (s < 0) {
          err(line, `corner sharpness ${s} is negative`);
          return;
        }
        sink.corners.push({ v: ints[k], sharpness: normaliseSharpness(s), line });
      }
      return;
    }
    case 'hole':
      if (ni < 1) {
        err(line, 'hole tag needs at least one face index');
        return;
      }
      for (const f of ints) {
        sink.holes.push(f);
        sink.holeLines.push(line);
      }
      return;
    case 'interpolateboundary': {
      if (ni !== 1 || ints[0] > 2) {
        err(line, 'interpolateboundary tag needs one integer: 0 none, 1 edge-and-corner, 2 edge-only');
        return;
      }
      sink.fileOptions.boundary = (['none', 'edge-and-corner', 'edge-only'] as const)[ints[0]];
      return;
    }
    case 'creasemethod': {
      const s = strs[0];
      if (ns !== 1 || (s !== 'normal' && s !== 'uniform' && s !== 'chaikin')) {
        err(line, 'creasemethod tag needs one string: normal or chaikin');
        return;
      }
      sink.fileOptions.creasing = s === 'chaikin' ? 'chaikin' : 'uniform';
      return;
    }
    default:
      sink.rawTags.push({ text, line });
      warnings.push({ line, message: `tag "${clip(name)}" is kept but not interpreted` });
  }
}

function fmt(x: number): string {
  // Shortest round-trip representation.
  return Object.is(x, -0) ? '0' : String(x);
}

/** Write a cage as OBJ (1-based indices, tags 0-based); `parseObj(writeObj(c))` reproduces `c`. */
export function writeObj(c: Cage, header?: string): string {
  const out: string[] = [];
  if (header) for (const l of header.split('\n')) out.push(`# ${l}`);
  const P = c.positions;
  for (let i = 0; i < P.length; i += 3) out.push(`v ${fmt(P[i])} ${fmt(P[i + 1])} ${fmt(P[i + 2])}`);
  for (let i = 0; i < c.uvs.length; i += 2) out.push(`vt ${fmt(c.uvs[i])} ${fmt(c.uvs[i + 1])}`);
  for (let i = 0; i < c.normals.length; i += 3) out.push(`vn ${fmt(c.normals[i])} ${fmt(c.normals[i + 1])} ${fmt(c.normals[i + 2])}`);
  const nf = c.faceOffsets.length - 1;
  for (let f = 0; f < nf; f++) {
    const parts: string[] = [];
    for (let k = c.faceOffsets[f]; k < c.faceOffsets[f + 1]; k++) {
      const v = c.faceIndices[k] + 1;
      const t = c.faceUvIndices[k],
        n = c.faceNormalIndices[k];
      if (t < 0 && n < 0) parts.push(`${v}`);
      else if (n < 0) parts.push(`${v}/${t + 1}`);
      else if (t < 0) parts.push(`${v}//${n + 1}`);
      else parts.push(`${v}/${t + 1}/${n + 1}`);
    }
    out.push(`f ${parts.join(' ')}`);
  }
  const fo = c.fileOptions;
  if (fo.boundary) out.push(`t interpolateboundary 1/0/0 ${{ none: 0, 'edge-and-corner': 1, 'edge-only': 2 }[fo.boundary]}`);
  if (fo.creasing) out.push(`t creasemethod 0/0/1 ${fo.creasing === 'chaikin' ? 'chaikin' : 'normal'}`);
  for (const t of c.rawTags) out.push(t.text);
  for (const cr of c.creases) out.push(`t crease 2/1/0 ${cr.v0} ${cr.v1} ${fmt(Math.min(cr.sharpness, SHARPNESS_INFINITE))}`);
  for (const co of c.corners) out.push(`t corner 1/1/0 ${co.v} ${fmt(co.sharpness)}`);
  if (c.holes.length) out.push(`t hole ${c.holes.length}/0/0 ${c.holes.join(' ')}`);
  return out.join('\n') + '\n';
}
