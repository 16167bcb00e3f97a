/**
 * The surfaces behind one interface (src/gpu/surface/registry.ts): what each declares, and that
 * the rest of src/ asks a surface rather than comparing its name.
 */
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';
import {
  isAccSurface,
  isSurfaceId,
  SURFACE_IDS,
  SURFACE_SCHEMES,
  surfaceScheme,
  type SurfaceId,
} from '../../../src/gpu/surface/registry.ts';
import { tessellatorPasses } from '../../../src/gpu/tess/passes.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { SLICE_BUDGET_BYTES_PER_FACE, buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { buildTopology, computeSharpness, DEFAULT_OPTIONS, loadCage, SHARPNESS_INFINITE } from '../../../src/mesh/index.ts';

const ROOT = new URL('../../../', import.meta.url).pathname;

function sources(dir: string): string[] {
  return readdirSync(dir).flatMap((f) => {
    const p = join(dir, f);
    return statSync(p).isDirectory() ? sources(p) : p.endsWith('.ts') ? [p] : [];
  });
}

/** A comparison of a value with a surface's name, or a `case` on one. (The demo's isAcc and isExact,
 * src/app/surfaces.ts, ask the registry.) */
const NAME_BRANCH =
  /(===|!==)\s*'(catmull-clark|phong|bezier-acc|gregory-acc|pm-acc)'|'(catmull-clark|phong|bezier-acc|gregory-acc|pm-acc)'\s*(===|!==)|case '(catmull-clark|phong|bezier-acc|gregory-acc|pm-acc)'/g;

/** Files that still compare a surface's name, and how many times: none. Each count may only fall;
 * a file not listed may not start (src/, scripts/ and bench/ are read). The CPU yardsticks in src/subdiv are the schemes themselves (the
 * ACC module choosing among its own three variants), not a consumer of them, and are left out. */
const NOT_YET: Record<string, number> = {};

