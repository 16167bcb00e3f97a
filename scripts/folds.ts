/**
 * Folded output triangles: the measure, the views a user is likely to see a model from, and a
 * census over models × surfaces × views (`npm run folds`), which tests/gpu/tess/folds.node.test.ts
 * holds a part of in CI and the whole of which is too slow for it (about ten minutes on two cores).
 *
 * A triangle is FOLDED when its geometric normal points against the sum of its three vertex
 * normals (the output's shading normals): drawn, it faces the other way from what it shades, and
 * with back faces culled it is a gap. (The older fold tests count a triangle that opposes all three
 * corners' normals, a stricter condition that misses the ones opposing two of them; both are
 * counted here.)
 *
 * The views: the fold tests' 24 seeded cameras round the model (tests/support/cpu-pipeline.ts
 * foldCameras: 0.6 to 2 times its size, LOD 0.5, 1 and 2 in turn), then the CLI's default camera
 * (src/gpu/tess/headless.ts headlessCamera) and the demo's first view (limit-distance.ts demoView)
 * at LOD 0.5, 1 and 2 each: 30 views, adaptive.
 *
 * `npm run folds -- [--surfaces a,b] [--models name,…] [--shared DIR]`: the project's models and,
 * when DIR (default ../shared/cages) holds them, the talk's four; every surface but Phong by
 * default, Catmull-Clark with and without the flat baseline. One line per model and surface:
 * folded (against the sum), folded (against all three), triangles, and the views that fold.
 */
import type { MeshReadback } from '../src/gpu/device/readback.ts';
import { type HeadlessOptions, tessellateOnce } from '../src/gpu/tess/headless.ts';
import type { PreparedMesh } from '../src/gpu/tess/prepare.ts';
import type { Tessellator } from '../src/gpu/tess/tessellator.ts';
import type { SurfaceData, SurfaceId } from '../src/gpu/surface/registry.ts';
import type { Cage } from '../src/mesh/types.ts';
import { foldCameras } from '../tests/support/cpu-pipeline.ts';
import { demoView } from './limit-distance.ts';

/** Triangles whose geometric normal opposes the sum of their vertex normals, and those that
 * oppose each of the three. */
export function foldedTriangles(o: MeshReadback): { againstSum: number; againstAll: number } {
  const P = o.positions,
    N = o.normals;
  let againstSum = 0;
  let againstAll = 0;
  for (let t = 0; t < o.triangleCount; t++) {
    const a = o.indices[3 * t],
      b = o.indices[3 * t + 1],
      c = o.indices[3 * t + 2];
    const e1x = P[3 * b] - P[3 * a],
      e1y = P[3 * b + 1] - P[3 * a + 1],
      e1z = P[3 * b + 2] - P[3 * a + 2];
    const e2x = P[3 * c] - P[3 * a],
      e2y = P[3 * c + 1] - P[3 * a + 1],
      e2z = P[3 * c + 2] - P[3 * a + 2];
    const gx = e1y * e2z - e1z * e2y,
      gy = e1z * e2x - e1x * e2z,
      gz = e1x * e2y - e1y * e2x;
    const d = (v: number) => N[3 * v] * gx + N[3 * v + 1] * gy + N[3 * v + 2] * gz;
    const da = d(a),
      db = d(b),
      dc = d(c);
    if (da + db + dc < 0) againstSum++;
    if (da < 0 && db < 0 && dc < 0) againstAll++;
  }
  return { againstSum, againstAll };
}

export interface FoldView {
  name: string;
  options: Pick<HeadlessOptions, 'eye' | 'target' | 'lodScale' | 'fovY' | 'viewportHeight'>;
}

/** The 30 views of a model (see the header). */
export function foldViews(mesh: PreparedMesh): FoldView[] {
  const views: FoldView[] = foldCameras(mesh).map((c, i) => ({
    name: `seeded ${i}`,
    options: { eye: [...c.eye], target: [...c.target], lodScale: c.lodScale, fovY: Math.PI / 4, viewportHeight: 1080 },
  }));
  const demo = demoView(mesh);
  for (const lodScale of [0.5, 1, 2]) {
    views.push({ name: `CLI default, LOD ${lodScale}`, options: { lodScale } });
    views.push({
      name: `demo's first view, LOD ${lodScale}`,
      options: { lodScale, eye: demo.eye, target: demo.target, fovY: demo.fovY, viewportHeight: demo.viewportHeight },
    });
  }
  return views;
}

