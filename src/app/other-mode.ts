/**
 * The stats' other factor mode (fixed while adaptive is drawn, and the reverse): when to count
 * it again, and which answer is still current. The counting itself (an extra build in that mode,
 * its counts read back, then the drawn build again) is the page's, handed in as `count`.
 *
 * Rules: a new key (model, surface, flat baseline, the other mode and its setting) drops the old
 * answer and counts at once; with the same key, only an adaptive count is redone, when the camera
 * moved, at most once a second (a timer brings the frame that does it); an answer whose key is no
 * longer current is dropped. DOM-free and GPU-free (tests/app/other-mode.test.ts).
 */
import type { MeshCounts } from './counts.ts';
import type { OtherModeCounts } from './stats.ts';

export interface ProbeRequest {
  key: string;
  other: 'fixed' | 'adaptive';
  /** Shown with the counts: "factor 8" or "LOD 1". */
  setting: string;
}

export interface ProbeHost {
  now(): number;
  /** Run `fn` after `ms` milliseconds. */
  later(ms: number, fn: () => void): void;
  /** Draw a frame (the page draws on demand; counting happens after a frame). */
  redraw(): void;
  /** The answer changed: show it. */
  changed(): void;
}

/** Least time between two counts of the same key (adaptive, while the camera moves). */
export const RECOUNT_MS = 1000;
/** When the reader is busy, look again this much later. */
const BUSY_RETRY_MS = 100;

export class OtherModeProbe {
  /** The current answer, or null while it is being counted. */
  counts: OtherModeCounts | null = null;
  readonly #host: ProbeHost;
  #key = '';
  #cameraMoved = false;
  #lastAt = Number.NEGATIVE_INFINITY;
  #timer = false;

  constructor(host: ProbeHost) {
    this.#host = host;
  }

  cameraMoved(): void {
    this.#cameraMoved = true;
  }

  /** Forget what was counted (a new device: nothing it counted is there any more). */
  reset(): void {
    this.#key = '';
    this.counts = null;
  }

  /**
   * After a frame: count again if the rules say so. `count` submits the extra builds and gives
   * the read of their counts, or null when it cannot start now (its reader is busy).
   */
  update(request: ProbeRequest, count: () => Promise<MeshCounts | null> | null): void {
    const { key, other, setting } = request;
    if (key !== this.#key) this.counts = null;
    else if (!(other === 'adaptive' && this.#cameraMoved)) return;
    const wait = this.#lastAt + RECOUNT_MS - this.#host.now();
    if (key === this.#key && wait > 0) {
      // The camera moved just after a count: count again a little later.
      this.#later(wait);
      return;
    }
    const read = count();
    if (!read) {
      this.#later(BUSY_RETRY_MS);
      return;
    }
    this.#key = key;
    this.#cameraMoved = false;
    this.#lastAt = this.#host.now();
    void read.then(
      (counts) => {
        if (!counts || this.#key !== key) return;
        this.counts = { mode: other, setting, counts };
        this.#host.changed();
      },
      () => {},
    );
  }

  #later(ms: number): void {
    if (this.#timer) return;
    this.#timer = true;
    this.#host.later(ms, () => {
      this.#timer = false;
      this.#host.redraw();
    });
  }
}
