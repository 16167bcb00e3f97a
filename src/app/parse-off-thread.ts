/**
 * Parse a user's OBJ file in a worker (src/app/model-worker.ts), so the page stays responsive
 * however large the file: the main thread only receives the finished cage. Where workers are
 * missing (unit tests in Node), the same work runs here.
 */
import { CageError } from '../mesh/index.ts';
import type { ParseReply } from './model-worker.ts';
import { parseObjBytes, type ParsedFile } from './parse-obj.ts';

export function parseFileOffThread(file: File, progress: (line: string) => void = () => {}): Promise<ParsedFile> {
  if (typeof Worker === 'undefined') return file.arrayBuffer().then((b) => parseObjBytes(new Uint8Array(b)));
  return new Promise((resolve, reject) => {
    const worker = new Worker(new URL('./model-worker.ts', import.meta.url), { type: 'module', name: `parse ${file.name}` });
    const done = () => worker.terminate();
    worker.onmessage = (e: MessageEvent<ParseReply>) => {
      const r = e.data;
      if ('progress' in r) progress(r.progress);
      else if ('loaded' in r) {
        done();
        resolve(r.loaded);
      } else {
        done();
        reject(r.issues ? new CageError(r.issues) : new Error(r.error));
      }
    };
    worker.onerror = (e) => {
      done();
      reject(new Error(`could not read ${file.name}: ${e.message || 'the parser stopped'}`));
    };
    worker.postMessage({ file });
  });
}
