// Every binding is declared once, in the contract (defineBindGroup), and its WGSL declaration is
// generated: no shader file and no TypeScript outside src/gpu/contract/ writes `@binding(` itself,
// in code or in a comment (a comment that shows one is how a hand copy starts).
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';

const ROOT = new URL('../../../', import.meta.url).pathname;

function files(dir: string, ext: string): string[] {
  return readdirSync(dir).flatMap((f) => {
    const p = join(dir, f);
    return statSync(p).isDirectory() ? files(p, ext) : p.endsWith(ext) ? [p] : [];
  });
}

describe('no hand-written bindings', () => {
  it('no .wgsl file declares a binding', () => {
    const found = files(join(ROOT, 'wgsl'), '.wgsl').filter((f) => readFileSync(f, 'utf8').includes('@binding('));
    expect(found.map((f) => relative(ROOT, f))).toEqual([]);
  });

  it('no TypeScript outside src/gpu/contract/ spells one', () => {
    const found = files(join(ROOT, 'src'), '.ts')
      .filter((f) => !relative(ROOT, f).startsWith('src/gpu/contract/'))
      .filter((f) => readFileSync(f, 'utf8').includes('@binding('));
    expect(found.map((f) => relative(ROOT, f))).toEqual([]);
  });

  it('the search finds one where there is one (so the zeros above mean something)', () => {
    const define = readFileSync(join(ROOT, 'src/gpu/contract/define.ts'), 'utf8');
    expect(define).toContain('@binding(');
  });
});
