// The panel's table (src/app/panel.ts PANEL), checked without a DOM: the labels the end-to-end
// tests drive it by, the parameters it binds, and how its values map onto the parameters.
import { describe, expect, it } from 'vitest';
import { PANEL } from '../../src/app/panel.ts';
import { DEFAULT_PARAMS, ERR_RANGE, type DemoParams } from '../../src/app/params.ts';

const controls = PANEL.flatMap((f) => f.controls);
const control = (label: string) => controls.find((c) => c.label === label)!;
const state = () => ({ picked: 'torus', errRange: 0.01 });

describe('the panel table', () => {
  it('names each control once, in its folders', () => {
    const labels = controls.map((c) => c.label);
    expect(new Set(labels).size).toBe(labels.length);
    expect(PANEL.map((f) => f.title)).toEqual(['Model', 'Tessellation', 'View', 'Displacement', 'Instanced tessellator']);
  });

  it('binds parameters of the URL, each control but the buttons', () => {
    for (const c of controls) {
      if (c.kind === 'action') expect(c.param).toBeUndefined();
      else expect(Object.keys(DEFAULT_PARAMS)).toContain(c.param);
    }
  });

  it("offers each choice's default among its options", () => {
    for (const c of controls.filter((c) => c.kind === 'choice' && !c.read)) {
      const values = Array.isArray(c.options) ? c.options : Object.values(c.options!);
      expect(values).toContain(DEFAULT_PARAMS[c.param!]);
    }
  });

  it('maps the comparison and the level onto their parameters', () => {
    const p: DemoParams = { ...DEFAULT_PARAMS };
    const compare = control('compare (right half)');
    compare.write!(p, state(), 'pm-acc');
    expect(p.compare).toBe('pm-acc');
    compare.write!(p, state(), 'off');
    expect(p.compare).toBeNull();
    expect(compare.read!(p, state())).toBe('off');
    control('level (fixed)').write!(p, state(), '16');
    expect(p.level).toBe(16);
  });

  it('takes the error range when editing ends, clamped, and none for a bad value', () => {
    const p: DemoParams = { ...DEFAULT_PARAMS };
    const s = state();
    const range = control('error range');
    range.write!(p, s, 1e9);
    expect(p.errRange).toBe(DEFAULT_PARAMS.errRange);
    range.commit!(p, s);
    expect(p.errRange).toBe(ERR_RANGE.max);
    range.write!(p, s, -1);
    range.commit!(p, s);
    expect(p.errRange).toBeNull();
  });

  it('a new error view drops the range typed for the old one', () => {
    const p: DemoParams = { ...DEFAULT_PARAMS, errorView: 'geometry', errRange: 0.5 };
    control('error view').write!(p, state(), 'normal');
    expect(p).toMatchObject({ errorView: 'normal', errRange: null });
  });

  it('shows what applies: the fixed factor not to the instanced tessellator alone, the error views for ACC', () => {
    const factor = control('fixed factor');
    expect(factor.shown!({ ...DEFAULT_PARAMS, mode: 'fixed' })).toBe(true);
    expect(factor.shown!({ ...DEFAULT_PARAMS, mode: 'fixed', tessellator: 'instanced' })).toBe(false);
    expect(factor.shown!({ ...DEFAULT_PARAMS, mode: 'fixed', tessellator: 'instanced', split: true })).toBe(true);
    const errorView = control('error view');
    expect(errorView.shown!({ ...DEFAULT_PARAMS, surface: 'catmull-clark' })).toBe(false);
    expect(errorView.shown!({ ...DEFAULT_PARAMS, surface: 'gregory-acc' })).toBe(true);
    expect(errorView.shown!({ ...DEFAULT_PARAMS, surface: 'phong', compare: 'bezier-acc' })).toBe(true);
  });
});
