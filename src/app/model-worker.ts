/**
 * A user's OBJ file read, decoded, parsed and validated off the page's main thread (a 50 MB file
 * took 37 s there, the tab frozen, before it could be refused). One worker per file
 * (src/app/parse-off-thread.ts starts it and ends it). In: the File. Out: progress lines, then
 * the loaded cage (its typed arrays transferred, not copied) or the error: a CageError's issues
 * go back as data, so the page shows the same message with its line numbers.
 */
import { type CageIssue, CageError, decodeText, type LoadedCage, loadCage } from '../mesh/index.ts';

export type ParseReply = { progress: string } | { loaded: LoadedCage } | { error: string; issues?: CageIssue[] };

const post = (reply: ParseReply, transfer: Transferable[] = []) => (self as unknown as Worker).postMessage(reply, transfer);

/** Every ArrayBuffer under `x` (typed arrays of the cage and its topology), once each. */
function buffersOf(x: unknown, out = new Set<ArrayBuffer>()): Set<ArrayBuffer> {
  if (ArrayBuffer.isView(x)) {
    if (x.buffer instanceof ArrayBuffer) out.add(x.buffer);
  } else if (x && typeof x === 'object') for (const v of Object.values(x)) buffersOf(v, out);
  return out;
}

self.onmessage = async (e: MessageEvent<{ file: File }>) => {
  const file = e.data.file;
  try {
    post({ progress: `reading ${file.name}` });
    const bytes = new Uint8Array(await file.arrayBuffer());
    post({ progress: `parsing ${file.name}` });
    const loaded = loadCage(decodeText(bytes));
    post({ loaded }, [...buffersOf(loaded)]);
  } catch (err) {
    if (err instanceof CageError) post({ error: err.message, issues: err.issues });
    else post({ error: err instanceof Error ? err.message : String(err) });
  }
};
