/**
 * Parse a user's OBJ file in a worker (src/app/model-worker.ts), so the page stays responsive
 * however large the file: the main thread only receives the finished cage. Where workers are
 * missing (unit tests in Node), the same work runs here.
 */
import { CageError, LimitError } from '../mesh/index.ts';
import type { ParseReply, ParseRequest } from './model-worker.ts';
import { parseObjBytes, type ParsedFile } from './parse-obj.ts';
import { runWorkerOnce } from './worker-once.ts';

export function parseFileOffThread(
  file: File,
  progress: (line: string) => void = () => {},
  fits?: ParseRequest['fits'],
): Promise<ParsedFile> {
  if (typeof Worker === 'undefined') return file.arrayBuffer().then((b) => parseObjBytes(new Uint8Array(b), fits));
  const request: ParseRequest = { file, fits };
  return runWorkerOnce(
    () => new Worker(new URL('./model-worker.ts', import.meta.url), { type: 'module', name: `parse ${file.name}` }),
    request,
    (r: ParseReply) => {
      if ('progress' in r) {
        progress(r.progress);
        return undefined;
      }
      if ('loaded' in r) return r.loaded;
      throw r.issues ? new CageError(r.issues) : r.limit ? new LimitError(r.error) : new Error(r.error);
    },
    (message) => new Error(`could not read ${file.name}: ${message || 'the parser stopped'}`),
  );
}
