/**
 * Displacement in the compute tessellator (wgsl/tess/displace.wgsl, src/gpu/tess/displacement-map.ts) against
 * the CPU reference of the displaced surface, on the project's displaced models (brick box: an
 * 8-bit map, clamp, every box edge a UV seam; wrinkled creature: a 16-bit map, repeat, a
 * cylindrical seam), in Node (the maps are PNG files decoded by src/mesh/heightmap-png.ts).
 *
 * For every output vertex, at the (triangle, weights) it records:
 *  - exact Catmull-Clark: src/subdiv/displace.ts DisplacedSurface.at, i.e. the f64 limit +
 *    h(uv)·N WITH the seam rule (a point on a cage edge or vertex through its owner face), so a
 *    GPU vertex whose uv came from the other face of a seam would fail;
 *  - Phong and Gregory ACC: the scheme's f64 CPU twin (src/gpu/surface/phong.ts, src/subdiv/acc.ts) + h·N
 *    with the same uv rule (src/mesh/uv.ts at src/gpu/tess/face-params.ts's face parameter);
 * positions within POSITION_TOL of the diagonal, watertight after the weld, no NaN; and the
 * displaced normals of the exact surface against the reference's.
 *
 * Bounds (measured values beside them):
 *  - POSITION_TOL 1e-5 of the diagonal (the figure). The GPU reads the same integer
 *    texels, so what separates the two is f32: the surface itself (≤ 2e-6, tests/gpu/cc/cc.gpu.test.ts)
 *    and the uv, whose f32 error δuv moves h by at most scale·W·δuv·(largest texel step): for
 *    the 8-bit 512-wide brick map (steps up to 1) and scale 0.06, 3e-6 of a model unit at
 *    δuv = 1e-7 (src/subdiv/displace.ts, "Precision budget").
 *  - Normals: NORMAL_TOL_DEG at the points where the reference's normal is a derivative
 *    (normalExact: not at an extraordinary vertex) and the point is not within 1e-3 texel of a
 *    texel line: there the bilinear map's gradient jumps, and f32 and f64 may take the two
 *    different sides (both are right); those points are counted, not held.
 */
import { readFileSync } from 'node:fs';
import { afterAll, describe, expect, it } from 'vitest';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { checkTessellation, angleBetween, firstAtPosition } from '../../support/tess-checks.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh, type PreparedMesh } from '../../../src/gpu/tess/prepare.ts';
import { readBuffer, readMesh, type MeshReadback } from '../../../src/gpu/device/readback.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { prepareDisplacement } from '../../../src/gpu/tess/displacement-map.ts';
import { prepareAccSurface } from '../../../src/gpu/acc/surface.ts';
import { faceParam } from '../../../src/gpu/tess/face-params.ts';
import { phongPoint } from '../../../src/gpu/surface/phong.ts';
import { decodeBary } from '../../../src/gpu/contract/tess.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import { DEFAULT_OPTIONS, loadCage, uvAtSubFace, type Cage } from '../../../src/mesh/index.ts';
import { decodeHeightPng } from '../../../src/mesh/heightmap-png.ts';
import { type DisplacedModelEntry, type HeightMap, sampleHeight } from '../../../src/mesh/heightmap.ts';
import { DisplacedSurface, Surface } from '../../../src/subdiv/index.ts';
import { AccSurface } from '../../../src/subdiv/acc-evaluate.ts';
import type { Surface as SurfaceKind } from '../../../src/gpu/tess/passes.ts';

const POSITION_TOL = 1e-5; // × the model's bounding-box diagonal
const NORMAL_TOL_DEG = 0.05;
const FACTOR = 6;

type Entry = DisplacedModelEntry;
const dir = new URL('../../../public/models/', import.meta.url);
const entries = JSON.parse(readFileSync(new URL('displaced.json', dir), 'utf8')) as Entry[];
const load = (e: Entry) => ({
  cage: loadCage(readFileSync(new URL(e.model, dir), 'utf8')).cage,
  map: decodeHeightPng(readFileSync(new URL(e.heightMap, dir))),
});

const tables = bakeTables(64);
const made: Tessellator[] = [];
afterAll(() => {
  made.forEach((t) => t.destroy());
  return releaseDevice();
});

