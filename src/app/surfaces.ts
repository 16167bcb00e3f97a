/**
 * The demo's surfaces as the panel and its modes see them: the registry's surfaces
 * (src/gpu/surface/registry.ts), which the demo asks what they are, plus the flat cage, a view of
 * the cage itself and no surface. Nothing in src/app tells surfaces apart by name; it asks these.
 */
import { isAccSurface, isSurfaceId, SURFACE_SCHEMES, surfaceScheme } from '../gpu/surface/registry.ts';
import type { DemoParams, Surface } from './params.ts';

/** The surfaces by their names in the panel and in messages. */
export const SURFACE_NAMES: Record<DemoParams['surface'], string> = {
  ...(Object.fromEntries(SURFACE_SCHEMES.map((s) => [s.id, s.name])) as Record<Exclude<Surface, 'cage'>, string>),
  cage: 'flat cage',
};

/** The surface that takes every cage (Phong needs nothing prepared): shown where another refuses one. */
export const FALLBACK_SURFACE = 'phong' as const satisfies Surface;

/** An ACC scheme (the surfaces the error views measure against the exact limit). */
export function isAcc(surface: string | null | undefined): surface is Exclude<Surface, 'cage' | 'phong' | 'catmull-clark'> {
  return surface != null && isSurfaceId(surface) && isAccSurface(surface);
}

/** The exact Catmull-Clark limit (the error views' reference; its patch colours are its regions'). */
export function isExact(surface: string | null | undefined): boolean {
  return surface != null && isSurfaceId(surface) && surfaceScheme(surface).exactLimit;
}

/** A surface whose data is prepared ahead of the upload, off the frame (the Catmull-Clark tables:
 * seconds on a large cage, cached per model); the ACC patches are made at upload, Phong needs none. */
export function preparedAhead(surface: string | null | undefined): boolean {
  return surface != null && isSurfaceId(surface) && surfaceScheme(surface).patchBuild === 'refinement';
}
