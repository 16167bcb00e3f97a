import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { FIGURES } from '../../src/diagrams/figures.ts';
import { formatParams, knownKeys, parseParams, toQuery, type LineParams, type TriParams } from '../../src/diagrams/params.ts';

const line = (q: string) => parseParams('line', q);
const tri = (q: string) => parseParams('triangle', q);
const texts = (m: { text: string }[]) => m.map((x) => x.text).join('\n');

describe('line parameters', () => {
  it('have defaults and no messages when empty', () => {
    const { params, messages } = line('');
    expect(messages).toEqual([]);
    expect(params.modes).toEqual(['hable']);
    expect(params.factor).toEqual([1, 16]);
    expect(params.t).toBeNull();
    expect(params.autoplay).toBe(true);
    expect(params.chrome).toBe(true);
  });

  it("read the issue's example", () => {
    const { params, messages } = line('?mode=hable&from=1&to=16&autoplay=1');
    expect(messages).toEqual([]);
    expect(params.modes).toEqual(['hable']);
    expect(params.factor).toEqual([1, 16]);
  });

  it('freeze at t and hide the chrome', () => {
    const { params, messages } = line('t=2.5&chrome=0&autoplay=0');
    expect(messages).toEqual([]);
    expect(params.t).toBe(2.5);
    expect(params.chrome).toBe(false);
    expect(params.autoplay).toBe(false);
  });

  it('stack several modes, accepting - for _ and any case', () => {
    const { params, messages } = line('MODE=Fractional-Even,hable,one_at_a_time,hable');
    expect(messages).toEqual([]);
    expect(params.modes).toEqual(['fractional_even', 'hable', 'one-at-a-time']);
  });

  it('read a static factor and key values', () => {
    expect(line('factor=10.3').params.factor).toEqual([10.3]);
    expect(line('factor=8..1..8').params.factor).toEqual([8, 1, 8]);
  });

  it('explain a bad mode and keep the good ones', () => {
    const { params, messages } = line('mode=hable,nope');
    expect(params.modes).toEqual(['hable']);
    expect(texts(messages)).toMatch(/unknown mode "nope"/);
    expect(texts(messages)).toMatch(/fractional_even/); // lists the valid ones
  });

  it('fall back to the default mode when none is valid', () => {
    const { params, messages } = line('mode=foo,bar');
    expect(params.modes).toEqual(['hable']);
    expect(messages.length).toBeGreaterThanOrEqual(2);
  });

  it('explain numbers that are not numbers and use the default', () => {
    const { params, messages } = line('from=abc&to=8');
    expect(params.factor).toEqual([1, 8]);
    expect(texts(messages)).toMatch(/from="abc" is not a factor/);
  });

  it('clamp factors out of range, with a message', () => {
    const { params, messages } = line('from=0.5&to=500');
    expect(params.factor).toEqual([1, 64]);
    expect(messages).toHaveLength(2);
    expect(texts(messages)).toMatch(/outside \[1, 64\]; using 64/);
  });

  it('explain bad key values', () => {
    const bad = line('factor=1..x');
    expect(bad.params.factor).toEqual([1, 16]);
    expect(texts(bad.messages)).toMatch(/not a factor/);
    const many = line(`factor=${Array.from({ length: 20 }, (_, i) => i + 1).join('..')}`);
    expect(texts(many.messages)).toMatch(/at most 16/);
    const clamp = line('factor=0..100');
    expect(clamp.params.factor).toEqual([1, 64]);
    expect(clamp.messages).toHaveLength(1);
  });

  it('say when both factor and from/to are given', () => {
    expect(texts(line('factor=3&from=1').messages)).toMatch(/either factor or from\/to/);
  });

  it('check maxFactor (case-insensitive key)', () => {
    expect(line('maxFactor=128&to=100').params.factor).toEqual([1, 100]);
    const bad = line('maxfactor=100');
    expect(bad.params.maxFactor).toBe(64);
    expect(texts(bad.messages)).toMatch(/power of two/);
  });

  it('explain bad booleans, enums, times and unknown keys', () => {
    const { params, messages } = line('autoplay=maybe&view=side&t=-3&speed=0&colour=red&utm_source=blog');
    expect(params.autoplay).toBe(true);
    expect(params.view).toBe('line');
    expect(params.t).toBe(0);
    expect(params.speed).toBe(0.05);
    const all = texts(messages);
    expect(all).toMatch(/autoplay="maybe" should be 1 or 0/);
    expect(all).toMatch(/view="side" is not one of line, trace/);
    expect(all).toMatch(/t=-3 is outside/);
    expect(all).toMatch(/unknown parameter "colour"/);
    expect(all).not.toMatch(/utm_source/);
  });

  it('read marks and a tracked point', () => {
    const { params, messages } = line('view=trace&half=1&track=0.5&marks=0.5,0.6667,7');
    expect(params.view).toBe('trace');
    expect(params.half).toBe(true);
    expect(params.track).toBe(0.5);
    expect(params.marks).toEqual([0.5, 0.6667]);
    expect(texts(messages)).toMatch(/marks: "7"/);
  });
});

