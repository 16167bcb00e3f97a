/**
 * Catmull-Clark checks shared by the GPU tests: GPU points (tessellation output or samples)
 * against the exact CPU reference (src/subdiv Surface), split into the exact region and the
 * small blended region round irregular vertices (found by the CPU side of the evaluator's region
 * lookup, src/gpu/cc/build.ts regionOf).
 */
import { Surface } from '../../src/subdiv/index.ts';
import { DEFAULT_OPTIONS, type Cage } from '../../src/mesh/index.ts';
import { faceParam } from '../../src/gpu/tess/face-params.ts';
import type { PreparedMesh } from '../../src/gpu/tess/prepare.ts';
import { regionOf, type CatmullClarkData } from '../../src/gpu/cc/build.ts';
import { angleBetween } from './tess-checks.ts';
import { decodeBary } from '../../src/gpu/contract/tess.ts';
import { readMesh, type MeshReadback } from '../../src/gpu/device/readback.ts';
import { Tessellator } from '../../src/gpu/tess/tessellator.ts';
import { bakeTables } from '../../src/pattern/tables.ts';
import type { FactorParams } from '../../src/gpu/contract/tessellated-mesh.ts';

export interface ErrorStats {
  count: number;
  maxP: number; // / bbox diagonal
  rmsP: number;
  p99P: number;
  maxN: number; // degrees
  rmsN: number;
  worst: string;
  worstN: string;
}

const empty = (): ErrorStats & { sp: number; sn: number; nn: number; all: number[] } => ({
  count: 0,
  maxP: 0,
  rmsP: 0,
  p99P: 0,
  maxN: 0,
  rmsN: 0,
  worst: '',
  worstN: '',
  sp: 0,
  sn: 0,
  nn: 0,
  all: [],
});

export class CCReference {
  readonly S: Surface;
  constructor(
    readonly cage: Cage,
    readonly mesh: PreparedMesh,
    readonly cc: CatmullClarkData,
  ) {
    this.S = new Surface(cage, undefined, { ...DEFAULT_OPTIONS, ...cage.fileOptions });
  }

  /** Exact limit at triangle t, weights w (floats summing to 1); and whether the GPU blends there. */
  at(t: number, w: [number, number, number]) {
    const fp = faceParam(this.mesh, this.cage, t, w);
    const k = 'k' in fp ? fp.k : 0;
    const x = 'k' in fp ? fp.s : fp.u,
      y = 'k' in fp ? fp.t : fp.v;
    const ref = 'k' in fp ? this.S.evaluateSubFace(fp.face, fp.k, fp.s, fp.t) : this.S.evaluate(fp.face, fp.u, fp.v);
    return { ref, blended: regionOf(this.cc, t, k, x, y).blended, face: fp.face };
  }

  /** Compare GPU points (positions, normals) at (t, w) items. */
  compare(items: { t: number; w: [number, number, number] }[], pos: ArrayLike<number>, nrm: ArrayLike<number>) {
    const exact = empty(),
      blended = empty();
    let nan = 0;
    items.forEach(({ t, w }, i) => {
      const { ref, blended: b, face } = this.at(t, w);
      const p = [pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]],
        n = [nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]];
      if (![...p, ...n].every(Number.isFinite)) nan++;
      const st = b ? blended : exact;
      const dp = Math.hypot(p[0] - ref.P[0], p[1] - ref.P[1], p[2] - ref.P[2]) / this.mesh.size;
      st.count++;
      st.sp += dp * dp;
      st.all.push(dp);
      if (dp > st.maxP) {
        st.maxP = dp;
        st.worst = `tri ${t} face ${face} w ${w.map((x) => x.toFixed(5))}: ${p} vs ${ref.P}`;
      }
      if (ref.normalDefined) {
        const dn = (angleBetween(n, ref.N) * 180) / Math.PI;
        st.sn += dn * dn;
        st.nn++;
        if (dn > st.maxN) {
          st.maxN = dn;
          st.worstN = `tri ${t} face ${face} w ${w.map((x) => x.toFixed(5))}: ${n} vs ${ref.N}`;
        }
      }
    });
    const p99 = (a: number[]) => (a.length ? a.sort((x, y) => x - y)[Math.floor(0.99 * (a.length - 1))] : 0);
    const fin = (s: ReturnType<typeof empty>): ErrorStats => ({
      count: s.count,
      maxP: s.maxP,
      rmsP: Math.sqrt(s.sp / Math.max(1, s.count)),
      p99P: p99(s.all),
      maxN: s.maxN,
      rmsN: Math.sqrt(s.sn / Math.max(1, s.nn)),
      worst: s.worst,
      worstN: s.worstN,
    });
    return { exact: fin(exact), blended: fin(blended), nan };
  }
}

