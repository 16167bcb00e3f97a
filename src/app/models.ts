/**
 * Where cages come from: the project's own models (public/models), an OBJ on the page's own site
 * (`?model=path`, checked by model-source.ts),
 * or a file dropped on the page. Everything ends in `loadCage`, which either gives a valid
 * cage or throws a CageError with line numbers.
 */
import { decodeText, loadCage, type LoadedCage } from '../mesh/index.ts';
import type { TriangulatedCage } from '../gpu/render/cage-mesh.ts';
import { errorMessage } from './controller.ts';
import { parseFileOffThread } from './parse-off-thread.ts';
import type { ParseRequest } from './model-worker.ts';
import { checkFileSize, MAX_MODEL_FILE_BYTES } from './file-size.ts';

export interface ModelEntry {
  /** File name without `.obj`: what `?model=` takes. */
  name: string;
  /** What the picker shows. */
  label: string;
}

/** The project's models (public/models, written by scripts/models.ts), in the order the picker
 * shows them. The list is fixed at build time, so the page asks the server for no index of them
 * (a request for one that is not there logs an error in the console on every load). */
export const BUILTIN_MODELS: ModelEntry[] = [
  { name: 'creature', label: 'Creature' },
  { name: 'pawn', label: 'Chess pawn' },
  { name: 'creased-box', label: 'Creased box' },
  { name: 'torus', label: 'Torus' },
  { name: 'gear', label: 'Gear' },
  { name: 'icosphere', label: 'Icosphere ball' },
  { name: 'sheet', label: 'Open sheet' },
  // With UVs and a height map (public/models/displaced.json), displaced by the surface pass
  // (src/app/displacement.ts fetches the map with the OBJ).
  { name: 'brick-box', label: 'Brick box (UVs)' },
  { name: 'creature-wrinkles', label: 'Creature (UVs)' },
];

export const DEFAULT_MODEL = 'creature';

const MODELS_DIR = 'models/';

export function modelUrl(name: string): string {
  return `${MODELS_DIR}${encodeURIComponent(name)}.obj`;
}

export interface LoadedModel extends LoadedCage {
  /** Shown in the stats and the error messages. */
  title: string;
  /** A file from the visitor's computer: no link can carry it (the URL and "copy link" say so). */
  localFile?: boolean;
  /** Its flat triangulation, where the worker that read it made it (src/app/model-worker.ts). */
  flat?: TriangulatedCage;
}

/** Fetch and parse an OBJ. Network and parse failures both come back as Errors with a message fit to show. */
export async function loadModelFromUrl(url: string, title: string): Promise<LoadedModel> {
  let res: Response;
  try {
    res = await fetch(url);
  } catch (e) {
    throw new Error(`could not fetch ${url}: ${errorMessage(e)}`);
  }
  if (!res.ok) throw new Error(`could not fetch ${url}: HTTP ${res.status} ${res.statusText}`);
  // Dev servers and SPA hosts answer unknown paths with the index page, not a 404.
  if ((res.headers.get('content-type') ?? '').includes('text/html')) throw new Error(`could not fetch ${url}: not found`);
  // Decoded as the CLIs decode files (UTF-8, or UTF-16 by its byte-order mark).
  const text = decodeText(new Uint8Array(await res.arrayBuffer()));
  return drawable({ ...loadCage(text), title });
}

/** A user's OBJ file: refused from its size before it is read (src/app/file-size.ts), then read
 * and parsed in a worker (src/app/parse-off-thread.ts); `progress` hears what it is doing. */
export async function loadModelFromFile(file: File, progress?: (line: string) => void, fits?: ParseRequest['fits']): Promise<LoadedModel> {
  checkFileSize(file, MAX_MODEL_FILE_BYTES, 'model files');
  return drawable({ ...(await parseFileOffThread(file, progress, fits)), title: file.name, localFile: true });
}

/** A model that loads but would draw nothing is refused with the reason, not shown as an empty
 * view (the loader has already refused coordinates the GPU cannot hold, src/mesh/range.ts). */
function drawable(m: LoadedModel): LoadedModel {
  const holes = new Set(m.cage.holes);
  if (holes.size >= m.topology.nFaces) throw new Error('every face of the model is a hole (t hole): there is nothing to draw');
  return m;
}
