/**
 * Single-crease patches on an OpenSubdiv regression cage (third-party, read from ../shared/cages,
 * never copied; skipped where it is absent): catmark_pawn's σ ≈ 5 crease loops all run straight
 * through valence-4 vertices, so the cage is prepared with 1 uniform level (6 before the
 * single-crease patches: 376 KB of GPU data per face, now ~0.5 KB), and its output vertices lie
 * on the exact limit (src/subdiv) within 1e-6 of the bounding-box diagonal, outside the blended
 * squares round extraordinary vertices.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { existsSync, readFileSync } from 'node:fs';
import { getDevice, releaseDevice, testCamera } from './gpu-device.ts';
import { CCReference } from './cc-checks.ts';
import { Tessellator } from '../src/gpu/tessellator.ts';
import { prepareMesh } from '../src/gpu/prepare.ts';
import { readMesh } from '../src/gpu/readback.ts';
import { buildCatmullClark } from '../src/gpu/cc/build.ts';
import { bakeTables } from '../src/pattern/tables.ts';
import { decodeBary } from '../src/gpu/contract.ts';
import { loadCage } from '../src/mesh/index.ts';

const FILE = '../shared/cages/catmark_pawn.obj';
const MAX_BOUND = 1e-6;
const SAMPLE = 3000;

let tess: Tessellator | undefined;
afterAll(() => {
  tess?.destroy();
  return releaseDevice();
});

describe.skipIf(!existsSync(FILE))('single-crease patches on catmark_pawn', () => {
  it('one uniform level, ≤ 1 KB per face, output vertices on the exact limit', async () => {
    const cage = loadCage(readFileSync(FILE, 'utf8')).cage;
    const mesh = prepareMesh(cage);
    const cc = buildCatmullClark(cage, mesh);
    const faces = cage.faceOffsets.length - 1;
    expect(cc.levels).toBe(1);
    expect(cc.singleCreaseCount).toBeGreaterThan(0);
    expect(cc.gpuBytes / faces).toBeLessThan(1024);
    const device = await getDevice();
    tess ??= Tessellator.create(device, bakeTables(64), {
      vertexCapacity: 1 << 20,
      triangleCapacity: 1 << 20,
      surface: 'catmull-clark',
      flatBaseline: false,
    });
    device.pushErrorScope('validation');
    tess.setMesh(mesh, cc);
    const enc = device.createCommandEncoder();
    tess.encode(enc, testCamera(mesh, 1.5 * mesh.size, 3));
    device.queue.submit([enc.finish()]);
    const out = await readMesh(device, tess.output);
    expect((await device.popErrorScope())?.message).toBeUndefined();

    const ref = new CCReference(cage, mesh, cc);
    const step = Math.max(1, Math.floor(out.vertexCount / SAMPLE));
    const errs: number[] = [];
    let nan = 0,
      worst = '',
      worstD = 0;
    for (let v = 0; v < out.vertexCount; v += step) {
      const b = out.bary[v];
      const [, w1, w2] = decodeBary(b);
      const t = out.srcTri[v];
      const w: [number, number, number] = [(65536 - w1 - w2) / 65536, w1 / 65536, w2 / 65536];
      const p = [out.positions[3 * v], out.positions[3 * v + 1], out.positions[3 * v + 2]];
      if (!p.every(Number.isFinite)) {
        nan++;
        continue;
      }
      const r = ref.at(t, w);
      if (r.blended) continue;
      const d = Math.hypot(p[0] - r.ref.P[0], p[1] - r.ref.P[1], p[2] - r.ref.P[2]) / mesh.size;
      if (d > worstD) {
        worstD = d;
        worst = `tri ${t} face ${r.face} w ${w.map((x) => x.toFixed(5))}`;
      }
      errs.push(d);
    }
    errs.sort((a, b) => a - b);
    const p99 = errs[Math.floor(0.99 * (errs.length - 1))] ?? 0;
    console.log(
      'catmark_pawn',
      JSON.stringify({
        faces,
        levels: cc.levels,
        single: cc.singleCreaseCount,
        bytesPerFace: Math.round(cc.gpuBytes / faces),
        checked: errs.length,
        max: worstD,
        p99,
      }),
    );
    expect(nan).toBe(0);
    expect(worstD, worst).toBeLessThan(MAX_BOUND);
  });
});
