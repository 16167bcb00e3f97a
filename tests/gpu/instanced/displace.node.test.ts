/**
 * Displacement in the instanced tessellator (src/gpu/instanced/displace-vertex.ts) on the project's
 * displaced models (brick box: 8-bit map, clamp, every box edge a UV seam; wrinkled creature:
 * 16-bit map, repeat, a cylindrical seam), in Node (the maps are PNG files, decoded by
 * src/mesh/heightmap-png.ts), at random per-patch levels. For every headless output vertex (the
 * draw's own vertex function, in compute), at the (triangle, weights) its pattern point is
 * evaluated at (its owner: ownerPoint, the CPU twin of the WGSL redirect):
 *  - the CPU reference of the displaced surface: exact Catmull-Clark, src/subdiv/displace.ts
 *    DisplacedSurface.at (with its seam rule); Phong and Gregory ACC, the scheme's f64 twin + h·N
 *    as tests/gpu/tess/displacement.node.test.ts; within POSITION_TOL of the diagonal, and where the limit
 *    normal is undefined (corners of sharp creases) |distance from the undisplaced point − |h||;
 *  - the COMPUTE tessellator's displaced output at the same (triangle, weights), where its output
 *    has that point (fixed factor 8: every point of a level ≤ 8 pattern), positions within F32_TOL
 *    of the diagonal, displaced normals within NORMAL_F32_DEG (this checks the tangents each
 *    surface hands displacePoint, ACC's carried from (u, v) to the triangle's weights);
 *  - no NaN; the crack check: along every shared cage edge both sides' points are bit-identical
 *    (gap exactly 0), with displacement on.
 */
import { readFileSync } from 'node:fs';
import { afterAll, describe, expect, it } from 'vitest';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { checkHeadless, randomLevels } from '../../support/instanced-checks.ts';
import { angleBetween } from '../../support/tess-checks.ts';
import { InstancedTessellator } from '../../../src/gpu/instanced/instanced.ts';
import { prepareInstanced, type InstancedMesh } from '../../../src/gpu/instanced/prepare-patches.ts';
import { patchTriangle } from '../../../src/gpu/instanced/cpu-twin.ts';
import type { HeadlessInstanced } from '../../../src/gpu/instanced/headless-output.ts';
import { ccSurfaceTessellator } from '../../../src/gpu/instanced/surface-cc.ts';
import { displacementLender, ownerPoint } from '../../../src/gpu/instanced/displace-vertex.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh, type PreparedMesh } from '../../../src/gpu/tess/prepare.ts';
import { readMesh } from '../../../src/gpu/device/readback.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { prepareDisplacement } from '../../../src/gpu/tess/displacement-map.ts';
import { prepareAccSurface } from '../../../src/gpu/acc/surface.ts';
import { AccPatches } from '../../../src/gpu/acc/patches.ts';
import { faceParam } from '../../../src/gpu/tess/face-params.ts';
import { phongPoint } from '../../../src/gpu/surface/phong.ts';
import { decodeBary } from '../../../src/gpu/contract/tess.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import { DEFAULT_OPTIONS, loadCage, uvAtSubFace, type Cage } from '../../../src/mesh/index.ts';
import { decodeHeightPng } from '../../../src/mesh/heightmap-png.ts';
import { type HeightMap, type HeightWrap, sampleHeight } from '../../../src/mesh/heightmap.ts';
import { DisplacedSurface, Surface } from '../../../src/subdiv/index.ts';
import { AccSurface } from '../../../src/subdiv/acc-evaluate.ts';

/** × the model's diagonal: the bound for the displaced surface (as the compute
 * tessellator's test, whose comment gives the 8-bit budget). */
const POSITION_TOL = 1e-5;
/** × the diagonal: two f32 evaluations of the same formula at the same integers. */
const F32_TOL = 1e-6;
/** Degrees between the displaced normals of the two tessellators at the same point (the same
 * formula; on ACC the tangents reach w-space by another f32 route). */
const NORMAL_F32_DEG = 0.01;
const MAX_LEVEL = 8;
const COMPUTE_FACTOR = 8;

interface Entry {
  model: string;
  heightMap: string;
  bits: 8 | 16;
  scale: number;
  midLevel: number;
  wrap: HeightWrap;
}
const dir = new URL('../../../public/models/', import.meta.url);
const entries = JSON.parse(readFileSync(new URL('displaced.json', dir), 'utf8')) as Entry[];

type Kind = 'phong' | 'catmull-clark' | 'gregory-acc';
const made: { destroy(): void }[] = [];
afterAll(() => {
  for (const t of made) t.destroy();
  return releaseDevice();
});