/** Tessellate `cage` displaced by `map` with a tessellator over `surface`, read back. */
async function run(surface: SurfaceKind, cage: Cage, map: HeightMap, e: Entry, o: { fixed?: number; enabled?: boolean } = {}) {
  const device = await getDevice();
  const mesh = prepareMesh(cage);
  const tess = Tessellator.create(device, tables, { surface, flatBaseline: false, vertexCapacity: 1 << 18, triangleCapacity: 1 << 18 });
  made.push(tess);
  const cc = surface === 'catmull-clark' ? buildCatmullClark(cage, mesh) : undefined;
  const acc = surface.endsWith('-acc') ? prepareAccSurface(device, cage, mesh, surface as 'gregory-acc') : undefined;
  device.pushErrorScope('validation');
  tess.setMesh(mesh, cc, acc, prepareDisplacement(cage, mesh, map, e.wrap));
  tess.setDisplacement({ scale: e.scale, midLevel: e.midLevel, enabled: o.enabled ?? true });
  const enc = device.createCommandEncoder();
  tess.encode(enc, testCamera(mesh, 1.5 * mesh.size, 'fixed' in o ? o.fixed : FACTOR));
  device.queue.submit([enc.finish()]);
  const out = await readMesh(device, tess.output);
  const edgeF = new Uint32Array(await readBuffer(device, tess.workBuffer, 4 * mesh.edgeCount, 4 * tess.workLayout.edgeF));
  expect((await device.popErrorScope())?.message).toBeUndefined();
  acc?.patches.destroy();
  return { mesh, out, edgeF };
}

/** Distance of the texel coordinate of uv to the nearest texel line (in texels). */
function texelLineDistance(map: HeightMap, uv: readonly number[]): number {
  const x = uv[0] * map.width - 0.5,
    y = (1 - uv[1]) * map.height - 0.5;
  return Math.min(Math.abs(x - Math.round(x)), Math.abs(y - Math.round(y)));
}

function usedVertices(out: MeshReadback): number[] {
  const used = new Uint8Array(out.vertexCount);
  for (let i = 0; i < 3 * out.triangleCount; i++) used[out.indices[i]] = 1;
  return [...used.keys()].filter((v) => used[v]);
}

function weights(out: MeshReadback, v: number): [number, number, number] {
  const [w0, w1, w2] = decodeBary(out.bary[v]);
  return [w0 / 65536, w1 / 65536, w2 / 65536];
}