describe('the surface registry', () => {
  it('declares every surface once, with a name and an evaluator of evalSurface', () => {
    expect(new Set(SURFACE_IDS).size).toBe(SURFACE_SCHEMES.length);
    expect(SURFACE_IDS).toEqual(['catmull-clark', 'phong', 'bezier-acc', 'gregory-acc', 'pm-acc']);
    for (const s of SURFACE_SCHEMES) {
      expect(surfaceScheme(s.id)).toBe(s);
      expect(s.name.length, s.id).toBeGreaterThan(0);
      expect(s.tessWgsl, s.id).toMatch(/fn evalSurface\s*\(/);
    }
    expect(new Set(SURFACE_SCHEMES.map((s) => s.name)).size).toBe(SURFACE_SCHEMES.length);
  });

  it('has one exact limit, the one surface that reads the work arena; normals split at its creases and at those the ACC schemes build sharp', () => {
    const exact = SURFACE_SCHEMES.filter((s) => s.exactLimit);
    expect(exact.map((s) => s.id)).toEqual(['catmull-clark']);
    for (const s of SURFACE_SCHEMES) {
      expect(s.readsWork, s.id).toBe(s.patchBuild === 'refinement');
      expect(s.splitsCreases, s.id).toBe(s.exactLimit ? 'infinitely-sharp' : isAccSurface(s.id) ? 'sharpness-1' : false);
    }
    expect(SURFACE_IDS.filter(isAccSurface)).toEqual(['bezier-acc', 'gregory-acc', 'pm-acc']);
  });

  it("the tessellator's passes follow the surface's patch build, and its evaluator is in every evaluating pass", () => {
    for (const s of SURFACE_SCHEMES) {
      const passes = tessellatorPasses(s.id);
      const build = passes.filter((p) => p.group === 'ccBuild').map((p) => p.name);
      expect(build.length > 0, s.id).toBe(s.patchBuild === 'refinement');
      for (const p of passes.filter((q) => ['bulge', 'count', 'emitVertices'].includes(q.name)))
        expect(p.code.includes(s.tessWgsl), `${s.id} ${p.name}`).toBe(true);
    }
  });

  it('tells what it needs prepared, without a GPU for the surfaces that need none', () => {
    const phong = surfaceScheme('phong');
    expect(phong.hasData({})).toBe(true);
    expect(surfaceScheme('catmull-clark').hasData({})).toBe(false);
    expect(surfaceScheme('gregory-acc').hasData({})).toBe(false);
  });

  it('refuses an unknown name with the list of known ones', () => {
    expect(isSurfaceId('loop')).toBe(false);
    expect(isSurfaceId('pm-acc')).toBe(true);
    expect(() => surfaceScheme('loop' as SurfaceId)).toThrow(/unknown surface 'loop' \(one of catmull-clark, phong/);
  });
});

describe("the exact surface's specialisation says what each cage has", () => {
  // Each value is 1 exactly when the cage has what its code is for (wgsl/cc/surface.wgsl), found
  // here from the cage rather than from the build's tables: a face that is not a quad; a boundary
  // or an infinitely sharp edge (phantom points); a single-crease patch or a fan with a semi-sharp
  // axis, both of which take the crease basis (the build's own count and flag: which creases
  // qualify, and at which level a fan starts, are the build's decisions, tests/gpu/cc/
  // single-crease*.test.ts and semi-sharp-fans.node.test.ts); fans
  // keeping their odd steps only (the build's memory bound: every step's data above it).
  const dir = join(ROOT, 'public/models');
  for (const file of readdirSync(dir).filter((f) => f.endsWith('.obj'))) {
    it(file, () => {
      const cage = loadCage(readFileSync(join(dir, file), 'utf8')).cage;
      const mesh = prepareMesh(cage);
      const cc = buildCatmullClark(cage, mesh);
      const everyStep = buildCatmullClark(cage, mesh, { slices: 'every' });
      const overBudget = everyStep.gpuBytes > SLICE_BUDGET_BYTES_PER_FACE * (cage.faceOffsets.length - 1) && everyStep.fanCount > 0;
      const topo = buildTopology(cage);
      const sharp = computeSharpness(cage, topo, { ...DEFAULT_OPTIONS, ...cage.fileOptions });
      const ngons = cage.faceOffsets.some((o, f) => f > 0 && o - cage.faceOffsets[f - 1] !== 4);
      const phantoms = topo.vertBoundary.some((b) => b === 1) || sharp.edge.some((s) => s >= SHARPNESS_INFINITE);
      expect(surfaceScheme('catmull-clark').specialise({ cc })).toEqual({
        CC_NGONS: +ngons,
        CC_CREASE_PATCHES: +(cc.singleCreaseCount > 0 || cc.semiAxes),
        CC_PHANTOMS: +phantoms,
        CC_ODD_SLICES: +overBudget,
      });
      expect(cc.gpuBytes).toBe(overBudget ? buildCatmullClark(cage, mesh, { slices: 'odd' }).gpuBytes : everyStep.gpuBytes);
    });
  }
  it('the other surfaces have none', () => {
    for (const s of SURFACE_SCHEMES) if (!s.exactLimit) expect(s.specialise({})).toEqual({});
  });
});

describe('no module outside the registry branches on a surface name', () => {
  const found: Record<string, number> = {};
  for (const f of ['src', 'scripts', 'bench'].flatMap((d) => sources(join(ROOT, d)))) {
    const rel = relative(ROOT, f);
    if (rel === 'src/gpu/surface/registry.ts' || rel.startsWith('src/subdiv/')) continue;
    // Comments may name surfaces; only code counts.
    const code = readFileSync(f, 'utf8')
      .replace(/\/\*[\s\S]*?\*\//g, '')
      .replace(/\/\/[^\n]*/g, '');
    const n = code.match(NAME_BRANCH)?.length ?? 0;
    if (n) found[rel] = n;
  }

  it('no new file branches on a name', () => {
    expect(Object.keys(found).filter((f) => !(f in NOT_YET))).toEqual([]);
  });

  it('the files not yet converted branch no more than they did', () => {
    for (const [f, n] of Object.entries(found)) if (f in NOT_YET) expect(n, f).toBeLessThanOrEqual(NOT_YET[f]);
  });

  it('the pattern finds a branch (so a zero above means something)', () => {
    expect("if (s === 'phong') x(); switch (s) { case 'pm-acc': } if ('gregory-acc' !== t) y();".match(NAME_BRANCH)?.length).toBe(3);
  });
});
