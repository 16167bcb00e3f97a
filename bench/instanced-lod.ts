/**
 * `node scripts/vite-run.mjs bench/instanced-lod.ts [-- --lod S] [--surface phong|catmull-clark] [--models a,b]`:
 * triangle counts of the two tessellators' adaptive modes at one camera and LOD scale (issue 11's
 * "LOD measure mismatch"), per project model: the compute tessellator's adaptive factors, the
 * instanced tessellator's dynamic rule (the sample's: chord pixels and curvature, 1920×1080) and
 * its factor-rule mode (the compute tessellator's measure, rounded up to powers of two). The
 * camera is the CLI's (src/gpu/tess/headless.ts headlessCamera, 1080 px high). Counts only, no timings
 * (instanced: the triangles a draw rasterises, and the welded mesh the CLI writes).
 */
import { readdirSync, readFileSync } from 'node:fs';
import { createNodeDevice } from '../src/gpu/device/node-device.ts';
import { Tessellator } from '../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../src/gpu/tess/prepare.ts';
import { headlessCamera, tessellateOnce } from '../src/gpu/tess/headless.ts';
import { bakeTables } from '../src/pattern/tables.ts';
import { loadCage } from '../src/mesh/index.ts';
import { buildCatmullClark } from '../src/gpu/cc/build.ts';
import { InstancedTessellator } from '../src/gpu/instanced/instanced.ts';
import { factorRuleLevels, type LevelParams } from '../src/gpu/instanced/instanced-options.ts';
import { prepareInstanced } from '../src/gpu/instanced/prepare-patches.ts';
import { weldInstanced } from '../src/gpu/instanced/headless-output.ts';
import { ccSurfaceTessellator } from '../src/gpu/instanced/surface-cc.ts';
import { isSurfaceId, SURFACE_IDS, surfaceScheme } from '../src/gpu/surface/registry.ts';

function option(argv: string[], name: string): string | undefined {
  const i = argv.indexOf(name);
  return i >= 0 ? argv[i + 1] : undefined;
}

export async function main(argv: string[]): Promise<number> {
  const lod = Number(option(argv, '--lod') ?? 1);
  const surface = option(argv, '--surface') ?? 'phong';
  // The surfaces the instanced tessellator evaluates from a cage alone or from a lending compute
  // tessellator (an ACC surface needs its patches built: not benchmarked here).
  const benched = SURFACE_IDS.filter((id) => surfaceScheme(id).instancedKind !== 'acc');
  if (!isSurfaceId(surface) || !benched.includes(surface)) {
    console.error(`instanced-lod: --surface ${benched.join(' or ')}, got ${surface}`);
    return 2;
  }
  const only = option(argv, '--models')?.split(',');
  const { device } = await createNodeDevice([]);
  const compute = Tessellator.create(device, bakeTables(64), { surface, flatBaseline: false });
  const instanced = new InstancedTessellator(device, { surface: surfaceScheme(surface).instancedKind });
  console.log(`surface ${surface}, LOD scale ${lod}, the CLI's camera (1080 px high)`);
  console.log(
    '| model | compute adaptive tris | instanced dynamic (sample rule): drawn / welded | ratio | instanced factor rule: drawn / welded | ratio |',
  );
  console.log('|---|---:|---:|---:|---:|---:|');
  const models = readdirSync('public/models')
    .filter((f) => f.endsWith('.obj'))
    .map((f) => f.replace('.obj', ''))
    .sort()
    .filter((m) => !only || only.includes(m));
  for (const name of models) {
    const cage = loadCage(readFileSync(`public/models/${name}.obj`, 'utf8')).cage;
    const mesh = prepareMesh(cage);
    let cc: ReturnType<typeof buildCatmullClark> | undefined;
    try {
      cc = surfaceScheme(surface).patchBuild === 'refinement' ? buildCatmullClark(cage, mesh) : undefined;
    } catch (e) {
      console.log(`| ${name} | refused: ${(e as Error).message} |`);
      continue;
    }
    const o = { mode: 'adaptive' as const, lodScale: lod, surface };
    const c = await tessellateOnce(device, cage, o, compute, { mesh, cc });
    const cam = headlessCamera(mesh, o);
    const im = prepareInstanced(cage, mesh);
    const source = cc ? ccSurfaceTessellator(device, mesh, cc) : undefined;
    instanced.setMesh(im, source);
    const count = async (lp: LevelParams) => {
      const out = await instanced.headless(lp);
      return { drawn: out.triangleCount, welded: weldInstanced(im, out).triangleCount };
    };
    const before = await count({ mode: 'dynamic', viewProj: cam.viewProj, viewport: [1920, 1080], lodScale: lod, level: 1 });
    const after = await count(factorRuleLevels(cam));
    source?.destroy();
    const ct = c.out.triangleCount;
    console.log(
      `| ${name} | ${ct} | ${before.drawn} / ${before.welded} | ${(before.welded / ct).toFixed(2)} | ${after.drawn} / ${after.welded} | ${(after.welded / ct).toFixed(2)} |`,
    );
  }
  compute.destroy();
  instanced.destroy();
  device.destroy();
  return 0;
}
