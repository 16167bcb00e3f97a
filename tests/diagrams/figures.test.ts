import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { clampedTriangle } from '../../src/pattern/clamped.ts';
import { d3d11TriCounts } from '../../src/pattern/d3d11.ts';
import { line } from '../../src/pattern/line.ts';
import { FIGURES } from '../../src/diagrams/figures.ts';
import { computeTrace, lineFigure } from '../../src/diagrams/line-figure.ts';
import { MIN_TEXT_PX } from '../../src/diagrams/model.ts';
import { parseParams, type LineParams, type TriParams } from '../../src/diagrams/params.ts';
import { PALETTES, sceneToSvg, type Scene } from '../../src/diagrams/scene.ts';
import { period } from '../../src/diagrams/timeline.ts';
import { framePattern, triFactorsAt, triangleFigure } from '../../src/diagrams/triangle-figure.ts';
import type { D3D11Partitioning } from '../../src/pattern/types.ts';

const preset = <K extends 'line' | 'triangle'>(kind: K, id: string) => parseParams(kind, `fig=${id}`).params;

function coordinatesFinite(s: Scene): boolean {
  for (const sh of s.shapes) {
    const nums = sh.kind === 'path' ? sh.polys.flat() : sh.kind === 'dots' ? sh.pts : [sh.x, sh.y];
    if (!nums.every(Number.isFinite)) return false;
  }
  return true;
}

describe('every figure', () => {
  it('draws finite shapes at several times, with counts for each mode', () => {
    for (const f of FIGURES) {
      const p = parseParams(f.kind, `fig=${f.id}`).params;
      for (const t of [0, p.start, period(p.timing) * 0.37, period(p.timing) * 0.81]) {
        const fr = p.kind === 'line' ? lineFigure(p, t) : triangleFigure(p, t);
        expect(coordinatesFinite(fr.scene), `${f.id} at ${t}`).toBe(true);
        expect(
          fr.counts.map((c) => c.mode),
          f.id,
        ).toEqual(p.modes);
        expect(fr.scene.width).toBeGreaterThan(100);
        expect(fr.scene.height).toBeGreaterThan(100);
      }
    }
  });

  it('is a pure function of (parameters, time)', () => {
    for (const f of FIGURES) {
      const p = parseParams(f.kind, `fig=${f.id}`).params;
      const draw = () => sceneToSvg((p.kind === 'line' ? lineFigure(p, 1.7) : triangleFigure(p, 1.7)).scene, PALETTES.light);
      expect(draw(), f.id).toBe(draw());
    }
  });
});