/** The instanced tessellator on `kind` with displacement, its lender, and the compute tessellator's
 * displaced output at a fixed factor, keyed by (triangle, weights). */
async function setUp(kind: Kind, e: Entry) {
  const device = await getDevice();
  const cage = loadCage(readFileSync(new URL(e.model, dir), 'utf8')).cage;
  const map = decodeHeightPng(readFileSync(new URL(e.heightMap, dir)));
  const prepared = prepareMesh(cage);
  const m = prepareInstanced(cage, prepared);
  const disp = prepareDisplacement(cage, prepared, map, e.wrap);
  const settings = { scale: e.scale, midLevel: e.midLevel, enabled: true };
  const cc = kind === 'catmull-clark' ? buildCatmullClark(cage, prepared) : undefined;
  const t = new InstancedTessellator(device, {
    surface: kind === 'phong' ? 'evalSurface' : kind === 'catmull-clark' ? 'lent-limit' : 'acc',
    displacement: true,
  });
  made.push(t);
  let source: AccPatches | Tessellator | undefined;
  let lender: Tessellator | undefined;
  if (cc) source = ccSurfaceTessellator(device, prepared, cc, disp, settings);
  else {
    lender = displacementLender(device, prepared, disp, settings);
    made.push(lender);
    if (kind === 'gregory-acc') source = new AccPatches(device, cage, 'gregory-acc');
  }
  if (source) made.push(source);
  t.setMesh(m, source, lender);

  // The compute tessellator, same surface and map.
  const compute = Tessellator.create(device, bakeTables(COMPUTE_FACTOR), {
    surface: kind,
    flatBaseline: false,
    vertexCapacity: 1 << 17,
    triangleCapacity: 1 << 17,
  });
  made.push(compute);
  const acc = kind === 'gregory-acc' ? prepareAccSurface(device, cage, prepared, kind) : undefined;
  compute.setMesh(prepared, cc, acc, disp);
  compute.setDisplacement(settings);
  device.pushErrorScope('validation');
  const enc = device.createCommandEncoder();
  compute.encode(enc, testCamera(prepared, 1.5 * prepared.size, COMPUTE_FACTOR));
  device.queue.submit([enc.finish()]);
  const co = await readMesh(device, compute.output);
  expect((await device.popErrorScope())?.message).toBeUndefined();
  acc?.patches.destroy();
  const computeAt = new Map<string, number>();
  for (let v = 0; v < co.vertexCount; v++) computeAt.set(`${co.srcTri[v]} ${decodeBary(co.bary[v]).join(' ')}`, v);
  return { t, m, cage, map, prepared, computeAt, co };
}

/** Each output vertex's owner triangle and weights (what the vertex function evaluates). */
function ownerItems(m: InstancedMesh, out: HeadlessInstanced) {
  return Array.from({ length: out.vertexCount }, (_, v) => {
    const p = out.patch[v],
      P = out.patchLevels[p];
    const pt = patchTriangle(m, p, P, Math.round(out.uv[2 * v] * P), Math.round(out.uv[2 * v + 1] * P));
    return ownerPoint(m.prepared, pt.t, pt.w);
  });
}

/** On a triangle face: the weights of its corners 1 and 2 at triangle t's weights w (as tests/gpu/tess/displacement.node.test.ts). */
function triangleUv(mesh: PreparedMesh, cage: Cage, t: number, w: [number, number, number]): [number, number] {
  const f = mesh.triFace[t];
  const s = cage.faceOffsets[f];
  const local = [0, 1, 2].map((i) => [0, 1, 2].find((j) => cage.faceIndices[s + j] === mesh.triVerts[3 * t + i])!);
  const l = [0, 0, 0];
  for (let i = 0; i < 3; i++) l[local[i]] += w[i];
  return [l[1], l[2]];
}

