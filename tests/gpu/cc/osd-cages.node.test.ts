/**
 * The GPU Catmull-Clark path on OpenSubdiv's regression cages (third-party, ../shared/cages, read
 * from there, never copied; the CI has them): every cage that loads is either prepared and
 * tessellated on its exact limit surface, or refused with a message naming what is not
 * supported. Output vertices (a sample, outside the blended squares round extraordinary
 * vertices) are held against the exact CPU reference, itself equal to OpenSubdiv (the
 * osd-check step of .ci/run), within 1e-6 of the bounding-box diagonal. These cages are where
 * boundaries, corners, darts, creases into extraordinary vertices, valence 2 and n-gons meet
 * the slice kernel and the evaluator's local steps.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { CCReference, exactTessellator, outputErrors, tessellateCC } from '../../support/cc-checks.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import type { MeshReadback } from '../../../src/gpu/device/readback.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import { loadCage } from '../../../src/mesh/index.ts';
import { LimitError } from '../../../src/mesh/errors.ts';
import { type Cage, buildTopology, isClosed } from '../../../src/mesh/index.ts';
import { readBuffer, readMesh } from '../../../src/gpu/device/readback.ts';
import { releaseSurfaceData, surfaceScheme } from '../../../src/gpu/surface/registry.ts';
import { accFaceParam } from '../../../src/gpu/acc/patches.ts';
import { ACC_SCHEMES, type AccScheme, accCage } from '../../../src/subdiv/acc.ts';
import { AccSurface } from '../../../src/subdiv/acc-evaluate.ts';
import { checkTessellation } from '../../support/tess-checks.ts';

const DIR = '../shared/cages';
const TALK = new Set(['suzanne', 'bigguy', 'monsterfrog', 'imrod']); // tests/gpu/cc/talk-models.node.test.ts
const MAX_BOUND = 1e-6;
const SAMPLE = 400;
/** The cages the exact surface refuses, and why: none since semi-sharp creases decay inside the
 * slice kernel (gregory_test7, helmet, hole_test2 and rook, sharpness 7-9, were refused for the
 * uniform levels they needed). Any refusal fails, and so would taking a cage listed here without
 * this list following. (Non-manifold cages load split apart as OpenSubdiv makes them sharp:
 * src/mesh/manifold.ts.) */
const REFUSED: Record<string, RegExp> = {};

/** Cages whose surface meets itself (faces glued back to back, folded over onto each other, and
 * the non-manifold cages, whose vertices and edges are split into copies at one position): the
 * ACC check's topology tests see coincident sheets there, which the cage has; what is held is the
 * rest (surface, NaN). */
const COINCIDENT = new Set(['catmark_val2_back2back', 'catmark_val2_foldover']);
const isSplit = (warnings: { message: string }[]) => warnings.some((w) => /non-manifold|runs the same way|zero-length/.test(w.message));
const COINCIDENCE = /used \d+ times|repeats vertex|share the position .* but are not welded|split-crease copies/;
/** The cages the ACC schemes refuse: those refused at load (none now). */
const ACC_REFUSED = Object.fromEntries(Object.entries(REFUSED).filter(([, why]) => !/levels|valence/.test(why.source)));

let tess: Tessellator | undefined;
const accTess = new Map<AccScheme, Tessellator>();
afterAll(() => {
  tess?.destroy();
  for (const t of accTess.values()) t.destroy();
  return releaseDevice();
});

const present = existsSync(DIR);
const names = present
  ? readdirSync(DIR)
      .filter((f) => f.endsWith('.obj'))
      .map((f) => f.slice(0, -4))
      .filter((n) => !TALK.has(n))
      .sort()
  : [];

