/**
 * The pattern CLI as a pure function (argv → stdout, stderr, exit code), so it is tested
 * without spawning processes. scripts/pattern-cli.ts is the thin Node wrapper.
 */
import { escapeControl } from '../mesh/text.ts';
import { toUnit } from './fixed.ts';
import { MAX_FACTOR } from './max-factor.ts';
import { line } from './line.ts';
import { clampedTriangle, type Reverse } from './clamped.ts';
import { d3d11Triangle } from './d3d11.ts';
import { checkMaxFactor } from './hable-line.ts';
import { LINE_MODES, TRI_MODES, type LineMode, type TriMode, type D3D11Partitioning, type TriPattern } from './types.ts';

export interface CliResult {
  stdout: string;
  stderr: string;
  code: number;
}

export const USAGE = `usage:
  pattern line --mode MODE (--factor F | --sweep FROM,TO,STEP) [--json] [--fixed] [--max-factor M]
  pattern tri --mode MODE (--factors F0,F1,F2 | --factors-file FILE) [--reverse R0,R1,R2] [--inside F] [--json] [--fixed] [--max-factor M]
line modes: ${LINE_MODES.join(', ')}
triangle modes: ${TRI_MODES.join(', ')}
--reverse (clamped only): 1 where the triangle walks edge i from corner i+1 to corner i.
--inside (D3D11 modes only): the inside tess factor (default: the mean of the edge factors).
--factors-file: one set per line, "f0,f1,f2[,inside][;r0,r1,r2]"; blank lines and # comments skipped.`;

class UsageError extends Error {}

/** The most output one run builds: the result is one string (V8 caps strings at 512 MiB). */
export const MAX_OUTPUT_CHARS = 256 * 1024 * 1024;

function tooMuch(what: string, chars: number): UsageError {
  return new UsageError(
    `${what}: the output would be up to about ${Math.round(chars / 1024 / 1024)} MiB, more than the ${MAX_OUTPUT_CHARS / 1024 / 1024} MiB one run writes: ask for less`,
  );
}

interface Args {
  command: 'line' | 'tri';
  mode: string;
  flags: Map<string, string | true>;
}

const VALUED = new Set(['--mode', '--factor', '--sweep', '--factors', '--factors-file', '--reverse', '--inside', '--max-factor']);
const BOOLEAN = new Set(['--json', '--fixed']);

function parseArgs(argv: string[]): Args {
  const [command, ...rest] = argv;
  if (command !== 'line' && command !== 'tri')
    throw new UsageError(command ? `unknown command '${command}' (expected 'line' or 'tri')` : 'missing command');
  const flags = new Map<string, string | true>();
  for (let i = 0; i < rest.length; i++) {
    const a = rest[i];
    if (BOOLEAN.has(a)) flags.set(a, true);
    else if (VALUED.has(a)) {
      const v = rest[++i];
      if (v === undefined || v.startsWith('--')) throw new UsageError(`${a} needs a value`);
      flags.set(a, v);
    } else throw new UsageError(`unknown argument '${a}'`);
  }
  const mode = flags.get('--mode');
  if (typeof mode !== 'string') throw new UsageError('--mode is required');
  return { command, mode, flags };
}

function num(text: string, what: string): number {
  const t = text.trim();
  const v = Number(t);
  if (t === '' || !Number.isFinite(v)) throw new UsageError(`${what}: '${text}' is not a finite number`);
  return v;
}

function numbers(text: string, count: number, what: string): number[] {
  const parts = text.split(',');
  if (parts.length !== count) throw new UsageError(`${what}: expected ${count} comma-separated numbers, got '${text}'`);
  return parts.map((p) => num(p, what));
}

function flagsList(text: string, what: string): Reverse {
  const parts = text.split(',').map((s) => s.trim());
  if (parts.length !== 3 || parts.some((p) => p !== '0' && p !== '1'))
    throw new UsageError(`${what}: expected three 0/1 flags like 0,1,0, got '${text}'`);
  return parts.map((p) => p === '1') as unknown as Reverse;
}

function positiveFactor(v: number, what: string): number {
  if (!(v > 0)) throw new UsageError(`${what}: tess factors must be > 0, got ${v}`);
  return v;
}

