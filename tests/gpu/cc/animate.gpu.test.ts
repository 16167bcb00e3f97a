/**
 * Catmull-Clark under change: an animated cage (new positions, only the patch build re-run, the
 * CPU-built tables kept) still matches the exact CPU reference of the moved cage; and the pop
 * test: sweeping the LOD scale in small steps with the flat-baseline blend on, no output vertex
 * lands farther than a stated bound from the previous step's mesh at the same point (which bounds
 * motion as much as popping), and the jump test: the same LOD scales against themselves times
 * 1 + 1e-3 and 1 + 1e-4, where a continuous surface moves ten times less and a pop does not.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { mat4 } from 'gl-matrix';
import { getDevice, releaseDevice } from '../../support/gpu-device.ts';
import { checkTessellation } from '../../support/tess-checks.ts';
import { CCReference, randomSamples } from '../../support/cc-checks.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh, type PreparedMesh } from '../../../src/gpu/tess/prepare.ts';
import { readBuffer, readMesh, type MeshReadback } from '../../../src/gpu/device/readback.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { sampleSurface } from '../../../src/gpu/tess/sample-surface.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import type { FactorParams } from '../../../src/gpu/contract/tessellated-mesh.ts';
import { decodeBary } from '../../../src/gpu/contract/tess.ts';
import { loadCage, type Cage } from '../../../src/mesh/index.ts';
import creasedBox from '../../../public/models/creased-box.obj?raw';
import creature from '../../../public/models/creature.obj?raw';
import torus from '../../../public/models/torus.obj?raw';

const tables = bakeTables(64);
const made: Tessellator[] = [];
afterAll(() => {
  made.forEach((t) => t.destroy());
  return releaseDevice();
});

/** Largest movement of any output vertex between consecutive LOD steps of ×1.06 (factors ×1.03), of the
 * bbox diagonal; measured: torus 1.05e-3 (1.11e-3 without the flat baseline), creased-box 3.91e-3 (9.5e-3). */
const POP_BOUND = 4e-3;

function camera(mesh: PreparedMesh, eyeDistance: number, lodScale: number): FactorParams {
  const c = [0, 1, 2].map((i) => (mesh.bboxMin[i] + mesh.bboxMax[i]) / 2) as [number, number, number];
  const eye: [number, number, number] = [c[0] + 0.3 * eyeDistance, c[1] + 0.5 * eyeDistance, c[2] + eyeDistance];
  const view = mat4.lookAt(mat4.create(), eye, c, [0, 1, 0]);
  const proj = mat4.perspectiveZO(mat4.create(), Math.PI / 4, 1, 0.01, 100);
  const viewProj = mat4.multiply(mat4.create(), proj, view) as Float32Array;
  return { mode: 'adaptive', fixedFactor: 1, lodScale, viewProj, eye, viewportHeight: 720, fovY: Math.PI / 4 };
}

async function make(flatBaseline: boolean): Promise<Tessellator> {
  const t = Tessellator.create(await getDevice(), tables, {
    vertexCapacity: 1 << 19,
    triangleCapacity: 1 << 19,
    surface: 'catmull-clark',
    flatBaseline,
  });
  made.push(t);
  return t;
}

async function run(t: Tessellator, p: FactorParams) {
  const enc = t.device.createCommandEncoder();
  t.encode(enc, p);
  t.device.queue.submit([enc.finish()]);
  return readMesh(t.device, t.output);
}

