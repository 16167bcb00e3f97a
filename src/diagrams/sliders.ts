/**
 * The player's factor sliders (the third row of its controls): one log-scaled slider per factor
 * (drag to pin it) and the sweep's range, for a line or a triangle figure.
 */
import { h } from './dom.ts';
import type { Params } from './params.ts';

/** Each slider's input, readout and label, by name (DiagramPlayer updates the readouts). */
export type SliderEls = Map<string, { input: HTMLInputElement; out: HTMLOutputElement; wrap: HTMLElement }>;

/** Log-scaled factor sliders: position 0..1000 ↔ factor 1..max. */
export const toPos = (f: number, max: number) => Math.round((1000 * Math.log(Math.max(1, f))) / Math.log(max));
export const fromPos = (p: number, max: number) => Math.round(Math.exp((p / 1000) * Math.log(max)) * 100) / 100;

/** Appends the sliders of `p` to `box`, recording them in `sliders`; `changed` runs after each
 * change, `rebuild` after a change of the sweep's range (it rebuilds the sliders). */
export function addFactorSliders(box: HTMLElement, p: Params, sliders: SliderEls, changed: () => void, rebuild: () => void): void {
  const add = (name: string, label: string, max: number, pin: (v: number) => void) => {
    const input = h('input', {
      type: 'range',
      min: 0,
      max: 1000,
      step: 1,
      'aria-label': `${label} (drag to pin)`,
      'data-max': max,
      'data-testid': `slider-${name}`,
    });
    const out = h('output', { text: '' });
    input.addEventListener('input', () => {
      pin(fromPos(Number(input.value), max));
      changed();
    });
    const wrap = h('label', { class: 'td-slider' }, h('span', { class: 'td-label', text: label }), input, out);
    box.append(wrap);
    sliders.set(name, { input, out, wrap });
  };
  const range = (label: string, get: () => [number, number], set: (a: number, b: number) => void, max: number) => {
    const [a, b] = get();
    const from = h('input', {
      type: 'number',
      min: 1,
      max,
      step: 0.1,
      value: a,
      'aria-label': `${label} from`,
      'data-testid': 'sweep-from',
    });
    const to = h('input', { type: 'number', min: 1, max, step: 0.1, value: b, 'aria-label': `${label} to`, 'data-testid': 'sweep-to' });
    const apply = () => {
      const x = Math.min(max, Math.max(1, Number(from.value) || 1));
      const y = Math.min(max, Math.max(1, Number(to.value) || 1));
      set(x, y);
      rebuild();
      changed();
    };
    from.addEventListener('change', apply);
    to.addEventListener('change', apply);
    box.append(
      h(
        'div',
        { class: 'td-slider', style: 'grid-template-columns: auto auto auto auto' },
        h('span', { class: 'td-label', text: 'sweep' }),
        from,
        h('span', { class: 'td-label', text: 'to' }),
        to,
      ),
    );
  };
  const mf = p.maxFactor;
  if (p.kind === 'line') {
    add('factor', 'factor', mf, (v) => (p.factor = [v]));
    range(
      'Factor',
      () => [Math.min(...p.factor), Math.max(...p.factor)],
      (a, b) => (p.factor = a === b ? [a] : [a, b]),
      mf,
    );
  } else {
    for (let i = 0; i < 3; i++) add(`f${i}`, `f${i}`, mf, (v) => (p.factors[i] = [v]));
    if (p.modes.some((m) => m !== 'clamped')) {
      add('inside', 'inside', 64, (v) => (p.inside = [v]));
    }
    const lo = Math.min(...p.factors.flat());
    const hi = Math.max(...p.factors.flat());
    range(
      'Edge factors',
      () => [lo, hi],
      (a, b) => {
        const tr = a === b ? [a] : [a, b];
        p.factors = [tr, tr, tr];
        p.inside = null;
      },
      mf,
    );
  }
}