function fmt(k: number, fixed: boolean): number {
  return fixed ? k : toUnit(k);
}

function lineJson(mode: LineMode, f: number, maxFactor: number, fixed: boolean, withFactor: boolean): object {
  const p = line(mode, f, { maxFactor });
  return {
    ...(withFactor ? { factor: f } : {}),
    points: p.x.map((k) => fmt(k, fixed)),
    moving: p.moving,
    triangles: [],
    vertexCount: p.x.length,
    triangleCount: 0,
  };
}

function triJson(p: TriPattern, fixed: boolean, extra: object): object {
  const points: number[][] = [];
  for (let v = 0; v < p.vertexCount; v++) points.push([0, 1, 2].map((c) => fmt(p.bary[3 * v + c], fixed)));
  const triangles: number[][] = [];
  for (let t = 0; t < p.triangleCount; t++) triangles.push([p.triangles[3 * t], p.triangles[3 * t + 1], p.triangles[3 * t + 2]]);
  return { ...extra, points, triangles, vertexCount: p.vertexCount, triangleCount: p.triangleCount };
}

function triangle(
  mode: TriMode,
  factors: [number, number, number],
  reverse: Reverse | undefined,
  inside: number | undefined,
  maxFactor: number,
): TriPattern {
  if (mode === 'clamped') {
    if (inside !== undefined) throw new UsageError('--inside applies to the D3D11 modes only: the clamped pattern has no inside factor');
    return clampedTriangle(factors, reverse, { maxFactor });
  }
  if (reverse !== undefined) throw new UsageError('--reverse applies to the clamped mode only: D3D11 edges are symmetric');
  return d3d11Triangle(mode as D3D11Partitioning, factors, inside ?? (factors[0] + factors[1] + factors[2]) / 3);
}

function humanLine(mode: string, f: number, o: { points: number[]; vertexCount: number }): string {
  return `line ${mode} factor ${f}: ${o.vertexCount} points\n${o.points.map((x) => x.toFixed(6)).join(' ')}\n`;
}

function humanTri(mode: string, label: string, o: { vertexCount: number; triangleCount: number }): string {
  return `tri ${mode} ${label}: ${o.vertexCount} vertices, ${o.triangleCount} triangles\n`;
}

