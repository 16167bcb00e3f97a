import { describe, it, expect } from 'vitest';
import { runPatternCli } from '../../src/pattern/cli.ts';

const noFiles = (path: string): string => {
  throw new Error(`ENOENT: ${path}`);
};
const run = (args: string, files: Record<string, string> = {}) =>
  runPatternCli(args.split(' '), (p) => (p in files ? files[p] : noFiles(p)));
const json = (args: string) => {
  const r = run(args);
  expect(r.code).toBe(0);
  return JSON.parse(r.stdout);
};

describe('pattern CLI', () => {
  it('prints a line as JSON with numbers in [0, 1]', () => {
    const o = json('line --mode hable --factor 16 --json');
    expect(o.vertexCount).toBe(17);
    expect(o.points[1]).toBe(1 / 16);
    expect(o.triangles).toEqual([]);
    expect(json('line --mode hable --factor 16 --json --fixed').points[1]).toBe(4096);
  });

  it('prints the reference counts for triangles', () => {
    expect(json('tri --mode fractional_even --factors 16,16,16 --inside 16 --json')).toMatchObject({
      vertexCount: 217,
      triangleCount: 384,
    });
    expect(json('tri --mode clamped --factors 16,16,16 --json')).toMatchObject({ vertexCount: 153, triangleCount: 256 });
    const one = json('tri --mode clamped --factors 1,1,1 --json');
    expect(one.triangles.length).toBe(1);
    expect(one.triangles[0].map((i: number) => one.points[i])).toEqual([
      [1, 0, 0],
      [0, 1, 0],
      [0, 0, 1],
    ]);
    const o = json('tri --mode clamped --factors 3.5,7,12 --reverse 0,1,0 --json');
    expect(o.points.length).toBe(o.vertexCount);
    for (const p of o.points) expect(p[0] + p[1] + p[2]).toBeCloseTo(1, 12);
  });

  it('sweeps a line, one JSON object per factor', () => {
    const r = run('line --mode hable --sweep 1,2,0.25');
    const rows = r.stdout
      .trim()
      .split('\n')
      .map((l) => JSON.parse(l));
    expect(rows.map((o) => o.factor)).toEqual([1, 1.25, 1.5, 1.75, 2]);
    expect(rows.map((o) => o.vertexCount)).toEqual([2, 4, 4, 4, 3]);
  });

  it('reads factor sets from a file, with inside factors, reverse flags and comments', () => {
    const r = run('tri --mode clamped --factors-file f.txt', { 'f.txt': '# sets\n1,1,1\n\n4,5,6;1,0,1\n' });
    expect(r.code).toBe(0);
    const rows = r.stdout
      .trim()
      .split('\n')
      .map((l) => JSON.parse(l));
    expect(rows.length).toBe(2);
    expect(rows[1].reverse).toEqual([1, 0, 1]);
    const d = run('tri --mode integer --factors-file f.txt', { 'f.txt': '2,3,4,5\n' });
    expect(JSON.parse(d.stdout)).toMatchObject({ inside: 5, vertexCount: 21, triangleCount: 31 });
  });

  it('rejects bad arguments with a message and exit code 2', () => {
    const bad = [
      '',
      'square --mode hable',
      'line --factor 3',
      'line --mode nope --factor 3',
      'line --mode hable',
      'line --mode hable --factor abc',
      'line --mode hable --factor -1',
      'line --mode hable --factor 3 --sweep 1,2,0.1',
      'line --mode hable --sweep 1,2,0',
      'line --mode hable --factor 3 --max-factor 48',
      'tri --mode clamped --factors 1,2',
      'tri --mode clamped --factors 1,2,3 --inside 4',
      'tri --mode integer --factors 1,2,3 --reverse 0,1,0',
      'tri --mode clamped --factors 1,2,3 --reverse 0,2,0',
      'tri --mode clamped --factors-file missing.txt',
      'tri --mode clamped --factors 1,2,3 --bogus',
    ];
    for (const args of bad) {
      const r = runPatternCli(args ? args.split(' ') : [], noFiles);
      expect(r.code, args).toBe(2);
      expect(r.stderr, args).toMatch(/^pattern: .+/);
      expect(r.stdout).toBe('');
    }
    const r = run('tri --mode clamped --factors-file f.txt', { 'f.txt': '1,1,1\n1,x,1\n' });
    expect(r.code).toBe(2);
    expect(r.stderr).toMatch(/f\.txt:2/);
  });
});
