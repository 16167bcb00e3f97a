/**
 * Baked pattern tables: what the GPU tessellator reads instead of running the pattern code.
 *
 * Everything is baked from the one implementation (hable-line.ts, clamped.ts) and a table-driven
 * evaluator below rebuilds lines and triangles from the bytes alone; the tests hold it equal to
 * the pattern functions, and the WGSL tessellator mirrors this evaluator.
 *
 * BINARY LAYOUT (version 2). A flat array of little-endian u32 words, so a WebGPU storage
 * buffer can hold it as array<u32>. Offsets are in words from the start.
 *
 *   word  header
 *    0    MAGIC 0x4C534554 ("TESL")
 *    1    VERSION = 2
 *    2    maxFactor M (a power of two, 2..256)
 *    3    slotCount S            every point the line can ever have, in position order
 *    4    stateCount T           distinct sets of present slots as F runs over [1, M]
 *    5    slotsOffset            S records of 5 words: x0, x1, f0, w, death
 *    6    stateStartOffset       T words: the smallest 16.16 factor F of each state (ascending)
 *    7    stateIndexOffset       T records of 2 words: first entry in stateList, point count
 *    8    stateListOffset        slot indices of each state's points, in position order
 *    9    mergeOffset            = totalWords, and
 *   10    mergeWords             = 0: version 1 stored the gap matching of the clamped pattern
 *                                here, per pair of line states; it is now computed from the
 *                                points' positions (clamped.ts gapMergeSteps), once per triangle
 *                                by the plan pass (wgsl/tess/plan.wgsl). The two words stay so
 *                                that the header's layout (and its WGSL getters) is unchanged.
 *   11    totalWords
 *   12-15 reserved (0)
 *
 *   Slots: a slot is present at F when f0 < F < death and sits at x0 ± ⌈|x1−x0|·clamp(F−f0,0,w)/w⌉
 *   (hable-line.ts). The two end points have f0 = 0 and x0 = x1.
 *   States: state k holds for stateStart[k] ≤ F < stateStart[k+1] (binary search on F).
 */
import { ONE } from './fixed.ts';
import { MAX_FACTOR } from './max-factor.ts';
import { ALWAYS, HABLE_OPTIONS, buildSlots, checkMaxFactor, NO_DEATH, slotPosition, stableFactorFixed, type Slot } from './hable-line.ts';
import { assembleClamped, chooseFrame, fromFrame, type FramedLine, type Reverse, FORWARD } from './clamped.ts';
import type { LinePattern, TriPattern } from './types.ts';

export const TABLE_MAGIC = 0x4c534554;
export const TABLE_VERSION = 2;
/** The header's words, in order (the layout above): the one list that the writer, the reader and
 * the WGSL getters (src/gpu/contract/tess.ts, `tableHeader_stateCount()` …) all index by. */
export const TABLE_HEADER_FIELDS = [
  'magic',
  'version',
  'maxFactor',
  'slotCount',
  'stateCount',
  'slotsOffset',
  'stateStartOffset',
  'stateIndexOffset',
  'stateListOffset',
  'mergeOffset',
  'mergeWords',
  'totalWords',
] as const;
export type TableHeaderField = (typeof TABLE_HEADER_FIELDS)[number];
/** Word index of each header field. */
export const TABLE_HEADER = Object.fromEntries(TABLE_HEADER_FIELDS.map((f, i) => [f, i])) as Readonly<Record<TableHeaderField, number>>;
/** Words the header takes (the rest reserved, 0). */
export const HEADER_WORDS = 16;
const SLOT_WORDS = 5;

/** The distinct present-slot sets of the schedule, with the F where each starts. */
function enumerateStates(slots: Slot[], maxFactor: number): { start: number[]; present: number[][] } {
  const events = new Set<number>([ONE]);
  for (const s of slots) {
    if (s.f0 !== ALWAYS && s.f0 + 1 <= maxFactor * ONE) events.add(s.f0 + 1); // born: present for F > f0
    if (s.death !== NO_DEATH) events.add(s.death); // gone for F ≥ death
  }
  const start = [...events].sort((a, b) => a - b);
  const present = start.map((F) => slots.flatMap((s, i) => (s.f0 < F && F < s.death ? [i] : [])));
  return { start, present };
}