export function runPatternCli(argv: string[], readFile: (path: string) => string): CliResult {
  if (argv.includes('--help') || argv.includes('-h')) return { stdout: USAGE + '\n', stderr: '', code: 0 };
  try {
    const { command, mode, flags } = parseArgs(argv);
    const json = flags.has('--json');
    const fixed = flags.has('--fixed');
    const maxFactor = flags.has('--max-factor') ? num(flags.get('--max-factor') as string, '--max-factor') : MAX_FACTOR;
    try {
      checkMaxFactor(maxFactor);
    } catch (e) {
      throw new UsageError(`--max-factor: ${(e as Error).message}`);
    }

    if (command === 'line') {
      if (!(LINE_MODES as readonly string[]).includes(mode))
        throw new UsageError(`unknown line mode '${mode}' (one of ${LINE_MODES.join(', ')})`);
      const m = mode as LineMode;
      const factor = flags.get('--factor');
      const sweep = flags.get('--sweep');
      if ((factor === undefined) === (sweep === undefined)) throw new UsageError('give exactly one of --factor F or --sweep FROM,TO,STEP');
      if (typeof factor === 'string') {
        const f = positiveFactor(num(factor, '--factor'), '--factor');
        const o = lineJson(m, f, maxFactor, fixed, false) as { points: number[]; vertexCount: number };
        return { stdout: json ? JSON.stringify(o) + '\n' : humanLine(m, f, o), stderr: '', code: 0 };
      }
      const [from, to, step] = numbers(sweep as string, 3, '--sweep');
      if (!(step > 0)) throw new UsageError(`--sweep: the step must be > 0, got ${step}`);
      if (!(to >= from)) throw new UsageError(`--sweep: TO must be ≥ FROM, got ${from},${to}`);
      positiveFactor(from, '--sweep');
      const n = Math.floor((to - from) / step + 1e-9);
      if (n > 1_000_000) throw new UsageError(`--sweep: ${n + 1} factors is too many (at most 1,000,001)`);
      // From the counts before the work: no line is longer than the largest factor's, plus its factor.
      const longest = JSON.stringify(lineJson(m, Math.min(to, maxFactor), maxFactor, fixed, true)).length + 24;
      if ((n + 1) * longest > MAX_OUTPUT_CHARS) throw tooMuch('--sweep', (n + 1) * longest);
      const out: string[] = [];
      for (let i = 0; i <= n; i++) {
        const f = Number((from + i * step).toPrecision(12));
        out.push(JSON.stringify(lineJson(m, f, maxFactor, fixed, true)));
      }
      return { stdout: out.join('\n') + '\n', stderr: '', code: 0 };
    }

    if (!(TRI_MODES as readonly string[]).includes(mode))
      throw new UsageError(`unknown triangle mode '${mode}' (one of ${TRI_MODES.join(', ')})`);
    const m = mode as TriMode;
    const single = flags.get('--factors');
    const file = flags.get('--factors-file');
    if ((single === undefined) === (file === undefined))
      throw new UsageError('give exactly one of --factors F0,F1,F2 or --factors-file FILE');
    if (typeof single === 'string') {
      const f = numbers(single, 3, '--factors').map((v) => positiveFactor(v, '--factors')) as [number, number, number];
      const reverse = typeof flags.get('--reverse') === 'string' ? flagsList(flags.get('--reverse') as string, '--reverse') : undefined;
      const inside = typeof flags.get('--inside') === 'string' ? num(flags.get('--inside') as string, '--inside') : undefined;
      const o = triJson(triangle(m, f, reverse, inside, maxFactor), fixed, {}) as { vertexCount: number; triangleCount: number };
      return { stdout: json ? JSON.stringify(o) + '\n' : humanTri(m, f.join(','), o), stderr: '', code: 0 };
    }
    if (flags.has('--reverse') || flags.has('--inside'))
      throw new UsageError('with --factors-file, give inside factors and reverse flags per line');
    let text: string;
    try {
      text = readFile(file as string);
    } catch (e) {
      throw new UsageError(`--factors-file: cannot read '${String(file)}': ${(e as Error).message}`);
    }
    const out: string[] = [];
    let chars = 0;
    text.split(/\r?\n/).forEach((raw, i) => {
      const lineText = raw.replace(/#.*/, '').trim();
      if (!lineText) return;
      const where = `${String(file)}:${i + 1}`;
      const [fPart, rPart] = lineText.split(';');
      const vals = fPart.split(',');
      if (vals.length !== 3 && vals.length !== 4) throw new UsageError(`${where}: expected f0,f1,f2[,inside][;r0,r1,r2], got '${raw}'`);
      const f = vals.slice(0, 3).map((v) => positiveFactor(num(v, where), where)) as [number, number, number];
      const inside = vals.length === 4 ? num(vals[3], where) : undefined;
      const reverse = rPart !== undefined ? flagsList(rPart, where) : undefined;
      let p: TriPattern;
      try {
        p = triangle(m, f, reverse, inside, maxFactor);
      } catch (e) {
        throw e instanceof UsageError ? new UsageError(`${where}: ${e.message}`) : e;
      }
      const extra = { factors: f, ...(inside !== undefined ? { inside } : {}), ...(reverse ? { reverse: reverse.map(Number) } : {}) };
      out.push(JSON.stringify(triJson(p, fixed, extra))); // always JSON: one object per line
      chars += out[out.length - 1].length + 1;
      if (chars > MAX_OUTPUT_CHARS) throw tooMuch(`--factors-file ${String(file)} (at line ${i + 1})`, chars);
    });
    return { stdout: out.length ? out.join('\n') + '\n' : '', stderr: '', code: 0 };
  } catch (e) {
    // Messages quote the user's files and arguments: their control characters are escaped.
    if (e instanceof UsageError) return { stdout: '', stderr: `pattern: ${escapeControl(e.message)}\n${USAGE}\n`, code: 2 };
    throw e;
  }
}