/** The f64 reference at (t, w): the displaced point, the undisplaced one, h, and whether the normal is defined. */
function reference(kind: Kind, cage: Cage, mesh: PreparedMesh, map: HeightMap, e: Entry) {
  if (kind === 'catmull-clark') {
    const ref = new DisplacedSurface(new Surface(cage, undefined, { ...DEFAULT_OPTIONS, ...cage.fileOptions }), map, e);
    return (t: number, w: [number, number, number]) => {
      const r = ref.at(faceParam(mesh, cage, t, w));
      return { pos: r.P, base: r.base.P, h: r.h, defined: r.base.normalDefined };
    };
  }
  const acc = kind === 'gregory-acc' ? new AccSurface(cage, kind) : undefined;
  return (t: number, w: [number, number, number]) => {
    const fp = faceParam(mesh, cage, t, w);
    let b: { pos: number[]; normal: number[] };
    if (!acc) b = phongPoint(mesh, t, w);
    else {
      const [u, v] = 'k' in fp ? triangleUv(mesh, cage, t, w) : [fp.u, fp.v];
      const r = acc.evaluate(fp.face, u, v);
      b = { pos: r.P, normal: r.N };
    }
    const uv = 'k' in fp ? uvAtSubFace(cage, fp.face, fp.k, fp.s, fp.t).uv : uvAtSubFace(cage, fp.face, 0, fp.u, fp.v).uv;
    const h = (sampleHeight(map, uv[0], uv[1], e.wrap).value - e.midLevel) * e.scale;
    return { pos: [0, 1, 2].map((c) => b.pos[c] + h * b.normal[c]), base: b.pos, h, defined: true };
  };
}

const cases: [Kind, Entry][] = [
  ['phong', entries[0]],
  ['phong', entries[1]],
  ['catmull-clark', entries[0]],
  ['catmull-clark', entries[1]],
  ['gregory-acc', entries[0]],
];

describe('displacement in the instanced tessellator', () => {
  for (const [kind, e] of cases) {
    it(`${kind}, ${e.model}, random per-patch levels ≤ ${MAX_LEVEL}: every vertex on the f64 displaced surface and the compute tessellator's, bit-identical across every cage edge`, async () => {
      const { t, m, cage, map, prepared, computeAt, co } = await setUp(kind, e);
      const device = t.device;
      const wanted = randomLevels(m.patchCount, MAX_LEVEL, 7 + e.model.length);
      t.setWanted(wanted);
      device.pushErrorScope('validation');
      const out = await t.headless({ mode: 'per-patch' });
      expect((await device.popErrorScope())?.message).toBeUndefined();
      // Layout, snap, no NaN, and the crack check (with displacement on).
      const r = checkHeadless(m, out, t, false);

      const size = prepared.size;
      const ref = reference(kind, cage, prepared, map, e);
      const items = ownerItems(m, out);
      let maxP = 0,
        undefinedNormal = 0,
        maxH = 0,
        matched = 0,
        vsCompute = 0,
        normalVsCompute = 0;
      items.forEach(({ t: tri, w }, v) => {
        const p = [0, 1, 2].map((c) => out.positions[3 * v + c]);
        const wf: [number, number, number] = [w[0] / 65536, w[1] / 65536, w[2] / 65536];
        const x = ref(tri, wf);
        maxH = Math.max(maxH, Math.abs(x.h));
        if (x.defined) maxP = Math.max(maxP, Math.hypot(p[0] - x.pos[0], p[1] - x.pos[1], p[2] - x.pos[2]) / size);
        else {
          undefinedNormal++;
          const moved = Math.hypot(p[0] - x.base[0], p[1] - x.base[1], p[2] - x.base[2]);
          maxP = Math.max(maxP, Math.abs(moved - Math.abs(x.h)) / size);
        }
        const c = computeAt.get(`${tri} ${w.join(' ')}`);
        if (c !== undefined) {
          matched++;
          const q = [0, 1, 2].map((k) => co.positions[3 * c + k]);
          vsCompute = Math.max(vsCompute, Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) / size);
          const n = [0, 1, 2].map((k) => out.normals[3 * v + k]);
          const nq = [0, 1, 2].map((k) => co.normals[3 * c + k]);
          normalVsCompute = Math.max(normalVsCompute, (angleBetween(n, nq) * 180) / Math.PI);
        }
      });
      console.log(
        `${kind} ${e.model}: ${m.patchCount} patches, ${out.vertexCount} vertices; max ${maxP.toExponential(2)} of the diagonal ` +
          `(${undefinedNormal} at undefined normals, held to |h|); max |h| ${maxH.toFixed(4)}; ` +
          `${matched} at a compute output point, max ${vsCompute.toExponential(2)}, normals ${normalVsCompute.toFixed(5)}°; ${r.edgesChecked} shared edges, gap ${r.gap}`,
      );
      expect(maxH).toBeGreaterThan(0.2 * e.scale); // the map does displace
      expect(maxP).toBeLessThan(POSITION_TOL);
      expect(matched).toBeGreaterThan(out.vertexCount / 4);
      expect(vsCompute).toBeLessThan(F32_TOL);
      expect(normalVsCompute).toBeLessThan(NORMAL_F32_DEG);
      expect(r.edgesChecked).toBeGreaterThan(0);
      expect(r.gap).toBe(0);
    }, 300_000);
  }
});