/** One model on one surface over the given views (adaptive): the folded triangles summed, and
 * the views that fold (the census below and tests/gpu/tess/folds.node.test.ts). */
export async function foldsOverViews(
  device: GPUDevice,
  tess: Tessellator,
  cage: Cage,
  prepared: { mesh: PreparedMesh } & SurfaceData,
  surface: SurfaceId,
  flatBaseline: boolean,
  views: FoldView[],
): Promise<{ againstSum: number; againstAll: number; triangles: number; where: string[] }> {
  const total = { againstSum: 0, againstAll: 0, triangles: 0, where: [] as string[] };
  for (const v of views) {
    const r = await tessellateOnce(device, cage, { mode: 'adaptive', surface, flatBaseline, ...v.options }, tess, prepared);
    const f = foldedTriangles(r.out);
    total.againstSum += f.againstSum;
    total.againstAll += f.againstAll;
    total.triangles += r.out.triangleCount;
    if (f.againstSum) total.where.push(`${v.name}: ${f.againstSum}`);
  }
  return total;
}

/** `npm run folds` (through scripts/vite-run.mjs, which calls this). */
export async function main(argv: string[]): Promise<number> {
  const { readFileSync, readdirSync, existsSync } = await import('node:fs');
  const { getDevice } = await import('../tests/support/gpu-device.ts');
  const { Tessellator } = await import('../src/gpu/tess/tessellator.ts');
  const { bakeTables } = await import('../src/pattern/tables.ts');
  const { prepareMesh } = await import('../src/gpu/tess/prepare.ts');
  const { loadCage } = await import('../src/mesh/index.ts');
  const { surfaceScheme, releaseSurfaceData, isSurfaceId } = await import('../src/gpu/surface/registry.ts');

  const arg = (name: string) => {
    const i = argv.indexOf(`--${name}`);
    return i >= 0 ? argv[i + 1] : undefined;
  };
  const surfaces = (arg('surfaces') ?? 'catmull-clark,bezier-acc,gregory-acc,pm-acc').split(',');
  for (const s of surfaces) if (!isSurfaceId(s)) throw new Error(`unknown surface ${s}`);
  const only = arg('models')?.split(',');
  const shared = arg('shared') ?? new URL('../../shared/cages/', import.meta.url).pathname;
  const models: [string, string][] = readdirSync(new URL('../public/models/', import.meta.url))
    .filter((f) => f.endsWith('.obj'))
    .sort()
    .map((f) => [f.replace('.obj', ''), new URL(`../public/models/${f}`, import.meta.url).pathname]);
  for (const m of ['suzanne', 'bigguy', 'monsterfrog', 'imrod'])
    if (existsSync(`${shared}/${m}.obj`)) models.push([m, `${shared}/${m}.obj`]);

  const device = await getDevice();
  console.log('| surface | model | folded (against the sum) | (against all three) | triangles | views that fold |');
  console.log('|---|---|---:|---:|---:|---|');
  for (const surface of surfaces as SurfaceId[]) {
    const tess = Tessellator.create(device, bakeTables(64), { surface, vertexCapacity: 1 << 22, triangleCapacity: 1 << 22 });
    for (const [name, path] of models) {
      if (only && !only.includes(name)) continue;
      // The cage the surface tessellates (an ACC scheme refines a cage with n-gons once).
      const cage = surfaceScheme(surface).surfaceCage(loadCage(readFileSync(path, 'utf8')).cage).cage;
      const mesh = prepareMesh(cage);
      let data: ReturnType<ReturnType<typeof surfaceScheme>['prepare']>;
      try {
        data = surfaceScheme(surface).prepare(device, cage, mesh);
      } catch (e) {
        console.log(`| ${surface} | ${name} | refused: ${String((e as Error).message).slice(0, 80)} | | | |`);
        continue;
      }
      const baselines = surfaceScheme(surface).flatBaseline ? [true, false] : [false];
      for (const flatBaseline of baselines) {
        tess.flatBaseline = flatBaseline;
        const f = await foldsOverViews(device, tess, cage, { mesh, ...data }, surface, flatBaseline, foldViews(mesh));
        const label = baselines.length > 1 ? `${surface}${flatBaseline ? ' (flat baseline)' : ''}` : surface;
        console.log(`| ${label} | ${name} | ${f.againstSum} | ${f.againstAll} | ${f.triangles} | ${f.where.join('; ')} |`);
      }
      releaseSurfaceData(data);
    }
    tess.destroy();
  }
  return 0;
}