describe('Catmull-Clark with an animated cage', () => {
  it('creature: moved cage, patch build re-run only, still the exact limit of the moved cage', async () => {
    const t = await make(false);
    const cage = loadCage(creature).cage;
    const mesh = prepareMesh(cage);
    const cc = buildCatmullClark(cage, mesh);
    t.setMesh(mesh, cc);
    await run(t, camera(mesh, 1.5 * mesh.size, 2));
    for (const phase of [0.3, 1.1]) {
      // A smooth deformation: bend and swell (same topology, tables untouched).
      const moved: Cage = {
        ...cage,
        positions: cage.positions.map((x, i) => {
          const v = Math.floor(i / 3),
            c = i % 3;
          const p = cage.positions.subarray(3 * v, 3 * v + 3);
          return c === 1 ? x + 0.2 * Math.sin(phase + 1.7 * p[0]) : c === 2 ? x * (1 + 0.1 * Math.cos(phase + p[1])) : x;
        }),
      };
      const movedMesh = prepareMesh(moved);
      t.updateCage(movedMesh.positions, movedMesh.normals);
      const enc = t.device.createCommandEncoder();
      t.encodePatchBuild(enc);
      t.device.queue.submit([enc.finish()]);
      const samples = randomSamples(mesh, 1500, 7);
      const gpu = await sampleSurface(t, samples);
      const r = new CCReference(moved, movedMesh, cc).compare(samples, gpu.pos, gpu.normal);
      console.log('animated', phase, JSON.stringify(r));
      expect(r.nan).toBe(0);
      expect(r.exact.maxP, r.exact.worst).toBeLessThan(1e-5);
      expect(r.exact.maxN).toBeLessThan(0.1);
      expect(r.blended.maxP).toBeLessThan(1e-4);
      // And the full rebuild on the moved cage stays watertight.
      const out = await run(t, camera(movedMesh, 1.5 * movedMesh.size, 2));
      const edgeF = new Uint32Array(await readBuffer(t.device, t.workBuffer, 4 * mesh.edgeCount, 4 * t.workLayout.edgeF));
      const ref = new CCReference(moved, movedMesh, cc);
      const report = checkTessellation(movedMesh, edgeF, out, {
        closed: true,
        split: true,
        reference: (tri, w) => {
          const x = ref.at(tri, w).ref;
          return { pos: x.P, normal: x.N };
        },
      });
      expect(report.problems).toEqual([]);
    }
  });
});

/** Cage-vertex weights (fixed point) of output vertex v, in source triangle t's corner order. */
function weightsIn(mesh: PreparedMesh, out: MeshReadback, v: number, t: number): number[] | null {
  const s = out.srcTri[v];
  const b = out.bary[v];
  const w = decodeBary(b);
  const res = [0, 0, 0];
  for (let i = 0; i < 3; i++) {
    if (!w[i]) continue;
    const cv = mesh.triVerts[3 * s + i];
    let j = 0;
    while (j < 3 && mesh.triVerts[3 * t + j] !== cv) j++;
    if (j === 3) return null;
    res[j] = w[i] / 65536;
  }
  return res;
}

/** Largest distance from a vertex of `next` to the mesh `prev` at the same surface parameter. */
function maxPop(mesh: PreparedMesh, prev: MeshReadback, next: MeshReadback): number {
  // Bucket prev's triangles by source triangle (the one all three corners lie in).
  const buckets = new Map<number, { w: number[][]; p: number[][] }[]>();
  const candidates = (v: number): number[] => {
    const s = prev.srcTri[v];
    return [s];
  };
  for (let k = 0; k < prev.triangleCount; k++) {
    const vs = [0, 1, 2].map((c) => prev.indices[3 * k + c]);
    // The source triangle: the srcTri of an interior vertex, else one whose corners hold all three.
    const tries = new Set<number>(vs.flatMap(candidates));
    for (let t2 = 0; t2 < mesh.triangleCount && tries.size < 8; t2++) {
      // Cheap extra candidates: triangles sharing a cage vertex with the first vertex's source.
      const s0 = prev.srcTri[vs[0]];
      if ([0, 1, 2].some((i) => [0, 1, 2].some((j) => mesh.triVerts[3 * t2 + i] === mesh.triVerts[3 * s0 + j]))) tries.add(t2);
    }
    for (const t of tries) {
      const ws = vs.map((v) => weightsIn(mesh, prev, v, t));
      if (ws.some((w) => !w)) continue;
      let list = buckets.get(t);
      if (!list) buckets.set(t, (list = []));
      list.push({ w: ws as number[][], p: vs.map((v) => [prev.positions[3 * v], prev.positions[3 * v + 1], prev.positions[3 * v + 2]]) });
      break;
    }
  }
  let worst = 0;
  for (let v = 0; v < next.vertexCount; v++) {
    const t = next.srcTri[v];
    const w = weightsIn(mesh, next, v, t)!;
    let best = Infinity;
    for (const tri of buckets.get(t) ?? []) {
      // Barycentric of w in the triangle tri.w (2D: use weights 1 and 2 as coordinates).
      const [a, b, c] = tri.w;
      const d = (b[1] - a[1]) * (c[2] - a[2]) - (c[1] - a[1]) * (b[2] - a[2]);
      if (d === 0) continue;
      const l1 = ((w[1] - a[1]) * (c[2] - a[2]) - (c[1] - a[1]) * (w[2] - a[2])) / d;
      const l2 = ((b[1] - a[1]) * (w[2] - a[2]) - (w[1] - a[1]) * (b[2] - a[2])) / d;
      const l0 = 1 - l1 - l2;
      if (l0 < -1e-9 || l1 < -1e-9 || l2 < -1e-9) continue;
      const q = [0, 1, 2].map((k) => l0 * tri.p[0][k] + l1 * tri.p[1][k] + l2 * tri.p[2][k]);
      best = Math.hypot(q[0] - next.positions[3 * v], q[1] - next.positions[3 * v + 1], q[2] - next.positions[3 * v + 2]);
      break;
    }
    if (best < Infinity) worst = Math.max(worst, best);
  }
  return worst / mesh.size;
}

