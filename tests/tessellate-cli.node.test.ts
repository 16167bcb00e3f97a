/** The headless CLI end to end: a real process, Dawn in Node (SwiftShader here). */
import { describe, it, expect } from 'vitest';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const dir = mkdtempSync(join(tmpdir(), 'tessellab-cli-'));
const run = (...args: string[]) =>
  spawnSync(process.execPath, ['scripts/vite-run.mjs', 'scripts/tessellate-cli.ts', ...args], { encoding: 'utf8', timeout: 120_000 });

describe('npm run tessellate', () => {
  it('writes a watertight OBJ and one parameter per vertex', () => {
    const out = join(dir, 'torus.obj');
    const params = join(dir, 'torus.txt');
    const r = run('public/models/torus.obj', '--fixed', '4', '--surface', 'phong', '--out', out, '--params', params);
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

  it('puts every vertex on the exact Catmull-Clark limit: --params read back by `subdiv --points`', () => {
    const out = join(dir, 'creature.obj');
    const params = join(dir, 'creature.txt');
    const r = run('public/models/creature.obj', '--adaptive', '--lod', '2', '--out', out, '--params', params);
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

  it("--stats prints one JSON line whose counts are the cage's and the written OBJ's", () => {
    const model = 'public/models/creased-box.obj';
    const out = join(dir, 'stats.obj');
    const r = run(model, '--fixed', '4', '--stats', '--out', out);
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

  it('rejects bad input with a message and exit code 2', () => {
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
    ]) {
      const r = run(...args);
      expect(r.status, args.join(' ')).toBe(2);
      expect(r.stderr).toMatch(/tessellate: /);
    }
  });
});