describe('displacement in the compute tessellator', () => {
  for (const e of entries) {
    it(`exact Catmull-Clark, ${e.model}: every output vertex on the f64 displaced limit (seam rule), normals, watertight`, async () => {
      const { cage, map } = load(e);
      const { mesh, out, edgeF } = await run('catmull-clark', cage, map, e);
      const ref = new DisplacedSurface(new Surface(cage, undefined, { ...DEFAULT_OPTIONS, ...cage.fileOptions }), map, e);
      // Positions (≤ 1e-5 of the diagonal, checkTessellation's bound), watertight, counts, no NaN.
      const report = checkTessellation(mesh, edgeF, out, {
        closed: true,
        split: true,
        // Where the limit has no tangent plane (corners of sharp creases) the direction is a
        // convention (the owner face's one-sided normal, whose GPU and CPU versions differ):
        // those vertices are held below to their distance |h| from the limit point instead.
        reference: (t, w) => {
          const r = ref.at(faceParam(mesh, cage, t, w));
          return r.base.normalDefined ? { pos: r.P, normal: r.N } : null;
        },
      });
      let maxP = 0,
        maxN = 0,
        held = 0,
        onLines = 0,
        irregular = 0,
        undefinedNormal = 0,
        maxH = 0;
      // The second copy of a point where normals split (an infinitely sharp crease, prepare.ts
      // splitCreases) lies where the first does (the seam rule's owner side), and its normal is
      // its own side's: the displaced surface in its own face's uvs (no seam rule).
      const first = firstAtPosition(out);
      for (const v of usedVertices(out)) {
        const w = weights(out, v);
        const fp = faceParam(mesh, cage, out.srcTri[v], w);
        if (first[v] !== v) {
          const local = ref.evaluateLocal(fp);
          const n = [out.normals[3 * v], out.normals[3 * v + 1], out.normals[3 * v + 2]];
          if (local.normalExact && texelLineDistance(map, local.uv) >= 1e-3)
            maxN = Math.max(maxN, (angleBetween(n, local.N) * 180) / Math.PI);
          continue;
        }
        const r = ref.at(fp);
        const p = [out.positions[3 * v], out.positions[3 * v + 1], out.positions[3 * v + 2]];
        const n = [out.normals[3 * v], out.normals[3 * v + 1], out.normals[3 * v + 2]];
        expect([...p, ...n].every(Number.isFinite)).toBe(true);
        maxH = Math.max(maxH, Math.abs(r.h));
        const dP = Math.hypot(p[0] - r.P[0], p[1] - r.P[1], p[2] - r.P[2]) / mesh.size;
        if (r.base.normalDefined) maxP = Math.max(maxP, dP);
        else {
          undefinedNormal++;
          const b = r.base.P;
          const moved = Math.hypot(p[0] - b[0], p[1] - b[1], p[2] - b[2]);
          maxP = Math.max(maxP, Math.abs(moved - Math.abs(r.h)) / mesh.size);
        }
        if (!r.normalExact) irregular++;
        else if (texelLineDistance(map, r.uv) < 1e-3) onLines++;
        else {
          held++;
          maxN = Math.max(maxN, (angleBetween(n, r.N) * 180) / Math.PI);
        }
      }
      console.log(e.model, { vertices: out.vertexCount, maxP, maxNdeg: maxN, held, onLines, irregular, undefinedNormal, maxH });
      expect(report.problems).toEqual([]);
      expect(maxH).toBeGreaterThan(0.2 * e.scale); // the map does displace
      expect(maxP).toBeLessThan(POSITION_TOL);
      expect(maxN).toBeLessThan(NORMAL_TOL_DEG);
      expect(onLines).toBeLessThan(0.02 * held);
    }, 300_000);
  }

  const e = entries[0];
  it(`the factor rule counts the heights (${e.model}, adaptive): no edge coarser than without them, some finer, none past 2 segments a texel`, async () => {
    const { cage, map } = load(e);
    const off = await run('catmull-clark', cage, map, e, { fixed: undefined, enabled: false });
    const on = await run('catmull-clark', cage, map, e, { fixed: undefined, enabled: true });
    const disp = prepareDisplacement(cage, off.mesh, map, e.wrap);
    const texels = new Float32Array(disp.dispEdge.buffer);
    let finer = 0;
    for (let k = 0; k < off.mesh.edgeCount; k++) {
      const a = off.edgeF[k] / 65536,
        b = on.edgeF[k] / 65536;
      expect(b).toBeGreaterThanOrEqual(a);
      if (b > a) {
        finer++;
        expect(b).toBeLessThanOrEqual(2 * texels[3 * k + 2] * (1 + 1e-6) + 1e-4);
      }
    }
    console.log(`${e.model}: ${finer} of ${off.mesh.edgeCount} edges finer; triangles ${off.out.triangleCount} → ${on.out.triangleCount}`);
    expect(finer).toBeGreaterThan(0);
    expect(on.out.triangleCount).toBeGreaterThan(off.out.triangleCount);
  }, 300_000);

  for (const surface of ['phong', 'gregory-acc'] as const) {
    it(`${surface}, ${e.model}: every output vertex on the f64 surface + h·N, watertight`, async () => {
      const { cage, map } = load(e);
      const { mesh, out, edgeF } = await run(surface, cage, map, e);
      const acc = surface === 'gregory-acc' ? new AccSurface(cage, surface) : undefined;
      const base = (t: number, w: [number, number, number], fp: ReturnType<typeof faceParam>) => {
        if (!acc) return phongPoint(mesh, t, w);
        // ACC's (u, v): quads the face's (u, v); triangles (w1, w2) of the face (= the kite's linear map).
        const [u, v] = 'k' in fp ? triangleUv(mesh, cage, t, w) : [fp.u, fp.v];
        const r = acc.evaluate(fp.face, u, v);
        return { pos: r.P, normal: r.N };
      };
      let maxP = 0;
      const reference = (t: number, w: [number, number, number]) => {
        const fp = faceParam(mesh, cage, t, w);
        const b = base(t, w, fp);
        const uv = 'k' in fp ? uvAtSubFace(cage, fp.face, fp.k, fp.s, fp.t).uv : uvAtSubFace(cage, fp.face, 0, fp.u, fp.v).uv;
        const h = (sampleHeight(map, uv[0], uv[1], e.wrap).value - e.midLevel) * e.scale;
        return { pos: [0, 1, 2].map((c) => b.pos[c] + h * b.normal[c]), normal: b.normal };
      };
      // Positions (≤ 1e-5 of the diagonal), watertight, the pattern's counts, no NaN.
      // Gregory ACC's creases (sharpness ≥ 1) are output once per side (mesh.accSplit).
      const report = checkTessellation(mesh, edgeF, out, { closed: true, reference, split: acc ? mesh.accSplit : false });
      expect(report.problems).toEqual([]);
      maxP = report.maxPositionError;
      console.log(surface, e.model, { vertices: out.vertexCount, maxP });
      expect(maxP).toBeLessThan(POSITION_TOL);
      expect(usedVertices(out).length).toBeGreaterThan(mesh.vertexCount);
    }, 300_000);
  }
});

/** On a triangle face: the weights of its corners 1 and 2 at triangle t's weights w (t is the face itself). */
function triangleUv(mesh: PreparedMesh, cage: Cage, t: number, w: [number, number, number]): [number, number] {
  const f = mesh.triFace[t];
  const s = cage.faceOffsets[f];
  const local = [0, 1, 2].map((i) => [0, 1, 2].find((j) => cage.faceIndices[s + j] === mesh.triVerts[3 * t + i])!);
  const l = [0, 0, 0];
  for (let i = 0; i < 3; i++) l[local[i]] += w[i];
  return [l[1], l[2]];
}
