/**
 * The CLIs' CPU stages, run in-process inside their error boundaries for the hostile-input tests
 * (tests/cli/): no GPU, no process. Each run gives the exit code and what it wrote, and
 * `assertHandled` holds the contract every run must keep: done (0) or refused as bad input (2)
 * with a message, never an internal error, a stack trace or a raw control character.
 */
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { expect } from 'vitest';
import { loadInput } from '../../scripts/tessellate-input.ts';
import { main as subdivMain } from '../../scripts/subdiv-cli.ts';
import { guarded, guardedSync } from '../../src/cli/boundary.ts';
import { buildCatmullClark } from '../../src/gpu/cc/build.ts';
import { prepareInstanced } from '../../src/gpu/instanced/prepare-patches.ts';
import { isAccSurface, surfaceScheme } from '../../src/gpu/surface/registry.ts';
import { prepareMesh } from '../../src/gpu/tess/prepare.ts';
import { AccSurface } from '../../src/subdiv/acc-evaluate.ts';
import type { AccScheme } from '../../src/subdiv/acc.ts';
import { runPatternCli } from '../../src/pattern/cli.ts';
import { readInputText } from '../../src/cli/files.ts';

export interface Run {
  code: number;
  out: string;
  err: string;
  ms: number;
}

export function tempDir(): string {
  return mkdtempSync(join(tmpdir(), 'tessellab-hostile-'));
}

/** Write `content` to `dir/name` and give its path. */
export function put(dir: string, name: string, content: string | Uint8Array): string {
  const path = join(dir, name);
  writeFileSync(path, content);
  return path;
}

/**
 * `npm run tessellate` up to the GPU: the arguments, the files, the loader, then the CPU
 * preparation the run would make (the prepared mesh, the Catmull-Clark tables, the ACC patches'
 * control points, the instanced patches), in the CLI's boundary.
 */
export async function tessellateCpu(...argv: string[]): Promise<Run> {
  let err = '';
  const t0 = performance.now();
  const code = await guarded(
    'tessellate',
    argv,
    (a) => {
      const { args, cage, warnings } = loadInput(a);
      for (const w of warnings) err += `tessellate: ${w}\n`;
      const mesh = prepareMesh(cage);
      const surface = args.acc ?? args.o.surface ?? 'catmull-clark';
      if (surfaceScheme(surface).patchBuild === 'refinement' || args.instancedCC) buildCatmullClark(cage, mesh);
      if (isAccSurface(surface)) new AccSurface(cage, surface as AccScheme);
      if (args.instanced) prepareInstanced(cage, mesh);
      return 0;
    },
    (line) => {
      err += `${line}\n`;
    },
  );
  return { code, out: '', err, ms: performance.now() - t0 };
}

export function subdiv(...argv: string[]): Run {
  let out = '';
  let err = '';
  const t0 = performance.now();
  const code = subdivMain(argv, {
    out: (t) => {
      out += t;
    },
    err: (t) => {
      err += t;
    },
  });
  return { code, out, err, ms: performance.now() - t0 };
}

/** `npm run pattern` as scripts/pattern-cli.ts runs it. */
export function pattern(...argv: string[]): Run {
  let out = '';
  let err = '';
  const t0 = performance.now();
  const code = guardedSync(
    'pattern',
    argv,
    (a) => {
      const r = runPatternCli(a, (path) => readInputText(path, 'file'));
      out += r.stdout;
      err += r.stderr;
      return r.code;
    },
    (line) => {
      err += `${line}\n`;
    },
  );
  return { code, out, err, ms: performance.now() - t0 };
}

// biome-ignore lint/suspicious/noControlCharactersInRegex: finding raw control characters is the check
const RAW_CONTROL = /[\u0000-\u0008\u000b-\u001f\u007f-\u009f]/;

/** Done or refused as bad input, in words: no internal error, no trace, no raw control byte. */
export function assertHandled(r: Run, what: string): void {
  expect([0, 2], `${what}: exit ${r.code}\n${r.err}`).toContain(r.code);
  expect(r.err, what).not.toMatch(/internal error|^\s+at /m);
  expect(RAW_CONTROL.test(r.err), `${what}: raw control character in ${JSON.stringify(r.err)}`).toBe(false);
  if (r.code === 2) expect(r.err.trim(), what).not.toBe('');
}

/** An n-gon (a disc), and a fan of n triangles round vertex 1 (valence n, on a boundary). */
export function ngon(n: number): string {
  const v = Array.from({ length: n }, (_, i) => `v ${Math.cos((2 * Math.PI * i) / n)} ${Math.sin((2 * Math.PI * i) / n)} 0`);
  return `${v.join('\n')}\nf ${Array.from({ length: n }, (_, i) => i + 1).join(' ')}\n`;
}
export function fan(n: number): string {
  const v = [
    'v 0 0 0',
    ...Array.from({ length: n }, (_, i) => `v ${Math.cos((2 * Math.PI * i) / n)} ${Math.sin((2 * Math.PI * i) / n)} 0`),
  ];
  const f = Array.from({ length: n }, (_, i) => `f 1 ${i + 2} ${((i + 1) % n) + 2}`);
  return `${v.join('\n')}\n${f.join('\n')}\n`;
}