describe('Catmull-Clark pop test (flat baseline by tess factor)', () => {
  for (const [name, text] of [
    ['torus', torus],
    ['creased-box', creasedBox],
  ] as const) {
    it(`${name}: sweeping the LOD scale moves no vertex by more than ${POP_BOUND} of the model size`, async () => {
      const cage = loadCage(text).cage;
      const mesh = prepareMesh(cage);
      const cc = buildCatmullClark(cage, mesh);
      const results: Record<string, number> = {};
      for (const flat of [true, false]) {
        const t = await make(flat);
        t.setMesh(mesh, cc);
        let prev: MeshReadback | undefined;
        let worst = 0;
        for (let i = 0; i <= 40; i++) {
          const out = await run(t, camera(mesh, 3 * mesh.size, 0.05 * 1.06 ** i));
          if (prev) worst = Math.max(worst, maxPop(mesh, prev, out));
          prev = out;
        }
        results[flat ? 'flat' : 'plain'] = worst;
      }
      console.log('pop', name, JSON.stringify(results));
      expect(results.flat).toBeLessThan(POP_BOUND);
      // Since the blend keeps every point within 1/lodScale pixels of the limit (issue 13), it
      // hides less of the refinement: it follows the limit wherever the linear blend would have
      // shown more than that. Measured: torus 9.9e-4 (plain 9.7e-4, 7.4e-4 since the gap strip
      // is cut without caps; 2.2e-4 before the bound), creased-box 3.6e-3 (plain 7.8e-3). So it
      // is held to the bound, and to no more than 40 % above the plain surface's pops.
      expect(results.flat).toBeLessThan(1.4 * results.plain);
    });

    // The sweep above bounds how far the surface moves in one step of ×1.06, which is motion as
    // much as popping: halving the step halves what it measures (creased box 3.9e-3 at ×1.06,
    // 2.1e-3 at ×1.03, 1.3e-3 at ×1.015; a scratch run, 2026-11-27). A pop is what does not
    // shrink with the step. So here each LOD scale of the sweep is compared with itself times
    // (1 + 1e-3) and (1 + 1e-4): the movement must fall at least fivefold with the step (linear
    // motion falls tenfold; a pop not at all) and stay under 2e-4 at the larger step. Measured:
    // creased box 7.5e-5 and 9.2e-6, torus 2.1e-5 and 2.2e-6. It samples: a pop is caught where it falls inside one of the 41 windows.
    // Factors rounded up to integers (a pop at every crossing) are: 2.9e-3 (torus) and 8.1e-3
    // (creased box) under the 1e-3 step, against the bound 2e-4. (The factor-rule variants that
    // failed the sweep's bound, tests/gpu/tess/limit-distance.node.test.ts, pass this: the blend held to
    // ½ px and the centroid term at α = 4 moved faster, 1.2e-4 and 1.3e-5, but did not pop. So
    // did the surface without the flat baseline: 2.4e-4 and 3.0e-5 on the creased box.) With the
    // factor rule's bulge term (src/gpu/tess/factors.ts; 2026-11-27): creased box 4.8e-5 and 6.6e-6,
    // torus 1.5e-5 and 1.6e-6, and the sweep above 3.6e-3 and 8.1e-4.
    it(`${name}: the flat-baseline surface moves continuously with the LOD scale (no jump between s and s·(1 + 1e-3))`, async () => {
      const cage = loadCage(text).cage;
      const mesh = prepareMesh(cage);
      const t = await make(true);
      t.setMesh(mesh, buildCatmullClark(cage, mesh));
      let coarse = 0;
      let fine = 0;
      for (let i = 0; i <= 40; i++) {
        const lod = 0.05 * 1.06 ** i;
        const at = (s: number) => run(t, camera(mesh, 3 * mesh.size, lod * s));
        const base = await at(1);
        coarse = Math.max(coarse, maxPop(mesh, base, await at(1 + 1e-3)));
        fine = Math.max(fine, maxPop(mesh, base, await at(1 + 1e-4)));
      }
      console.log('jump', name, JSON.stringify({ step1e3: coarse, step1e4: fine }));
      expect(coarse).toBeLessThan(2e-4);
      expect(fine).toBeLessThan(0.2 * coarse);
    });
  }
});
