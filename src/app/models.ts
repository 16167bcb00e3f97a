/**
 * Where cages come from: the project's own models (public/models), any URL (`?model=URL`),
 * or a file dropped on the page. Everything ends in `loadCage`, which either gives a valid
 * cage or throws a CageError with line numbers.
 */
import { loadCage, type LoadedCage } from '../mesh/index.ts';

export interface ModelEntry {
  /** File name without `.obj`: what `?model=` takes. */
  name: string;
  /** What the picker shows. */
  label: string;
}

/** The generated models (scripts/models.ts), in the order the picker shows them. */
export const BUILTIN_MODELS: ModelEntry[] = [
  { name: 'creature', label: 'Creature' },
  { name: 'pawn', label: 'Chess pawn' },
  { name: 'creased-box', label: 'Creased box' },
  { name: 'torus', label: 'Torus' },
  { name: 'gear', label: 'Gear' },
  { name: 'icosphere', label: 'Icosphere ball' },
  { name: 'sheet', label: 'Open sheet' },
];

export const DEFAULT_MODEL = 'creature';

const MODELS_DIR = 'models/';

/**
 * The list in `models/index.json` when there is one (an array of names, or of {name, label}),
 * else the built-in list.
 */
export async function fetchModelList(): Promise<ModelEntry[]> {
  try {
    const res = await fetch(`${MODELS_DIR}index.json`);
    if (!res.ok || !(res.headers.get('content-type') ?? '').includes('json')) return BUILTIN_MODELS;
    const json: unknown = await res.json();
    const items = Array.isArray(json) ? json : (json as { models?: unknown[] })?.models;
    if (!Array.isArray(items)) return BUILTIN_MODELS;
    const list = items.flatMap((m): ModelEntry[] => {
      if (typeof m === 'string') return [{ name: m, label: labelFor(m) }];
      if (m && typeof m === 'object' && typeof (m as ModelEntry).name === 'string') {
        const name = (m as ModelEntry).name.replace(/\.obj$/i, '');
        return [{ name, label: typeof (m as ModelEntry).label === 'string' ? (m as ModelEntry).label : labelFor(name) }];
      }
      return [];
    });
    return list.length ? list : BUILTIN_MODELS;
  } catch {
    return BUILTIN_MODELS;
  }
}

function labelFor(name: string): string {
  return BUILTIN_MODELS.find((m) => m.name === name)?.label ?? name.replace(/[-_]/g, ' ').replace(/^./, (c) => c.toUpperCase());
}

export function modelUrl(name: string): string {
  return `${MODELS_DIR}${encodeURIComponent(name)}.obj`;
}

export interface LoadedModel extends LoadedCage {
  /** Shown in the stats and the error messages. */
  title: string;
}

/** Fetch and parse an OBJ. Network and parse failures both come back as Errors with a message fit to show. */
export async function loadModelFromUrl(url: string, title: string): Promise<LoadedModel> {
  let res: Response;
  try {
    res = await fetch(url);
  } catch (e) {
    throw new Error(`could not fetch ${url}: ${(e as Error).message}`);
  }
  if (!res.ok) throw new Error(`could not fetch ${url}: HTTP ${res.status} ${res.statusText}`);
  // Dev servers and SPA hosts answer unknown paths with the index page, not a 404.
  if ((res.headers.get('content-type') ?? '').includes('text/html')) throw new Error(`could not fetch ${url}: not found`);
  const text = await res.text();
  return { ...loadCage(text), title };
}

export async function loadModelFromFile(file: File): Promise<LoadedModel> {
  const text = await file.text();
  return { ...loadCage(text), title: file.name };
}
