/** What a figure function returns for one frame: the drawing and the numbers shown beside it. */
import type { Scene } from './scene.ts';

export interface PanelCounts {
  /** The pattern mode of this row or panel. */
  mode: string;
  label: string;
  /** Points of a line, vertices of a triangle pattern. */
  vertices: number;
  /** Segments of a line, triangles of a triangle pattern. */
  triangles: number;
  /** Zero-length segments or zero-area triangles. */
  degenerate: number;
}

export interface FactorValue {
  /** `factor`, or `f0`, `f1`, `f2`, `inside`. */
  name: string;
  value: number;
  animated: boolean;
}

export interface FigureFrame {
  scene: Scene;
  counts: PanelCounts[];
  factors: FactorValue[];
}

/**
 * Below this many CSS px of available width (a phone, a blog column) a figure lays itself out
 * again instead of shrinking its 760 px layout: panels stacked, drawn at about one scene unit
 * per CSS px, so that the type sizes below are what the reader sees.
 */
export const COMPACT_BELOW = 600;

/** The smallest type of a compact layout, in CSS px (the small labels of the wide layout are
 * 10 to 10.5 px at full size, and the wide layout is shrunk below 600 px). */
export const MIN_TEXT_PX = 11;

/** The narrowest a compact layout gets (a 320 px phone's content width is about 280 px). */
export const MIN_COMPACT_WIDTH = 280;

/** The layout for `width` CSS px of available width: null for the wide layout, else the compact
 * layout's width (whole px, so it never draws wider than the space it measured). */
export function compactWidth(width: number | undefined): number | null {
  if (width === undefined || !(width > 0) || width >= COMPACT_BELOW) return null;
  return Math.max(MIN_COMPACT_WIDTH, Math.floor(width));
}
