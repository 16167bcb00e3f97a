/** The headless CLI end to end: its main in this process, and a real process where the claim is the
 * process's (exit status, stdout); Dawn in Node (SwiftShader here). */
import { describe, it, expect } from 'vitest';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { loadCage, DEFAULT_OPTIONS } from '../../../src/mesh/index.ts';
import { decodeHeightPng } from '../../../src/mesh/heightmap-png.ts';
import { DisplacedSurface, Surface } from '../../../src/subdiv/index.ts';
import { runCli, spawnCli, statsLine } from '../../support/tessellate-cli.ts';

const dir = mkdtempSync(join(tmpdir(), 'tessellab-cli-'));
// In this process (tests/support/tessellate-cli.ts says why); spawnCli where the claim is the process's.
const run = runCli;

describe('npm run tessellate', () => {
  it('writes a watertight OBJ and one parameter per vertex', async () => {
    const out = join(dir, 'torus.obj');
    const params = join(dir, 'torus.txt');
    const r = await run('public/models/torus.obj', '--fixed', '4', '--surface', 'phong', '--out', out, '--params', params);
    expect(r.status, r.stderr).toBe(0);
    const obj = readFileSync(out, 'utf8').split('\n');
    const v = obj.filter((l) => l.startsWith('v ')).length;
    const faces = obj
      .filter((l) => l.startsWith('f '))
      .map((l) =>
        l
          .slice(2)
          .split(' ')
          .map((x) => Number(x.split('//')[0])),
      );
    const cageFaces = readFileSync('public/models/torus.obj', 'utf8')
      .split('\n')
      .filter((l) => l.startsWith('f ')).length;
    expect(faces.length).toBe(cageFaces * 2 * 16); // quads → 2 triangles → 16 each at factor 4
    const directed = new Set<string>();
    for (const f of faces) for (let i = 0; i < 3; i++) directed.add(`${f[i]},${f[(i + 1) % 3]}`);
    for (const e of directed) {
      const [a, b] = e.split(',');
      expect(directed.has(`${b},${a}`)).toBe(true);
    }
    const lines = readFileSync(params, 'utf8').trim().split('\n');
    expect(lines.length).toBe(v);
    for (const l of lines) {
      const [f, u, w] = l.split(' ').map(Number);
      expect(f).toBeGreaterThanOrEqual(0);
      expect(u).toBeGreaterThanOrEqual(0);
      expect(w).toBeLessThanOrEqual(1);
    }
  });

  it('puts every vertex on the exact Catmull-Clark limit: --params read back by `subdiv --points`', async () => {
    const out = join(dir, 'creature.obj');
    const params = join(dir, 'creature.txt');
    const r = await run('public/models/creature.obj', '--adaptive', '--lod', '2', '--out', out, '--params', params);
    expect(r.status, r.stderr).toBe(0);
    const gpu = readFileSync(out, 'utf8')
      .split('\n')
      .filter((l) => l.startsWith('v '))
      .map((l) => l.slice(2).split(' ').map(Number));
    const ref = spawnSync(
      process.execPath,
      ['node_modules/tsx/dist/cli.mjs', 'scripts/subdiv-cli.ts', '--points', params, 'public/models/creature.obj'],
      { encoding: 'utf8', timeout: 120_000, maxBuffer: 1 << 28 },
    );
    expect(ref.status, ref.stderr).toBe(0);
    const points = JSON.parse(ref.stdout).points as { P: number[] }[];
    expect(points.length).toBe(gpu.length);
    const lo = [0, 1, 2].map((c) => Math.min(...gpu.map((p) => p[c])));
    const hi = [0, 1, 2].map((c) => Math.max(...gpu.map((p) => p[c])));
    const diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    let worst = 0;
    points.forEach((p, i) => {
      worst = Math.max(worst, Math.hypot(p.P[0] - gpu[i][0], p.P[1] - gpu[i][1], p.P[2] - gpu[i][2]) / diagonal);
    });
    console.log(`tessellate --surface catmull-clark vs subdiv --points: max ${worst.toExponential(2)} of the diagonal`);
    expect(worst).toBeLessThan(1e-5);
  });

  it('--fixed reaches the top factor, and --capacity N holds the output: the factors scaled, said on stderr and in --stats', async () => {
    // Factor 128 on the torus would be millions of triangles; 5,000 makes the budget scale it.
    const r = await run('public/models/torus.obj', '--fixed', '128', '--surface', 'phong', '--capacity', '5000', '--stats');
    expect(r.status, r.stderr).toBe(0);
    const s = statsLine(r.stdout);
    expect(s.capacity).toBe(5000);
    expect(s.triangles).toBeLessThanOrEqual(5000);
    expect(s.vertices).toBeLessThanOrEqual(5000);
    expect(s.budgetScale).toBeLessThan(1);
    expect(r.stderr).toContain('its factors were scaled by');
    for (const bad of ['0', '1.5', '1e12']) {
      const b = await run('public/models/torus.obj', '--fixed', '4', '--capacity', bad, '--stats');
      expect(b.status).toBe(2);
      expect(b.stderr).toContain('--capacity: output vertices and triangles');
    }
  });

  it("--stats prints one JSON line whose counts are the cage's and the written OBJ's", async () => {
    const model = 'public/models/creased-box.obj';
    const out = join(dir, 'stats.obj');
    // A real process: the claim is what reaches its stdout (one JSON line) and its exit status.
    const r = spawnCli(model, '--fixed', '4', '--stats', '--out', out);
    expect(r.status, r.stderr).toBe(0);
    const lines = r.stdout
      .trim()
      .split('\n')
      .filter((l) => l.startsWith('{'));
    expect(lines.length).toBe(1);
    const s = JSON.parse(lines[0]);
    const cageFaces = readFileSync(model, 'utf8')
      .split('\n')
      .filter((l) => l.startsWith('f ')).length;
    const obj = readFileSync(out, 'utf8').split('\n');
    expect(s.faces).toBe(cageFaces);
    expect(s.vertices).toBe(obj.filter((l) => l.startsWith('v ')).length);
    expect(s.triangles).toBe(obj.filter((l) => l.startsWith('f ')).length);
    expect(s.triangles).toBe(2 * cageFaces * 16); // all quads → 2 triangles → 16 each at factor 4
    expect(s.cpuPrepMs).toBeGreaterThan(0);
    expect(s.gpuBytes).toBeGreaterThan(0);
    expect(s.gpuBytes % 4).toBe(0);
    // Dawn offers timestamp queries on Vulkan adapters, SwiftShader included.
    expect(s.subdivisionMs).toBeGreaterThan(0);
    expect(s.tessellationMs).toBeGreaterThan(0);
  });

  const objOf = (path: string) => {
    const lines = readFileSync(path, 'utf8').split('\n');
    const v = lines.filter((l) => l.startsWith('v ')).map((l) => l.slice(2).split(' ').map(Number));
    const f = lines
      .filter((l) => l.startsWith('f '))
      .map((l) =>
        l
          .slice(2)
          .split(' ')
          .map((x) => Number(x.split('//')[0]) - 1),
      );
    return { v, f };
  };
  const closedEverywhere = (f: number[][]) => {
    const directed = new Set<string>();
    for (const t of f) for (let i = 0; i < 3; i++) directed.add(`${t[i]},${t[(i + 1) % 3]}`);
    let open = 0;
    for (const e of directed) {
      const [a, b] = e.split(',');
      if (!directed.has(`${b},${a}`)) open++;
    }
    return { open, directed: directed.size };
  };

  it('--tessellator instanced --level 4: the compute tessellator’s points at --fixed 4 (Phong), welded and closed', async () => {
    const inst = join(dir, 'torus-inst.obj');
    const comp = join(dir, 'torus-comp.obj');
    const params = join(dir, 'torus-inst.txt');
    let r = await run(
      'public/models/torus.obj',
      '--tessellator',
      'instanced',
      '--level',
      '4',
      '--out',
      inst,
      '--params',
      params,
      '--stats',
    );
    expect(r.status, r.stderr).toBe(0);
    const stats = statsLine(r.stdout);
    r = await run('public/models/torus.obj', '--fixed', '4', '--surface', 'phong', '--out', comp);
    expect(r.status, r.stderr).toBe(0);
    const a = objOf(inst),
      b = objOf(comp);
    expect(stats.tessellator).toBe('instanced');
    expect(stats.vertices).toBe(a.v.length);
    expect(stats.triangles).toBe(a.f.length);
    // Matched settings, matched meshes: the same counts and the same points (f32 apart).
    expect(a.v.length).toBe(b.v.length);
    expect(a.f.length).toBe(b.f.length);
    const lo = [0, 1, 2].map((c) => Math.min(...b.v.map((p) => p[c])));
    const hi = [0, 1, 2].map((c) => Math.max(...b.v.map((p) => p[c])));
    const diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    let worst = 0;
    for (const p of a.v) {
      let best = Infinity;
      for (const q of b.v) best = Math.min(best, Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
      worst = Math.max(worst, best / diagonal);
    }
    console.log(`instanced level 4 vs compute fixed 4 (Phong, torus): farthest point ${worst.toExponential(2)} of the diagonal`);
    expect(worst).toBeLessThan(1e-6);
    expect(closedEverywhere(a.f).open).toBe(0);
    expect(readFileSync(params, 'utf8').trim().split('\n').length).toBe(a.v.length);
  });

  it('--tessellator instanced --adaptive: mixed levels, the weld closes every shared edge (no T-junction, no hole)', async () => {
    const out = join(dir, 'creature-inst.obj');
    const params = join(dir, 'creature-inst.json');
    const r = await run(
      'public/models/creature.obj',
      '--tessellator',
      'instanced',
      '--adaptive',
      '--lod',
      '2',
      '--out',
      out,
      '--params',
      params,
      '--stats',
    );
    expect(r.status, r.stderr).toBe(0);
    const stats = statsLine(r.stdout);
    const { v, f } = objOf(out);
    expect(stats.vertices).toBe(v.length);
    expect(stats.triangles).toBe(f.length);
    expect(stats.drawnTriangles).toBeGreaterThan(stats.triangles); // mixed levels: the snap collapsed some
    expect(stats.weldGap).toBeLessThan(1e-6);
    // The creature is closed: every directed edge has its twin, so the fine sides' snapped
    // boundaries meet the coarse sides' segments exactly.
    const c = closedEverywhere(f);
    console.log(
      `instanced adaptive creature: ${v.length} vertices, ${f.length} triangles, ${c.open} unpaired edges, weld gap ${stats.weldGap}`,
    );
    expect(c.open).toBe(0);
    const p = JSON.parse(readFileSync(params, 'utf8'));
    expect(p.vertexCount).toBe(v.length);
  });

  it('--tessellator instanced --surface bezier-acc: the ACC surface, welded closed across mixed levels; an n-gon cage refined once, said', async () => {
    const out = join(dir, 'creature-acc.obj');
    const r = await run(
      'public/models/creature.obj',
      '--tessellator',
      'instanced',
      '--surface',
      'bezier-acc',
      '--adaptive',
      '--out',
      out,
      '--stats',
    );
    expect(r.status, r.stderr).toBe(0);
    const stats = statsLine(r.stdout);
    const { v, f } = objOf(out);
    expect(stats.vertices).toBe(v.length);
    expect(stats.triangles).toBe(f.length);
    expect(readFileSync(out, 'utf8')).toContain('bezier-acc surface');
    // Two sides of an edge evaluate different ACC patches in f32: the gap the weld closes.
    console.log(`instanced bezier-acc creature: ${f.length} triangles, weld gap ${stats.weldGap} of the size`);
    expect(stats.weldGap).toBeLessThan(1e-6);
    expect(closedEverywhere(f).open).toBe(0);
    const ico = await run('public/models/icosphere.obj', '--tessellator', 'instanced', '--surface', 'pm-acc', '--level', '2', '--stats');
    expect(ico.status, ico.stderr).toBe(0);
    expect(ico.stderr).toMatch(/Pm ACC: one Catmull-Clark step first \(the cage has n-gons\): 230 patches/);
    expect(statsLine(ico.stdout).patches).toBe(230);
  });

  it('--surface gregory-acc on the compute tessellator: a closed OBJ; the gear (n-gons, σ = 2 creases) refined twice, said', async () => {
    const out = join(dir, 'creature-gregory.obj');
    const r = await run('public/models/creature.obj', '--fixed', '3', '--surface', 'gregory-acc', '--out', out);
    expect(r.status, r.stderr).toBe(0);
    expect(closedEverywhere(objOf(out).f).open).toBe(0);
    const gearOut = join(dir, 'gear-pm.obj');
    const gear = await run('public/models/gear.obj', '--fixed', '3', '--surface', 'pm-acc', '--out', gearOut);
    expect(gear.status, gear.stderr).toBe(0);
    expect(gear.stderr).toMatch(/2 Catmull-Clark steps first \(the cage has n-gons; semi-sharp creases up to 2 decay\)/);
    // (Open along its infinitely sharp creases, where each side has its own normals.)
    expect(objOf(gearOut).f.length).toBeGreaterThan(1000);
  });

  it('--demo-view --limit-px: the demo’s first view (adaptive, flat baseline) within a pixel of the exact limit', async () => {
    const r = await run('public/models/creature.obj', '--adaptive', '--flat-baseline', '--demo-view', '--limit-px', '--stats');
    expect(r.status, r.stderr).toBe(0);
    const s = JSON.parse(r.stdout.trim().split('\n').pop()!);
    expect(s.limitPx.vertices).toBeGreaterThan(500);
    expect(s.limitPx.max).toBeLessThanOrEqual(1.001);
    // Between the vertices (NOT MET: 1 px; tests/gpu/tess/limit-distance.node.test.ts holds the ratchet).
    expect(s.displayedPx.samples).toBeGreaterThan(2 * s.limitPx.vertices);
    expect(s.displayedPx.max).toBeGreaterThan(0);
  });

  it('rejects bad input with a message and exit code 2', async () => {
    const bad = join(dir, 'bad.obj');
    writeFileSync(bad, 'v 0 0 0\nv 1 0 0\nf 1 2 7\n');
    for (const args of [
      ['public/models/torus.obj', '--out', join(dir, 'x.obj')],
      ['public/models/torus.obj', '--fixed', '0', '--out', join(dir, 'x.obj')],
      ['missing.obj', '--fixed', '3', '--out', join(dir, 'x.obj')],
      [bad, '--fixed', '3', '--out', join(dir, 'x.obj')],
      ['public/models/torus.obj', '--adaptive', '--eye', '1,2', '--out', join(dir, 'x.obj')],
      ['public/models/torus.obj', '--fixed', '2', '--surface', 'loop', '--out', join(dir, 'x.obj')],
      ['public/models/torus.obj', '--fixed', '2', '--surface', 'phong', '--flat-baseline', '--out', join(dir, 'x.obj')],
      ['public/models/torus.obj', '--fixed', '2'], // neither --out nor --stats
      ['public/models/torus.obj', '--tessellator', 'instanced', '--fixed', '4', '--out', join(dir, 'x.obj')],
      ['public/models/torus.obj', '--tessellator', 'instanced', '--level', '3', '--out', join(dir, 'x.obj')],
      ['public/models/torus.obj', '--tessellator', 'instanced', '--level', '4', '--surface', 'loop', '--out', join(dir, 'x.obj')],
      ['public/models/torus.obj', '--level', '4', '--out', join(dir, 'x.obj')],
      ['public/models/torus.obj', '--tessellator', 'hull', '--level', '4', '--out', join(dir, 'x.obj')],
      ['public/models/torus.obj', '--fixed', '2', '--surface', 'phong', '--limit-px', '--stats'],
      ['public/models/torus.obj', '--adaptive', '--demo-view', '--eye', '1,2,3', '--stats'],
    ]) {
      const r = await run(...args);
      expect(r.status, args.join(' ')).toBe(2);
      expect(r.stderr).toMatch(/tessellate: /);
    }
    // main's 2 is the process's exit status (scripts/vite-run.mjs), shown once by a real process.
    const p = spawnCli('public/models/torus.obj', '--fixed', '0', '--out', join(dir, 'x.obj'));
    expect(p.status).toBe(2);
    expect(p.stderr).toMatch(/tessellate: --fixed/);
  });

  it('--displacement map.png --scale S: every vertex on the f64 displaced limit at its --params; bad maps and cages without uvs refused', async () => {
    const model = 'public/models/brick-box.obj';
    const png = 'public/models/brick-box-height.png';
    const out = join(dir, 'displaced.obj');
    const params = join(dir, 'displaced.json');
    const r = await run(
      model,
      '--fixed',
      '4',
      '--displacement',
      png,
      '--scale',
      '0.06',
      '--wrap',
      'clamp',
      '--out',
      out,
      '--params',
      params,
    );
    expect(r.status, r.stderr).toBe(0);
    const v = objOf(out).v;
    const p = JSON.parse(readFileSync(params, 'utf8')).params as number[][];
    expect(p.length).toBe(v.length);
    const cage = loadCage(readFileSync(model, 'utf8')).cage;
    const ref = new DisplacedSurface(
      new Surface(cage, undefined, { ...DEFAULT_OPTIONS, ...cage.fileOptions }),
      decodeHeightPng(readFileSync(png)),
      {
        scale: 0.06,
        midLevel: 0.5,
        wrap: 'clamp',
      },
    );
    const lo = [0, 1, 2].map((c) => Math.min(...v.map((q) => q[c])));
    const hi = [0, 1, 2].map((c) => Math.max(...v.map((q) => q[c])));
    const diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    let worst = 0;
    let moved = 0;
    p.forEach((x, i) => {
      const d = ref.at(x.length === 3 ? { face: x[0], u: x[1], v: x[2] } : { face: x[0], k: x[1], s: x[2], t: x[3] });
      if (Math.abs(d.h) > 1e-3) moved++;
      // Where the limit has no tangent plane (the box's corners) the direction is a convention:
      // held to the distance |h| (tests/gpu/tess/displacement.node.test.ts).
      const e = d.base.normalDefined
        ? Math.hypot(d.P[0] - v[i][0], d.P[1] - v[i][1], d.P[2] - v[i][2])
        : Math.abs(Math.hypot(d.base.P[0] - v[i][0], d.base.P[1] - v[i][1], d.base.P[2] - v[i][2]) - Math.abs(d.h));
      worst = Math.max(worst, e / diagonal);
    });
    console.log(
      `tessellate --displacement vs the f64 reference: max ${worst.toExponential(2)} of the diagonal, ${moved} of ${v.length} moved`,
    );
    expect(worst).toBeLessThan(1e-5);
    expect(moved).toBeGreaterThan(v.length / 4);

    const bad = join(dir, 'bad.png');
    writeFileSync(bad, 'not a png at all');
    const b = await run(model, '--fixed', '2', '--displacement', bad, '--scale', '1', '--stats');
    expect(b.status).toBe(2);
    expect(b.stderr).toMatch(/not a PNG/);
    const n = await run('public/models/creature.obj', '--fixed', '2', '--displacement', png, '--scale', '1', '--stats');
    expect(n.status).toBe(2);
    expect(n.stderr).toMatch(/texture coordinate|UVs/);
    const u = await run(model, '--fixed', '2', '--displacement', png, '--stats');
    expect(u.status).toBe(2);
    expect(u.stderr).toMatch(/needs --scale/);
  });
});
