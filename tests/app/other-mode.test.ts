/**
 * The demo's two small schedulers without a page: the other-mode count (src/app/other-mode.ts)
 * and the stats' trailing throttle (src/app/throttle.ts), on a fake clock.
 */
import { describe, expect, it } from 'vitest';
import type { MeshCounts } from '../../src/app/counts.ts';
import { OtherModeProbe, RECOUNT_MS, type ProbeRequest } from '../../src/app/other-mode.ts';
import { TrailingThrottle } from '../../src/app/throttle.ts';

/** A clock the test moves by hand, with timers that fire when it passes them. */
function fakeClock() {
  let now = 0;
  let nextId = 1;
  const timers = new Map<number, { at: number; fn: () => void }>();
  return {
    now: () => now,
    setTimeout(fn: () => void, ms: number): number {
      const id = nextId++;
      timers.set(id, { at: now + ms, fn });
      return id;
    },
    clearTimeout(id: number): void {
      timers.delete(id);
    },
    pending: () => timers.size,
    advance(ms: number): void {
      const until = now + ms;
      for (;;) {
        const due = [...timers].filter(([, t]) => t.at <= until).sort((a, b) => a[1].at - b[1].at)[0];
        if (!due) break;
        timers.delete(due[0]);
        now = due[1].at;
        due[1].fn();
      }
      now = until;
    },
  };
}

const flush = () => new Promise((r) => setTimeout(r, 0));
const counts = (triangleCount: number): MeshCounts => ({ vertexCount: triangleCount, triangleCount, budgetScale: 1, budgetCandidate: 0 });

function probeHarness() {
  const clock = fakeClock();
  const log: string[] = [];
  const probe = new OtherModeProbe({
    now: clock.now,
    later: (ms, fn) => clock.setTimeout(fn, ms),
    redraw: () => log.push('redraw'),
    changed: () => log.push(`changed ${probe.counts?.counts.triangleCount}`),
  });
  let busy = false;
  const reads: ((c: MeshCounts | null) => void)[] = [];
  const count = () => {
    if (busy) return null;
    log.push('count');
    return new Promise<MeshCounts | null>((r) => reads.push(r));
  };
  return { clock, log, probe, count, reads, setBusy: (b: boolean) => (busy = b) };
}

const fixed: ProbeRequest = { key: 'torus|fixed|factor 8', other: 'fixed', setting: 'factor 8' };
const adaptive: ProbeRequest = { key: 'torus|adaptive|LOD 1', other: 'adaptive', setting: 'LOD 1' };

describe('OtherModeProbe', () => {
  it('counts once per key, shows the answer, and does not count a fixed mode again for camera moves', async () => {
    const h = probeHarness();
    h.probe.update(fixed, h.count);
    h.probe.update(fixed, h.count);
    h.probe.cameraMoved();
    h.clock.advance(5 * RECOUNT_MS);
    h.probe.update(fixed, h.count);
    expect(h.log).toEqual(['count']);
    h.reads[0](counts(100));
    await flush();
    expect(h.probe.counts).toEqual({ mode: 'fixed', setting: 'factor 8', counts: counts(100) });
    expect(h.log).toEqual(['count', 'changed 100']);
  });

  it('a new key drops the old answer at once, and an answer for an old key is never shown', async () => {
    const h = probeHarness();
    h.probe.update(fixed, h.count);
    h.reads[0](counts(100));
    await flush();
    h.probe.update({ ...fixed, key: 'gear|fixed|factor 8' }, h.count);
    expect(h.probe.counts).toBeNull();
    // A third key before the second answer arrives: the second answer is stale.
    h.probe.update({ ...fixed, key: 'gear|fixed|factor 9', setting: 'factor 9' }, h.count);
    h.reads[1](counts(200));
    await flush();
    expect(h.probe.counts).toBeNull();
    h.reads[2](counts(300));
    await flush();
    expect(h.probe.counts?.setting).toBe('factor 9');
    expect(h.probe.counts?.counts.triangleCount).toBe(300);
  });

  it('adaptive: a moving camera recounts at most once a second, and a timer brings the frame that does', () => {
    const h = probeHarness();
    h.probe.update(adaptive, h.count);
    h.probe.cameraMoved();
    h.clock.advance(300);
    h.probe.update(adaptive, h.count);
    h.probe.update(adaptive, h.count); // one timer, however many frames
    expect(h.log).toEqual(['count']);
    expect(h.clock.pending()).toBe(1);
    h.clock.advance(RECOUNT_MS - 300);
    expect(h.log).toEqual(['count', 'redraw']);
    h.probe.update(adaptive, h.count);
    expect(h.log).toEqual(['count', 'redraw', 'count']);
    // Without a camera move, nothing more.
    h.clock.advance(10 * RECOUNT_MS);
    h.probe.update(adaptive, h.count);
    expect(h.log.filter((l) => l === 'count')).toHaveLength(2);
  });

  it('a busy reader defers the count to a later frame instead of dropping it', () => {
    const h = probeHarness();
    h.setBusy(true);
    h.probe.update(fixed, h.count);
    expect(h.log).toEqual([]);
    h.clock.advance(1000);
    expect(h.log).toEqual(['redraw']);
    h.setBusy(false);
    h.probe.update(fixed, h.count);
    expect(h.log).toEqual(['redraw', 'count']);
  });

  it('reset (a new device) counts the same key again', () => {
    const h = probeHarness();
    h.probe.update(fixed, h.count);
    h.probe.reset();
    h.probe.update(fixed, h.count);
    expect(h.log).toEqual(['count', 'count']);
  });
});

describe('TrailingThrottle', () => {
  it('runs at once, then at most once per interval, and always once more after the last call', () => {
    const clock = fakeClock();
    const runs: number[] = [];
    const t = new TrailingThrottle(() => runs.push(clock.now()), 250, clock);
    t.call();
    clock.advance(10);
    t.call();
    clock.advance(10);
    t.call();
    expect(runs).toEqual([0]);
    clock.advance(1000);
    expect(runs).toEqual([0, 250]); // the trailing run, once
    t.call(); // interval passed: at once
    expect(runs).toEqual([0, 250, 1020]);
  });

  it('a forced call runs at once and takes the place of a pending trailing run', () => {
    const clock = fakeClock();
    const runs: number[] = [];
    const t = new TrailingThrottle(() => runs.push(clock.now()), 250, clock);
    t.call();
    clock.advance(50);
    t.call();
    t.call(true);
    expect(runs).toEqual([0, 50]);
    expect(clock.pending()).toBe(0);
    clock.advance(1000);
    expect(runs).toEqual([0, 50]);
  });
});
