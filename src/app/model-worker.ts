/**
 * A user's OBJ file read, decoded, parsed and validated off the page's main thread (a 50 MB file
 * took 37 s there, the tab frozen, before it could be refused). One worker per file
 * (src/app/parse-off-thread.ts starts it and ends it). In: the File. Out: progress lines, then
 * the loaded cage and its flat triangulation (src/app/parse-obj.ts; typed arrays transferred,
 * not copied) or the error: a CageError's issues go back as data, so the page shows the same
 * message with its line numbers.
 */
import { type CageIssue, CageError } from '../mesh/index.ts';
import { parseObjBytes, type ParsedFile } from './parse-obj.ts';
import { buffersOf } from './transfer.ts';

export type ParseReply = { progress: string } | { loaded: ParsedFile } | { error: string; issues?: CageIssue[] };

const post = (reply: ParseReply, transfer: Transferable[] = []) => (self as unknown as Worker).postMessage(reply, transfer);

self.onmessage = async (e: MessageEvent<{ file: File }>) => {
  const file = e.data.file;
  try {
    post({ progress: `reading ${file.name}` });
    const bytes = new Uint8Array(await file.arrayBuffer());
    post({ progress: `parsing ${file.name}` });
    const loaded = parseObjBytes(bytes);
    post({ loaded }, [...buffersOf(loaded)]);
  } catch (err) {
    if (err instanceof CageError) post({ error: err.message, issues: err.issues });
    else post({ error: err instanceof Error ? err.message : String(err) });
  }
};