export function bakeTables(maxFactor = MAX_FACTOR): Uint32Array {
  checkMaxFactor(maxFactor);
  const slots = buildSlots(maxFactor, HABLE_OPTIONS);
  const { start, present } = enumerateStates(slots, maxFactor);
  const S = slots.length;
  const T = start.length;
  const mergeWords = 0;
  const listWords = present.reduce((n, p) => n + p.length, 0);

  const slotsOffset = HEADER_WORDS;
  const stateStartOffset = slotsOffset + S * SLOT_WORDS;
  const stateIndexOffset = stateStartOffset + T;
  const stateListOffset = stateIndexOffset + 2 * T;
  const mergeOffset = stateListOffset + listWords;
  const totalWords = mergeOffset;
  const out = new Uint32Array(totalWords);
  const header: Record<TableHeaderField, number> = {
    magic: TABLE_MAGIC,
    version: TABLE_VERSION,
    maxFactor,
    slotCount: S,
    stateCount: T,
    slotsOffset,
    stateStartOffset,
    stateIndexOffset,
    stateListOffset,
    mergeOffset,
    mergeWords,
    totalWords,
  };
  out.set(TABLE_HEADER_FIELDS.map((f) => header[f]));

  slots.forEach((s, i) => {
    out.set([s.x0, s.x1, s.f0 === ALWAYS ? 0 : s.f0, s.w, s.death], slotsOffset + SLOT_WORDS * i);
  });
  let at = stateListOffset;
  present.forEach((p, k) => {
    out[stateStartOffset + k] = start[k];
    out[stateIndexOffset + 2 * k] = at - stateListOffset;
    out[stateIndexOffset + 2 * k + 1] = p.length;
    out.set(p, at);
    at += p.length;
  });

  return out;
}

/** A decoded view of the tables, and the evaluator that the WGSL tessellator mirrors. */
export class PatternTables {
  readonly maxFactor: number;
  readonly slotCount: number;
  readonly stateCount: number;
  private readonly off: { slots: number; start: number; index: number; list: number };

  constructor(readonly words: Uint32Array) {
    const h = (f: TableHeaderField) => words[TABLE_HEADER[f]];
    if (words.length < HEADER_WORDS || h('magic') !== TABLE_MAGIC) throw new Error('not a tessellab pattern table (bad magic)');
    if (h('version') !== TABLE_VERSION) throw new Error(`unsupported pattern table version ${h('version')} (expected ${TABLE_VERSION})`);
    if (h('totalWords') !== words.length) throw new Error(`pattern table truncated: ${words.length} of ${h('totalWords')} words`);
    this.maxFactor = h('maxFactor');
    this.slotCount = h('slotCount');
    this.stateCount = h('stateCount');
    this.off = {
      slots: h('slotsOffset'),
      start: h('stateStartOffset'),
      index: h('stateIndexOffset'),
      list: h('stateListOffset'),
    };
  }

  slot(i: number): Slot {
    const o = this.off.slots + SLOT_WORDS * i;
    const w = this.words;
    return { x0: w[o], x1: w[o + 1], f0: w[o + 2], w: w[o + 3], death: w[o + 4] };
  }

  /** The state holding at 16.16 factor F (binary search over the state starts). */
  state(F: number): number {
    let lo = 0;
    let hi = this.stateCount - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (this.words[this.off.start + mid] <= F) lo = mid;
      else hi = mid - 1;
    }
    return lo;
  }

  /** Slot indices of a state's points, in position order. */
  statePoints(k: number): Uint32Array {
    const first = this.words[this.off.index + 2 * k];
    const count = this.words[this.off.index + 2 * k + 1];
    return this.words.subarray(this.off.list + first, this.off.list + first + count);
  }

  fixedFactor(factor: number): number {
    return stableFactorFixed(factor, this.maxFactor);
  }

  line(factor: number): LinePattern {
    const F = this.fixedFactor(factor);
    const x: number[] = [];
    const moving: boolean[] = [];
    for (const i of this.statePoints(this.state(F))) {
      const s = this.slot(i);
      x.push(slotPosition(s, F));
      moving.push(s.f0 !== 0 && F < s.f0 + s.w);
    }
    return { x, moving };
  }

  framedLine(factor: number, flip: boolean): FramedLine & { state: number } {
    const F = this.fixedFactor(factor);
    const state = this.state(F);
    const pts = [...this.statePoints(state)];
    const x = pts.map((i) => slotPosition(this.slot(i), F));
    if (!flip) return { x, state };
    return { x: x.map((v) => ONE - v).reverse(), state };
  }

  /** The clamped-parallelogram pattern rebuilt from the tables alone. */
  clampedTriangle(factors: readonly [number, number, number], reverse: Reverse = FORWARD): TriPattern {
    const frame = chooseFrame(reverse);
    const bottom = this.framedLine(factors[frame.bottomEdge], frame.flipBottom);
    const left = this.framedLine(factors[frame.leftEdge], frame.flipLeft);
    const right = this.framedLine(factors[frame.rightEdge], frame.flipRight);
    return fromFrame(assembleClamped(bottom.x, left.x, right.x), frame);
  }
}
