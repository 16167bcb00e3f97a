/**
 * The player's view options (the fourth row of its controls): per kind of figure, the selects and
 * toggles that change how the figure is drawn, each writing its parameter and reporting the change.
 */
import { h } from './dom.ts';
import { SHAPES, STAGES, type Params } from './params.ts';

/** Appends the view options of `p`'s kind to `opts`; `changed` runs after each change. */
export function appendViewOptions(opts: HTMLElement, p: Params, changed: () => void): void {
  const select = (label: string, values: readonly string[], get: () => string, set: (v: string) => void, testid: string) => {
    const s = h('select', { 'aria-label': label, 'data-testid': testid });
    for (const v of values) s.append(h('option', { value: v, text: v, selected: v === get() }));
    s.addEventListener('change', () => {
      set(s.value);
      changed();
    });
    opts.append(h('label', {}, h('span', { class: 'td-label', text: `${label} ` }), s));
  };
  const toggle = (label: string, get: () => boolean, set: (v: boolean) => void) => {
    const box = h('input', { type: 'checkbox', checked: get() });
    box.addEventListener('change', () => {
      set(box.checked);
      changed();
    });
    opts.append(h('label', { class: 'td-chip' }, box, h('span', { text: label })));
  };
  if (p.kind === 'line') {
    select(
      'View',
      ['line', 'trace'],
      () => p.view,
      (v) => (p.view = v as typeof p.view),
      'view',
    );
    toggle(
      'segments by size',
      () => p.segments,
      (v) => (p.segments = v),
    );
    toggle(
      'weights',
      () => p.labels,
      (v) => (p.labels = v),
    );
    toggle(
      'whole factors',
      () => p.snap,
      (v) => (p.snap = v),
    );
  } else {
    select(
      'Stage',
      STAGES,
      () => p.stage,
      (v) => (p.stage = v as typeof p.stage),
      'stage',
    );
    select(
      'Shape',
      SHAPES,
      () => p.shape,
      (v) => (p.shape = v as typeof p.shape),
      'shape',
    );
    toggle(
      'edge loops',
      () => p.loops,
      (v) => (p.loops = v),
    );
    toggle(
      'vertices',
      () => p.points,
      (v) => (p.points = v),
    );
  }
}
