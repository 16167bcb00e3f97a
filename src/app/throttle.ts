/**
 * Run something at most once per interval, and never drop the last call: a call inside the
 * interval leaves one trailing run at its end. The demo draws on demand, so no later frame may
 * come to show what arrived in between (the stats would keep reading "…").
 */
export interface Timers {
  now(): number;
  setTimeout(fn: () => void, ms: number): number;
  clearTimeout(id: number): void;
}

export class TrailingThrottle {
  readonly #run: () => void;
  readonly #interval: number;
  readonly #timers: Timers;
  #due = Number.NEGATIVE_INFINITY;
  #timer = 0;

  constructor(run: () => void, intervalMs: number, timers: Timers) {
    this.#run = run;
    this.#interval = intervalMs;
    this.#timers = timers;
  }

  /** Run now if the interval has passed (or `force`), else once at its end. */
  call(force = false): void {
    const now = this.#timers.now();
    if (!force && now < this.#due) {
      if (!this.#timer) this.#timer = this.#timers.setTimeout(() => this.#fire(), this.#due - now);
      return;
    }
    if (this.#timer) {
      this.#timers.clearTimeout(this.#timer);
      this.#timer = 0;
    }
    this.#due = now + this.#interval;
    this.#run();
  }

  #fire(): void {
    this.#timer = 0;
    this.call(true);
  }
}
