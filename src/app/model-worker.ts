/**
 * A user's OBJ file read, decoded, parsed and validated off the page's main thread (a 50 MB file
 * took 37 s there, the tab frozen, before it could be refused). One worker per file
 * (src/app/parse-off-thread.ts starts it and ends it). In: the File. Out: progress lines, then
 * the loaded cage and its flat triangulation (src/app/parse-obj.ts; typed arrays transferred,
 * not copied) or the error: a CageError's issues go back as data, so the page shows the same
 * message with its line numbers.
 */
import { type CageIssue, CageError, LimitError } from '../mesh/index.ts';
import { type DeviceFits, parseObjBytes, type ParsedFile } from './parse-obj.ts';
import { buffersOf } from './transfer.ts';

export type ParseReply = { progress: string } | { loaded: ParsedFile } | { error: string; issues?: CageIssue[]; limit?: boolean };

/** What the page asks: the file, and the device's bounds, so that a cage it cannot hold is refused
 * here from its counts (src/gpu/tess/arenas.ts cageTooLarge) rather than handed over: a cage of a
 * million faces is hundreds of MB of arrays, whose arrival and collection on the page's thread were
 * its longest tasks (180-350 ms on a busy machine) for a model it then refused. */
export interface ParseRequest {
  file: File;
  fits?: DeviceFits;
}

const post = (reply: ParseReply, transfer: Transferable[] = []) => (self as unknown as Worker).postMessage(reply, transfer);

self.onmessage = async (e: MessageEvent<ParseRequest>) => {
  const { file, fits } = e.data;
  try {
    post({ progress: `reading ${file.name}` });
    const bytes = new Uint8Array(await file.arrayBuffer());
    post({ progress: `parsing ${file.name}` });
    const loaded = parseObjBytes(bytes, fits);
    post({ loaded }, [...buffersOf(loaded)]);
  } catch (err) {
    if (err instanceof CageError) post({ error: err.message, issues: err.issues });
    else if (err instanceof LimitError) post({ error: err.message, limit: true });
    else post({ error: err instanceof Error ? err.message : String(err) });
  }
};