describe.skipIf(!present)("Catmull-Clark GPU path and the ACC schemes on OpenSubdiv's regression cages", () => {
  it('every cage is tessellated on its exact limit or refused with a reason', async () => {
    const device = await getDevice();
    tess ??= exactTessellator(device);
    const rows: string[] = [];
    const failures: string[] = [];
    for (const name of names) {
      let loaded: ReturnType<typeof loadCage>;
      try {
        loaded = loadCage(readFileSync(`${DIR}/${name}.obj`, 'utf8'));
      } catch (e) {
        const msg = (e as Error).message;
        rows.push(`${name}: cage refused (${msg.split('\n')[0]})`);
        if (!REFUSED[name]?.test(msg)) failures.push(`${name}: refused at load (${msg.split('\n')[0]})`);
        continue;
      }
      const cage = loaded.cage;
      const mesh = prepareMesh(cage);
      let cc: ReturnType<typeof buildCatmullClark>;
      try {
        cc = buildCatmullClark(cage, mesh);
      } catch (e) {
        const msg = (e as Error).message;
        rows.push(`${name}: refused (${msg})`);
        if (!REFUSED[name]?.test(msg)) failures.push(`${name}: refused (${msg})`);
        // A refusal must say what is unsupported or which limit the cage passes (a LimitError,
        // in the user's terms), never be an internal error.
        if (!(e instanceof LimitError) && !/not supported|unsupported/i.test(msg)) failures.push(`${name}: ${msg}`);
        continue;
      }
      if (name in REFUSED) failures.push(`${name}: taken now; REFUSED must follow`);
      let out: MeshReadback;
      try {
        out = await tessellateCC(device, tess, mesh, cc, testCamera(mesh, 1.5 * mesh.size, 3));
      } catch (e) {
        failures.push(`${name}: ${(e as Error).message}`);
        continue;
      }
      const ref = new CCReference(cage, mesh, cc);
      // The surface is the output triangles: a cage vertex that no face with a surface uses
      // (bare vertices, vertices of holes only) keeps an output slot that nothing reads.
      const used = new Uint8Array(out.vertexCount);
      for (let i = 0; i < 3 * out.triangleCount; i++) used[out.indices[i]] = 1;
      // ... and holds the cage position and no source triangle, never a previous mesh's data.
      for (let v = 0; v < mesh.vertexCount; v++) {
        if (used[v]) continue;
        const same = [0, 1, 2].every((i) => out.positions[3 * v + i] === mesh.positions[3 * v + i]);
        if (!same || out.srcTri[v] !== 0xffffffff) failures.push(`${name}: unused vertex ${v} holds stale data`);
      }
      const { errs, max, nan } = outputErrors(ref, out, SAMPLE);
      const checked = errs.length;
      const faces = cage.faceOffsets.length - 1;
      rows.push(
        `${name}: ${faces} faces, ${Math.round(cc.gpuBytes / faces)} B/face, levels ${cc.levels}, checked ${checked}, max ${max.toExponential(2)}`,
      );
      if (nan > 0 || !(max < MAX_BOUND) || checked === 0) failures.push(`${name}: nan ${nan}, checked ${checked}, max ${max}`);
    }
    console.log(rows.join('\n'));
    expect(failures).toEqual([]);
  }, 600_000);

  // The ACC schemes, one per cage in turn (all three on every cage would cost three times the
  // CI time for the same paths): the cage the scheme takes (n-gons refined once: accCage), every
  // output vertex on the f64 ACC surface at its (face, u, v), watertight where the cage is closed,
  // no NaN (tests/support/tess-checks.ts).
  it('every cage that loads is tessellated by an ACC scheme on its surface, watertight, no NaN', async () => {
    const device = await getDevice();
    const rows: string[] = [];
    const failures: string[] = [];
    for (const [i, name] of names.entries()) {
      const scheme = ACC_SCHEMES[i % ACC_SCHEMES.length];
      let cage: Cage;
      let coincident = COINCIDENT.has(name);
      try {
        const loaded = loadCage(readFileSync(`${DIR}/${name}.obj`, 'utf8'));
        coincident ||= isSplit(loaded.warnings);
        cage = accCage(loaded.cage).cage;
      } catch (e) {
        const msg = (e as Error).message;
        if (!ACC_REFUSED[name]?.test(msg)) failures.push(`${name}: refused at load (${msg.split('\n')[0]})`);
        continue;
      }
      if (name in ACC_REFUSED) failures.push(`${name}: taken now; ACC_REFUSED must follow`);
      let t = accTess.get(scheme);
      if (!t) {
        t = Tessellator.create(device, bakeTables(64), { vertexCapacity: 1 << 20, triangleCapacity: 1 << 20, surface: scheme });
        accTess.set(scheme, t);
      }
      try {
        const mesh = prepareMesh(cage);
        const data = surfaceScheme(scheme).prepare(device, cage, mesh);
        try {
          t.setMesh(mesh, undefined, data.acc);
          device.pushErrorScope('validation');
          const enc = device.createCommandEncoder();
          // Factor 3, or 1 on the cages refined into tens of thousands of patches (car, bishop:
          // their semi-sharp creases decay in accCage's steps): CI time, the same paths.
          t.encode(enc, testCamera(mesh, 1.5 * mesh.size, cage.faceOffsets.length > 8192 ? 1 : 3));
          device.queue.submit([enc.finish()]);
          const out = await readMesh(device, t.output);
          const edgeF = new Uint32Array(await readBuffer(device, t.workBuffer, 4 * mesh.edgeCount, 4 * t.workLayout.edgeF));
          const error = await device.popErrorScope();
          if (error) throw new Error(error.message);
          const cpu = new AccSurface(cage, scheme);
          const report = checkTessellation(mesh, edgeF, out, {
            closed: isClosed(cage, buildTopology(cage)),
            split: mesh.accSplit,
            reference: (tri, w) => {
              const [f, u, v] = accFaceParam(mesh, cage, tri, w);
              const r = cpu.evaluate(f, u, v);
              return { pos: r.P, normal: r.N, bound: 2e-6 };
            },
          });
          const faces = cage.faceOffsets.length - 1;
          rows.push(`${name} ${scheme}: ${faces} patches, ${out.triangleCount} triangles, max ${report.maxPositionError.toExponential(2)}`);
          const problems = report.problems.filter((p) => !(coincident && COINCIDENCE.test(p)));
          if (problems.length) failures.push(`${name} ${scheme}: ${problems.slice(0, 3).join('; ')}`);
        } finally {
          releaseSurfaceData(data);
        }
      } catch (e) {
        failures.push(`${name} ${scheme}: ${(e as Error).message}`);
      }
    }
    console.log(rows.join('\n'));
    expect(failures).toEqual([]);
  }, 600_000);
});