describe('the compact (phone) layout', () => {
  const draw = (f: (typeof FIGURES)[number], t: number, width?: number) => {
    const p = parseParams(f.kind, `fig=${f.id}`).params;
    return p.kind === 'line' ? lineFigure(p, t, f.title, width) : triangleFigure(p, t, f.title, width);
  };

  it('is as wide as the space it is given below 600 px, with no type under 11 px and the same counts', () => {
    for (const f of FIGURES) {
      const p = parseParams(f.kind, `fig=${f.id}`).params;
      for (const width of [280, 334.6, 390, 599]) {
        for (const t of [p.start, period(p.timing) * 0.37]) {
          const fr = draw(f, t, width);
          const where = `${f.id} at ${width} px, t ${t}`;
          expect(fr.scene.width, where).toBe(Math.floor(width));
          expect(coordinatesFinite(fr.scene), where).toBe(true);
          const sizes = fr.scene.shapes.flatMap((s) => (s.kind === 'text' ? [s.size] : []));
          expect(sizes.length, where).toBeGreaterThan(0);
          expect(Math.min(...sizes), where).toBeGreaterThanOrEqual(MIN_TEXT_PX);
          expect(fr.counts, where).toEqual(draw(f, t).counts);
        }
      }
    }
  });

  it('keeps the shapes inside the scene (the labels: their anchors)', () => {
    for (const f of FIGURES) {
      const fr = draw(f, parseParams(f.kind, `fig=${f.id}`).params.start, 334);
      const { width, height } = fr.scene;
      for (const s of fr.scene.shapes) {
        const xs =
          s.kind === 'path'
            ? s.polys.flatMap((q) => q.filter((_, i) => i % 2 === 0))
            : s.kind === 'dots'
              ? s.pts.filter((_, i) => i % 2 === 0)
              : [s.x];
        const ys =
          s.kind === 'path'
            ? s.polys.flatMap((q) => q.filter((_, i) => i % 2 === 1))
            : s.kind === 'dots'
              ? s.pts.filter((_, i) => i % 2 === 1)
              : [s.y];
        expect(Math.min(...xs), f.id).toBeGreaterThanOrEqual(0);
        expect(Math.max(...xs), f.id).toBeLessThanOrEqual(width);
        expect(Math.min(...ys), f.id).toBeGreaterThanOrEqual(0);
        expect(Math.max(...ys), f.id).toBeLessThanOrEqual(height);
      }
    }
  });

  it('is taller than the wide layout scaled to the same width (it does not just shrink)', () => {
    for (const f of FIGURES) {
      const t = parseParams(f.kind, `fig=${f.id}`).params.start;
      const wide = draw(f, t).scene;
      const narrow = draw(f, t, 334).scene;
      expect(narrow.height / narrow.width, f.id).toBeGreaterThan(wide.height / wide.width);
    }
  });

  it('is not used at 600 px and over, nor without a width', () => {
    const f = FIGURES[0];
    expect(draw(f, 1, 600).scene).toEqual(draw(f, 1).scene);
    expect(draw(f, 1, 1200).scene.width).toBe(760);
  });
});

describe('triangle counts are the pattern code’s', () => {
  it('at any factors, for every mode (full stage)', () => {
    fc.assert(
      fc.property(
        fc.tuple(
          fc.double({ min: 1, max: 20, noNaN: true }),
          fc.double({ min: 1, max: 20, noNaN: true }),
          fc.double({ min: 1, max: 20, noNaN: true }),
        ),
        fc.double({ min: 1, max: 20, noNaN: true }),
        (edges, inside) => {
          const q = `mode=clamped,integer,pow2,fractional_odd,fractional_even&f0=${edges[0]}&f1=${edges[1]}&f2=${edges[2]}&inside=${inside}`;
          const p = parseParams('triangle', q).params;
          const fr = triangleFigure(p, 0);
          const cl = clampedTriangle(edges);
          expect(fr.counts[0]).toMatchObject({ vertices: cl.vertexCount, triangles: cl.triangleCount });
          fr.counts.slice(1).forEach((c) => {
            const ref = d3d11TriCounts(c.mode as D3D11Partitioning, edges, inside);
            expect(c).toMatchObject({ vertices: ref.vertexCount, triangles: ref.triangleCount });
          });
        },
      ),
      { numRuns: 60 },
    );
  });

  it('384 against 256 at 16', () => {
    const fr = triangleFigure(preset('triangle', 'inefficient-16'), 0);
    expect(fr.counts.map((c) => c.triangles)).toEqual([384, 256]);
    expect(fr.counts.map((c) => c.vertices)).toEqual([217, 153]);
    expect(fr.scene.desc).toMatch(/384 triangles/);
  });

  it('6 against 1 at the minimum', () => {
    const fr = triangleFigure(preset('triangle', 'minimum-triangles'), 0);
    expect(fr.counts.map((c) => c.triangles)).toEqual([6, 1, 1]);
  });

  it('the low-factor figure starts from one triangle and stays a clean tiling', () => {
    const p = preset('triangle', 'low-factors') as TriParams;
    expect(triangleFigure(p, 0).counts[0].triangles).toBe(1);
    for (let t = 0; t <= p.timing.duration; t += 0.25) {
      const fr = triangleFigure(p, t);
      expect(fr.counts[0].degenerate, `t=${t}`).toBe(0);
    }
  });

  it('draws D3D11 edge factor i on the same screen edge as the clamped factor i', () => {
    // Edge 0 of both patterns must hold exactly the vertices with frame weight w_C = 0 (bottom).
    const fc3 = { edges: [3, 5, 9] as [number, number, number], inside: 4 };
    for (const mode of ['clamped', 'integer', 'fractional_odd'] as const) {
      const pat = framePattern(mode, fc3, [false, false, false], 64);
      let bottom = 0;
      for (let v = 0; v < pat.vertexCount; v++) if (pat.bary[3 * v + 2] === 0) bottom++;
      const expected = mode === 'clamped' ? line('hable', 3).x.length : mode === 'integer' ? 4 : line('fractional_odd', 3).x.length;
      expect(bottom, mode).toBe(expected);
    }
  });

  it('factor tracks animate as given', () => {
    const p = preset('triangle', 'edges-independent') as TriParams;
    const D = p.timing.duration;
    expect(triFactorsAt(p, 0).edges).toEqual([8, 8, 8]);
    expect(triFactorsAt(p, D / 6).edges).toEqual([1, 8, 8]);
    expect(triFactorsAt(p, D / 2).edges).toEqual([8, 1, 8]);
    expect(triFactorsAt(p, (5 * D) / 6).edges[2]).toBeCloseTo(1, 9);
  });
});

