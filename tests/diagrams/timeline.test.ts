import { describe, expect, it } from 'vitest';
import {
  defaultDuration,
  isAnimated,
  period,
  phaseAt,
  snapValue,
  timeForValue,
  trackValue,
  type Timing,
} from '../../src/diagrams/timeline.ts';

describe('time → phase', () => {
  const pp: Timing = { duration: 4, hold: 1, loop: 'pingpong' };
  it('ping-pong: up, hold, down, hold', () => {
    expect(period(pp)).toBe(10);
    expect(phaseAt(pp, 0)).toBe(0);
    expect(phaseAt(pp, 2)).toBe(0.5);
    expect(phaseAt(pp, 4.5)).toBe(1);
    expect(phaseAt(pp, 7)).toBe(0.5);
    expect(phaseAt(pp, 9.5)).toBe(0);
    expect(phaseAt(pp, 12)).toBe(0.5); // the next cycle
  });
  it('repeat and once', () => {
    const rep: Timing = { duration: 4, hold: 1, loop: 'repeat' };
    expect(period(rep)).toBe(5);
    expect(phaseAt(rep, 4.5)).toBe(1);
    expect(phaseAt(rep, 6)).toBe(0.25);
    const once: Timing = { duration: 4, hold: 1, loop: 'once' };
    expect(phaseAt(once, 100)).toBe(1);
  });
});

describe('phase → factor', () => {
  it('linear and log between keys', () => {
    expect(trackValue([1, 16], 0.5, 'linear')).toBe(8.5);
    expect(trackValue([1, 16], 0.5, 'log')).toBeCloseTo(4, 12);
    expect(trackValue([8, 1, 8], 0.5, 'linear')).toBe(1);
    expect(trackValue([8, 1, 8], 0.25, 'linear')).toBe(4.5);
    expect(trackValue([5], 0.3, 'log')).toBe(5);
  });
  it('snaps to whole factors and finds the time of a factor', () => {
    expect(snapValue(6.999999999999)).toBe(7);
    expect(snapValue(6.5)).toBe(6);
    const tm: Timing = { duration: 8, hold: 0.6, loop: 'pingpong' };
    expect(timeForValue([8, 16], 10.3, 'linear', tm)).toBeCloseTo(2.3, 12);
    expect(timeForValue([8, 16], 20, 'linear', tm)).toBeNull();
  });
  it('knows static tracks and picks a sensible duration', () => {
    expect(isAnimated([3])).toBe(false);
    expect(isAnimated([3, 3])).toBe(false);
    expect(isAnimated([3, 4])).toBe(true);
    expect(defaultDuration([[1, 64]], 'log')).toBe(9);
    expect(defaultDuration([[16]], 'linear')).toBe(2);
    expect(defaultDuration([[1, 200]], 'linear')).toBe(16);
  });
});
