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
