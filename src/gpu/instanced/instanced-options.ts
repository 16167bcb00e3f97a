/**
 * What the instanced tessellator is made with (InstancedOptions: its surface, displacement and
 * render targets) and what each level pass takes (LevelParams, their defaults and their mode codes
 * in INST_PARAMS; factorRuleLevels makes them from the compute tessellator's FactorParams).
 */
import type { FactorParams } from '../contract/tessellated-mesh.ts';

/** How the vertex stage evaluates the surface: its own cage buffer through evalSurface (Phong),
 * AccPatches' control points, or the buffers a compute tessellator on the exact Catmull-Clark
 * limit lends it (src/gpu/surface/registry.ts instancedKind says which for each surface). */
export type InstancedSurfaceKind = 'evalSurface' | 'acc' | 'lent-limit';

export interface InstancedOptions {
  /** WGSL defining `fn evalSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint` (default: Phong,
   * wgsl/surface/phong.wgsl), evaluated through wgsl/instanced/surface-tri.wgsl. */
  surfaceWgsl?: string;
  /**
   * 'acc': the ACC surfaces (Bezier, Gregory or Pm ACC, by the AccPatches handed to setMesh:
   * src/gpu/acc/patches.ts builds them from the cage, wgsl/acc/surface.wgsl evaluates them through
   * wgsl/instanced/surface-acc.wgsl), their two buffers bound in a fourth bind group (group 3) in
   * every pass. 'lent-limit': the exact Catmull-Clark limit surface, evaluated by the compute tessellator's
   * wgsl/cc/surface.wgsl over the buffers of a Catmull-Clark Tessellator handed to setMesh
   * (src/gpu/instanced/surface-cc.ts: ccSurfaceTessellator makes one), bound in group 3; encodeLevels runs
   * its patch build first.
   */
  surface?: InstancedSurfaceKind;
  /**
   * Displace every vertex the vertex function evaluates by a height map (src/gpu/instanced/displace-vertex.ts):
   * setMesh then needs a lending compute Tessellator holding the displacement arenas (on
   * Catmull-Clark the surface's own lender, made with the displacement; on Phong and ACC
   * displacementLender), bound in group 3; boundary points are evaluated through their owner
   * triangle (crack-free at UV seams). Off (default): the module has none of it.
   */
  displacement?: boolean;
  /** Render target format of the lit pipeline (default 'rgba8unorm'). */
  colorFormat?: GPUTextureFormat;
  /** Depth format of the lit and shadow pipelines (default 'depth32float'). */
  depthFormat?: GPUTextureFormat;
  /** Samples per pixel of the lit pass (the demo's renderer draws with 4× MSAA; default 1). */
  sampleCount?: number;
}

export interface LevelParams {
  /** static: every patch at `level`; per-patch: the levels given to setWanted; dynamic: per
   * edge from the view (viewProj, viewport, lodScale, targetPixels, pixelError); factor-rule: per
   * edge by the compute tessellator's adaptive rule (viewProj, eye, pixelAngle, lodScale:
   * factorRuleLevels makes them from its FactorParams), rounded up to a power of two. */
  mode: 'static' | 'per-patch' | 'dynamic' | 'factor-rule';
  /** The static level (also the dynamic mode's level for an edge behind the eye). Default 4. */
  level?: number;
  viewProj?: Float32Array;
  viewport?: [number, number];
  lodScale?: number;
  /** Dynamic: pixels per segment along an edge's chord (default 12). */
  targetPixels?: number;
  /** Dynamic: allowed distance in pixels between the curve and its segments (default 0.5). */
  pixelError?: number;
  /** Factor rule: the eye in model space, and radians per pixel (fovY / viewport height). */
  eye?: [number, number, number];
  pixelAngle?: number;
}

/** The defaults of LevelParams, shared by the GPU upload and the CPU twin. */
export const LEVEL_DEFAULTS = { level: 4, lodScale: 1, targetPixels: 12, pixelError: 0.5 };

/** LevelParams.mode as INST_PARAMS.mode holds it (wgsl/instanced/levels.wgsl). */
export const LEVEL_MODE = { static: 0, 'per-patch': 1, dynamic: 2, 'factor-rule': 3 } as const;

/** The factor-rule levels for the compute tessellator's camera and LOD scale (its FactorParams, as
 * its adaptive mode reads them): the two tessellators then measure the view alike. */
export function factorRuleLevels(f: FactorParams): LevelParams {
  return {
    mode: 'factor-rule',
    viewProj: f.viewProj,
    eye: [f.eye[0], f.eye[1], f.eye[2]],
    pixelAngle: f.fovY / Math.max(1, f.viewportHeight),
    lodScale: f.lodScale,
  };
}