describe('triangle parameters', () => {
  it('have defaults', () => {
    const { params, messages } = tri('');
    expect(messages).toEqual([]);
    expect(params.modes).toEqual(['clamped']);
    expect(params.factors).toEqual([
      [1, 8],
      [1, 8],
      [1, 8],
    ]);
    expect(params.inside).toBeNull();
    expect(params.stage).toBe('full');
  });

  it('set all factors with from/to and each with f0..f2', () => {
    const { params } = tri('from=2&to=9&f1=5&inside=3..4');
    expect(params.factors).toEqual([[2, 9], [5], [2, 9]]);
    expect(params.inside).toEqual([3, 4]);
    expect(tri('from=16&to=16').params.factors).toEqual([[16], [16], [16]]);
  });

  it('read reverse flags in both spellings and explain bad ones', () => {
    expect(tri('reverse=0,1,0').params.reverse).toEqual([false, true, false]);
    expect(tri('reverse=101').params.reverse).toEqual([true, false, true]);
    const bad = tri('reverse=yes');
    expect(bad.params.reverse).toEqual([false, false, false]);
    expect(texts(bad.messages)).toMatch(/three flags/);
  });

  it('say that inside has no effect on the clamped pattern alone', () => {
    expect(texts(tri('inside=4').messages)).toMatch(/D3D11 modes only/);
    expect(tri('mode=clamped,integer&inside=4').messages).toEqual([]);
  });

  it('explain a bad stage and a bad factor', () => {
    const { params, messages } = tri('stage=melted&f2=big');
    expect(params.stage).toBe('full');
    expect(params.factors[2]).toEqual([1, 8]);
    expect(messages).toHaveLength(2);
  });
});

describe('presets', () => {
  it('every figure parses without a message on its own page', () => {
    for (const f of FIGURES) {
      const { messages, figure } = parseParams(f.kind, `fig=${f.id}`);
      expect(messages, f.id).toEqual([]);
      expect(figure?.id).toBe(f.id);
    }
  });

  it('ids are unique and every figure has a title and a caption', () => {
    expect(new Set(FIGURES.map((f) => f.id)).size).toBe(FIGURES.length);
    for (const f of FIGURES) {
      expect(f.title.length, f.id).toBeGreaterThan(3);
      expect(f.caption.length, f.id).toBeGreaterThan(40);
    }
  });

  it('URL values override the preset; factors are replaced as a group', () => {
    const { params } = line('fig=even-10.3&to=12&segments=1');
    expect(params.modes).toEqual(['even']);
    expect(params.factor).toEqual([1, 12]); // from/to replaced together: from falls back to 1
    expect(params.segments).toBe(true);
    const t = tri('fig=edges-independent&f1=3');
    expect(t.params.factors[1]).toEqual([3]);
    expect(t.params.factors[0]).toEqual([8, 1, 8, 8, 8, 8, 8]);
  });

  it('explain an unknown figure and a figure of the other kind', () => {
    expect(texts(line('fig=nope').messages)).toMatch(/no figure "nope"/);
    const other = line('fig=inefficient-16');
    expect(texts(other.messages)).toMatch(/triangle figure/);
    expect(other.figure).toBeNull();
  });
});

describe('toQuery', () => {
  it('round-trips every preset', () => {
    for (const f of FIGURES) {
      const p = parseParams(f.kind, `fig=${f.id}`).params;
      expect(toQuery(p), f.id).toBe(`fig=${f.id}`);
    }
  });

  it('round-trips changed parameters', () => {
    const p = parseParams('triangle', 'fig=inefficient-16').params as TriParams;
    p.factors[0] = [5.5];
    p.modes = ['clamped', 'integer'];
    p.loops = true;
    const q = toQuery(p);
    const back = parseParams('triangle', q);
    expect(back.messages).toEqual([]);
    expect(formatParams(back.params)).toEqual(formatParams(p));
    const l = parseParams('line', 'mode=even').params as LineParams;
    l.factor = [2, 3, 9];
    l.t = 1.25;
    expect(formatParams(parseParams('line', toQuery(l)).params)).toEqual(formatParams(l));
  });
});

describe('any input', () => {
  it('never throws and always gives a drawable figure', () => {
    const keys = [...new Set([...knownKeys('line'), ...knownKeys('triangle'), 'junk'])];
    const value = fc.oneof(
      fc.string(),
      fc.double().map(String),
      fc.constantFrom('1', '0', '', 'NaN', 'Infinity', '1..64', '..', 'hable,even'),
    );
    fc.assert(
      fc.property(
        fc.constantFrom('line', 'triangle') as fc.Arbitrary<'line' | 'triangle'>,
        fc.dictionary(fc.constantFrom(...keys), value),
        (kind, input) => {
          const { params } = parseParams(kind, input);
          expect(params.modes.length).toBeGreaterThan(0);
          const tracks = params.kind === 'line' ? [params.factor] : [...params.factors, ...(params.inside ? [params.inside] : [])];
          for (const tr of tracks) for (const v of tr) expect(v >= 1 && v <= 256).toBe(true);
          expect(params.timing.duration).toBeGreaterThan(0);
          expect(Number.isFinite(params.speed) && params.speed > 0).toBe(true);
        },
      ),
      { numRuns: 300 },
    );
  });
});
