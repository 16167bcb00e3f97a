/**
 * The page's caps on a user's file, checked from `File.size` before a byte of it is read: a
 * file is read whole (then decoded, then parsed), so without a cap a multi-gigabyte drop would
 * take the tab's memory before any message could say why. Refused, the file is never read and
 * what the page shows stays.
 */

const MIB = 1024 * 1024;

/** The largest OBJ the page reads: 256 MiB (about 4 M quads of text). The page holds the file's
 * bytes, its decoded text and the parsed cage at once, a few times the file's size in all; the
 * GPU's binding limit refuses cages far smaller than this anyway. (The CLIs, with no tab's heap
 * to share, read up to 512 MiB: src/cli/files.ts.) */
export const MAX_MODEL_FILE_BYTES = 256 * MIB;

/** The largest height-map PNG the page reads: 256 MiB. A map at the pixel cap (8192², one
 * 16-bit channel) stored with no compression at all is ~128 MiB; twice that leaves room for
 * colour PNGs, and the pixel cap still applies after decoding. */
export const MAX_HEIGHT_MAP_FILE_BYTES = 256 * MIB;

function mib(bytes: number): string {
  return `${(bytes / MIB).toFixed(1)} MiB`;
}

/** Throws an Error in the user's terms when `file` is larger than `maxBytes`; `what` names the
 * kind of file ("model files", "height maps"). Reads nothing: only the size the browser reports. */
export function checkFileSize(file: { name: string; size: number }, maxBytes: number, what: string): void {
  if (file.size > maxBytes)
    throw new Error(`${file.name} is ${mib(file.size)}: the page reads ${what} of up to ${mib(maxBytes)}, so it was not opened.`);
}