describe('line figures', () => {
  it('draw exactly the moving points in red', () => {
    const p = preset('line', 'all-lines') as LineParams;
    for (const t of [0.5, 2, 3.5, 7]) {
      const fr = lineFigure(p, t);
      const f = Number(fr.factors[0].value);
      const red = fr.scene.shapes
        .filter((s) => s.kind === 'dots' && s.fill === 'accent')
        .reduce((n, s) => n + (s.kind === 'dots' ? s.pts.length / 2 : 0), 0);
      const expected = p.modes.reduce((n, m) => n + line(m, f).moving.filter(Boolean).length, 0);
      expect(red, `t=${t}`).toBe(expected);
      fr.counts.forEach((c) => expect(c.vertices).toBe(line(c.mode as never, f).x.length));
    }
  });

  it('show the factor 10.3 of the even figure, with 11 segments', () => {
    const fr = lineFigure(preset('line', 'even-10.3') as LineParams, (preset('line', 'even-10.3') as LineParams).start);
    expect(fr.factors[0].value).toBeCloseTo(10.3, 9);
    expect(fr.counts[0].triangles).toBe(11);
  });

  it('step through whole factors when snapping', () => {
    const p = preset('line', 'one-at-a-time') as LineParams;
    for (let t = 0; t < period(p.timing); t += 0.13) expect(Number.isInteger(lineFigure(p, t).factors[0].value)).toBe(true);
  });

  it('D3D11 does not converge: the followed point goes 0.5 → 2/3 → 0.5 in every octave', () => {
    const tr = computeTrace('fractional_even', 2, 32, true, 64, true, 0.5, 960);
    const at = (f: number) => {
      const pts = tr.followed as number[];
      let best = 0;
      for (let j = 0; j < pts.length; j += 2) if (Math.abs(pts[j + 1] - f) < Math.abs(pts[best + 1] - f)) best = j;
      return pts[best];
    };
    for (const N of [4, 8, 16]) {
      expect(at(N), `f=${N}`).toBeCloseTo(0.5, 2);
      expect(at(1.5 * N), `f=${1.5 * N}`).toBeCloseTo(2 / 3, 2);
    }
    expect(at(32)).toBeCloseTo(0.5, 6);
  });
});

describe('SVG', () => {
  it('is one escaped, standalone document', () => {
    const p = preset('triangle', 'gap-matching');
    const svg = sceneToSvg(triangleFigure(p, 1, 'A <b> & "c"').scene, PALETTES.dark);
    expect(svg.startsWith('<svg xmlns="http://www.w3.org/2000/svg"')).toBe(true);
    expect(svg.endsWith('</svg>')).toBe(true);
    expect(svg).toContain('<title>A &lt;b&gt; &amp; &quot;c&quot;</title>');
    expect(svg).toContain(PALETTES.dark.bg);
    expect(svg).not.toMatch(/NaN|undefined/);
  });
});
