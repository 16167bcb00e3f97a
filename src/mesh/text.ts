// Text from files, the same in the CLIs and the page: how bytes become a string (decodeText) and
// how file-derived text is made safe to echo to a terminal or a page (escapeControl).
import { CageError } from './errors.ts';

/** How much of a file's start is looked at to tell text from binary (as git does: 8000 bytes). */
const SNIFF_BYTES = 8000;

/**
 * Decode a text file's bytes: a UTF-8 byte-order mark is dropped, a UTF-16 one (LE or BE) selects
 * UTF-16, anything else is UTF-8 (invalid sequences become U+FFFD, so the parser names the line
 * instead of the decoder failing). Editors on Windows save OBJ files as UTF-16 with a BOM.
 * A file that is not text (a NUL byte in its first 8000 bytes, or mostly bytes that are not
 * UTF-8 there: an image, an archive, a binary mesh) is refused in one line rather than parsed
 * into lines of garbage.
 */
export function decodeText(bytes: Uint8Array): string {
  const b = bytes;
  if (b.length >= 2 && b[0] === 0xff && b[1] === 0xfe) return new TextDecoder('utf-16le').decode(b.subarray(2));
  if (b.length >= 2 && b[0] === 0xfe && b[1] === 0xff) return new TextDecoder('utf-16be').decode(b.subarray(2));
  const body = b.length >= 3 && b[0] === 0xef && b[1] === 0xbb && b[2] === 0xbf ? b.subarray(3) : b;
  refuseBinary(body);
  return new TextDecoder('utf-8').decode(body);
}

function refuseBinary(b: Uint8Array): void {
  const head = b.subarray(0, SNIFF_BYTES);
  const notText = (why: string) => new CageError([{ line: 0, message: `not a text OBJ file: ${why}` }]);
  if (head.includes(0)) throw notText('it has NUL bytes, as binary files do (or UTF-16 text without its byte-order mark)');
  // Latin-1 comments make a few invalid sequences; a binary file makes them everywhere.
  const decoded = new TextDecoder('utf-8').decode(head);
  let invalid = 0;
  for (const c of decoded) if (c === '\uFFFD') invalid++;
  if (invalid > 16 && invalid > decoded.length / 10)
    throw notText(`${invalid} of its first ${decoded.length} characters are not UTF-8 text`);
}

// C0 controls but tab and newline, DEL, C1 controls (U+009B is a one-character CSI on some
// terminals), line and paragraph separators and the bidirectional overrides and isolates (which
// reorder what a reader sees).
// biome-ignore lint/suspicious/noControlCharactersInRegex: finding control characters is its purpose
const CONTROL = /[\u0000-\u0008\u000b-\u001f\u007f-\u009f\u2028\u2029\u202a-\u202e\u2066-\u2069]/g;

/**
 * `s` with every character that could drive a terminal or reorder text shown as `\xNN` or
 * `\uNNNN`: a hostile file's ESC [2J or OSC title sequence is printed, not obeyed. Tab and
 * newline are kept (messages are lines); pass `{ newlines: false }` for one-line text.
 */
export function escapeControl(s: string, o: { newlines?: boolean } = {}): string {
  const out = s.replace(CONTROL, (c) => {
    const code = c.charCodeAt(0);
    return code < 0x100 ? `\\x${code.toString(16).padStart(2, '0')}` : `\\u${code.toString(16).padStart(4, '0')}`;
  });
  return o.newlines === false ? out.replace(/\n/g, '\\n').replace(/\t/g, '\\t') : out;
}
