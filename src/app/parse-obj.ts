/**
 * An OBJ file's bytes to what the page shows: decoded, parsed and validated (src/mesh), with the
 * cage's flat triangulation (the picture shown while its surface is prepared). One function for
 * the worker that reads a user's file (src/app/model-worker.ts) and for the page's thread where
 * there are no workers (src/app/parse-off-thread.ts).
 */
import { decodeText, LimitError, type LoadedCage, loadCage } from '../mesh/index.ts';
import { cageTooLarge } from '../gpu/tess/arenas.ts';
import { triangulateCage, type TriangulatedCage } from '../gpu/render/cage-mesh.ts';

/** The cage, and its flat triangulation, made with it: 40-60 ms of the page's thread on a
 * 40,000-face cage when it was made there. */
export type ParsedFile = LoadedCage & { flat: TriangulatedCage };

/** The device's bounds a cage must fit (src/gpu/tess/arenas.ts cageTooLarge). */
export interface DeviceFits {
  maxFactor: number;
  bindingLimit: number;
}

/** Throws what loadCage throws (a CageError with line numbers for a bad file), and, given the
 * device's bounds, a LimitError for a cage too large for them (before the triangulation is made). */
export function parseObjBytes(bytes: Uint8Array, fits?: DeviceFits): ParsedFile {
  const loaded = loadCage(decodeText(bytes));
  const why = fits ? cageTooLarge(loaded.cage, fits.maxFactor, fits.bindingLimit) : null;
  if (why) throw new LimitError(why);
  return { ...loaded, flat: triangulateCage(loaded.cage) };
}
