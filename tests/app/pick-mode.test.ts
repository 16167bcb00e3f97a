// Which of the demo's modes draws (src/app/modes/pick-mode.ts), from what is asked and what the
// shown model and the device allow; and the demo's current mode object, swapped only when that
// answer changes (src/app/modes/mode-switch.ts). No GPU, no page.
import { describe, expect, it } from 'vitest';
import type { Shown } from '../../src/app/controller.ts';
import { ModeSwitch } from '../../src/app/modes/mode-switch.ts';
import { pickMode, type ModeAsk, type ModeCaps, type ModeId } from '../../src/app/modes/pick-mode.ts';
import { ACC_SURFACES, SURFACES } from '../../src/app/params.ts';

const nothing: ModeAsk = { tessellator: 'compute', split: false, compare: null, errorView: 'off' };
const phong: ModeCaps = { model: true, shown: 'phong', vertexStorage: true };
const acc: ModeCaps = { ...phong, shown: 'gregory-acc' };

const instanced: ModeAsk = { ...nothing, tessellator: 'instanced' };
const split: ModeAsk = { ...nothing, split: true };
const compare: ModeAsk = { ...nothing, compare: 'bezier-acc' };
const errorView: ModeAsk = { ...nothing, errorView: 'geometry' };
/** Everything asked at once. */
const all: ModeAsk = { tessellator: 'instanced', split: true, compare: 'pm-acc', errorView: 'normal' };

describe('pickMode', () => {
  it('the compute tessellator alone when nothing else is asked for, on every surface', () => {
    for (const shown of SURFACES) expect(pickMode(nothing, { ...phong, shown })).toBe('compute');
  });

  it('each mode where it is asked for and the surface allows it', () => {
    expect(pickMode(instanced, phong)).toBe('instanced');
    expect(pickMode(split, phong)).toBe('split');
    expect(pickMode(compare, phong)).toBe('compare');
    expect(pickMode(errorView, acc)).toBe('error');
  });

  it('the split view whatever `tessellator` says', () => {
    expect(pickMode({ ...split, tessellator: 'compute' }, phong)).toBe('split');
    expect(pickMode({ ...split, tessellator: 'instanced' }, phong)).toBe('split');
  });

  it('the instanced tessellator and the split view before a comparison (they are the other use of the two halves) and an error view', () => {
    expect(pickMode({ ...instanced, compare: 'gregory-acc', errorView: 'geometry' }, acc)).toBe('instanced');
    expect(pickMode({ ...split, compare: 'gregory-acc', errorView: 'geometry' }, acc)).toBe('split');
    expect(pickMode(all, acc)).toBe('split');
  });

  it('a comparison before an error view (it measures its halves itself)', () => {
    expect(pickMode({ ...compare, errorView: 'normal' }, acc)).toBe('compare');
  });

  it('before a model is shown: the compute tessellator, whatever is asked', () => {
    for (const ask of [instanced, split, compare, errorView, all]) expect(pickMode(ask, { ...acc, model: false })).toBe('compute');
  });

  it('on the flat cage: the compute tessellator (its faces), whatever is asked', () => {
    for (const ask of [instanced, split, compare, errorView, all]) expect(pickMode(ask, { ...phong, shown: 'cage' })).toBe('compute');
  });

  it('without vertex-stage storage (compatibility mode) the compute tessellator draws what else is asked', () => {
    const compat = (c: ModeCaps): ModeCaps => ({ ...c, vertexStorage: false });
    expect(pickMode(instanced, compat(phong))).toBe('compute');
    expect(pickMode(split, compat(phong))).toBe('compute');
    expect(pickMode({ ...split, compare: 'bezier-acc' }, compat(phong))).toBe('compare');
    expect(pickMode({ ...instanced, errorView: 'geometry' }, compat(acc))).toBe('error');
    expect(pickMode(all, compat(acc))).toBe('compare');
  });

  it('error views only on an ACC surface: elsewhere the compute tessellator alone', () => {
    for (const shown of ACC_SURFACES) expect(pickMode(errorView, { ...phong, shown })).toBe('error');
    for (const shown of ['phong', 'catmull-clark', 'cage'] as Shown[]) expect(pickMode(errorView, { ...phong, shown })).toBe('compute');
  });

  it('a comparison on any surface but the flat cage (the shown one: Phong where the asked one refused the model)', () => {
    for (const shown of SURFACES) expect(pickMode(compare, { ...phong, shown })).toBe(shown === 'cage' ? 'compute' : 'compare');
  });

  it('the instanced tessellator and the split view on any surface but the flat cage', () => {
    for (const shown of SURFACES) {
      expect(pickMode(instanced, { ...phong, shown })).toBe(shown === 'cage' ? 'compute' : 'instanced');
      expect(pickMode(split, { ...phong, shown })).toBe(shown === 'cage' ? 'compute' : 'split');
    }
  });
});

describe('the current mode', () => {
  function modes() {
    const log: string[] = [];
    const make = (id: ModeId) => {
      log.push(`make ${id}`);
      return { id, release: () => log.push(`release ${id}`) };
    };
    return { log, modes: new ModeSwitch(make) };
  }

  it('starts as the compute tessellator', () => {
    const { log, modes: m } = modes();
    expect(m.current.id).toBe('compute');
    expect(log).toEqual(['make compute']);
  });

  it('is kept while the answer stays the same', () => {
    const { log, modes: m } = modes();
    const first = m.to('compute');
    expect(m.to('compute')).toBe(first);
    const split = m.to('split');
    expect(m.to('split')).toBe(split);
    expect(log).toEqual(['make compute', 'release compute', 'make split']);
  });

  it('is released before the next one is made, once per change', () => {
    const { log, modes: m } = modes();
    for (const id of ['compare', 'compare', 'error', 'instanced', 'compute'] as ModeId[]) m.to(id);
    expect(m.current.id).toBe('compute');
    expect(log).toEqual([
      'make compute',
      'release compute',
      'make compare',
      'release compare',
      'make error',
      'release error',
      'make instanced',
      'release instanced',
      'make compute',
    ]);
  });
});
