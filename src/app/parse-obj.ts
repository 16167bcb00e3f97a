/**
 * An OBJ file's bytes to what the page shows: decoded, parsed and validated (src/mesh), with the
 * cage's flat triangulation (the picture shown while its surface is prepared). One function for
 * the worker that reads a user's file (src/app/model-worker.ts) and for the page's thread where
 * there are no workers (src/app/parse-off-thread.ts).
 */
import { type Cage, decodeText, LimitError, type LoadedCage, loadCage } from '../mesh/index.ts';
import { triangulateCage, type TriangulatedCage } from '../gpu/render/cage-mesh.ts';

/** The cage, and its flat triangulation, made with it: 40-60 ms of the page's thread on a
 * 40,000-face cage when it was made there. */
export type ParsedFile = LoadedCage & { flat: TriangulatedCage };

/** Throws what loadCage throws (a CageError with line numbers for a bad file), and a LimitError
 * with `refuse`'s sentence when it has one for the cage (before the triangulation is made). */
export function parseObjBytes(bytes: Uint8Array, refuse: (cage: Cage) => string | null = () => null): ParsedFile {
  const loaded = loadCage(decodeText(bytes));
  const why = refuse(loaded.cage);
  if (why) throw new LimitError(why);
  return { ...loaded, flat: triangulateCage(loaded.cage) };
}