/** Deterministic random (triangle, barycentric) samples, fixed point, with some at corners and near them. */
export function randomSamples(mesh: PreparedMesh, n: number, seed = 1) {
  let s = seed;
  const rnd = () => (s = (s * 16807) % 2147483647) / 2147483647;
  const out: { t: number; w1: number; w2: number; w: [number, number, number] }[] = [];
  for (let i = 0; i < n; i++) {
    const t = Math.floor(rnd() * mesh.triangleCount);
    let a = rnd(),
      b = rnd();
    if (a + b > 1) {
      a = 1 - a;
      b = 1 - b;
    }
    let w1 = Math.round(a * 65536),
      w2 = Math.round(b * 65536);
    if (i % 8 === 0) {
      w1 = 0;
      w2 = 0;
    }
    if (i % 8 === 1) {
      w1 = 1 + (i % 97);
      w2 = i % 5;
    } // within 2^-10 of corner 0
    if (w1 + w2 > 65536) w2 = 65536 - w1;
    out.push({ t, w1, w2, w: [(65536 - w1 - w2) / 65536, w1 / 65536, w2 / 65536] });
  }
  return out;
}

/** One rebuild of `mesh` by a Catmull-Clark tessellator, read back; throws on a validation error. */
/** The exact surface's compute tessellator the GPU checks tessellate with (the exact limit: flat
 * baseline off; tables to factor 64), for up to `capacity` vertices and triangles. */
export function exactTessellator(device: GPUDevice, capacity = 1 << 20): Tessellator {
  return Tessellator.create(device, bakeTables(64), {
    vertexCapacity: capacity,
    triangleCapacity: capacity,
    surface: 'catmull-clark',
    flatBaseline: false,
  });
}

export async function tessellateCC(
  device: GPUDevice,
  tess: Tessellator,
  mesh: PreparedMesh,
  cc: CatmullClarkData,
  camera: FactorParams,
): Promise<MeshReadback> {
  device.pushErrorScope('validation');
  tess.setMesh(mesh, cc);
  const enc = device.createCommandEncoder({ label: 'cc check rebuild' });
  tess.encode(enc, camera);
  device.queue.submit([enc.finish()]);
  const out = await readMesh(device, tess.output);
  const error = await device.popErrorScope();
  if (error) throw new Error(`WebGPU validation error: ${error.message}`);
  return out;
}

export interface OutputErrors {
  /** Distances (fractions of the diagonal) of the vertices held, ascending. */
  errs: number[];
  max: number;
  p99: number;
  /** Vertices with a non-finite position; vertices in a blended square (not held). */
  nan: number;
  blended: number;
  worst: string;
}

/**
 * Output vertices (every `step`-th of those the triangles use, so a sample of about `sample`)
 * against the exact reference, outside the blended squares round extraordinary vertices.
 */
export function outputErrors(ref: CCReference, out: MeshReadback, sample: number): OutputErrors {
  const used = new Uint8Array(out.vertexCount);
  for (let i = 0; i < 3 * out.triangleCount; i++) used[out.indices[i]] = 1;
  const step = Math.max(1, Math.floor(out.vertexCount / sample));
  const errs: number[] = [];
  let nan = 0,
    blended = 0,
    worst = '',
    worstD = -1;
  for (let v = 0; v < out.vertexCount; v += step) {
    if (!used[v]) continue;
    const [w0, w1, w2] = decodeBary(out.bary[v]);
    const t = out.srcTri[v];
    const w: [number, number, number] = [w0 / 65536, w1 / 65536, w2 / 65536];
    const p = [out.positions[3 * v], out.positions[3 * v + 1], out.positions[3 * v + 2]];
    if (!p.every(Number.isFinite)) {
      nan++;
      continue;
    }
    const r = ref.at(t, w);
    if (r.blended) {
      blended++;
      continue;
    }
    const d = Math.hypot(p[0] - r.ref.P[0], p[1] - r.ref.P[1], p[2] - r.ref.P[2]) / ref.mesh.size;
    if (d > worstD) {
      worstD = d;
      worst = `tri ${t} face ${r.face} w ${w.map((x) => x.toFixed(5))}`;
    }
    errs.push(d);
  }
  errs.sort((a, b) => a - b);
  return { errs, max: errs[errs.length - 1] ?? 0, p99: errs[Math.floor(0.99 * (errs.length - 1))] ?? 0, nan, blended, worst };
}
