// The CLIs' file access, checked before any work: an input must be a readable file of bounded
// size, an output's folder must exist and be writable. Every failure is an InputError naming the
// path and what to do, not a Node error code after a long GPU run.
import { accessSync, constants, statSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { decodeText } from '../mesh/text.ts';
import { InputError } from './boundary.ts';

/** The largest input file read (a cage or a height map): 512 MiB. The OBJ reader holds a few
 * times a file's size; beyond this the machine's memory, not the input, decides the outcome. */
export const MAX_INPUT_BYTES = 512 * 1024 * 1024;

function mib(bytes: number): string {
  return `${(bytes / 1024 / 1024).toFixed(1)} MiB`;
}

/** The bytes of an input file, after checking it is one (not a folder, not missing, not huge). */
export function readInputBytes(path: string, what: string, maxBytes = MAX_INPUT_BYTES): Uint8Array {
  let size: number;
  try {
    const st = statSync(path);
    if (st.isDirectory()) throw new InputError(`${what} ${path} is a folder, not a file`);
    if (!st.isFile()) throw new InputError(`${what} ${path} is not a regular file`);
    size = st.size;
  } catch (e) {
    if (e instanceof InputError) throw e;
    throw new InputError(`${what} ${path}: ${fsReason(e)}`);
  }
  if (size > maxBytes) throw new InputError(`${what} ${path} is ${mib(size)}, more than the ${mib(maxBytes)} read`);
  try {
    return readFileSync(path);
  } catch (e) {
    throw new InputError(`${what} ${path}: ${fsReason(e)}`);
  }
}

/** An input text file, decoded as the page decodes it (UTF-8 or UTF-16 by its byte-order mark). */
export function readInputText(path: string, what: string, maxBytes = MAX_INPUT_BYTES): string {
  return decodeText(readInputBytes(path, what, maxBytes));
}

/** Throws unless `path` can be written: its folder exists and is writable, it is not a folder. */
export function checkOutputPath(path: string, what: string): void {
  const dir = dirname(resolve(path));
  try {
    if (!statSync(dir).isDirectory()) throw new InputError(`${what} ${path}: ${dir} is not a folder`);
    accessSync(dir, constants.W_OK);
  } catch (e) {
    if (e instanceof InputError) throw e;
    throw new InputError(`${what} ${path}: the folder ${dir} ${fsReason(e)}`);
  }
  try {
    if (statSync(path).isDirectory()) throw new InputError(`${what} ${path} is a folder, not a file`);
    accessSync(path, constants.W_OK);
  } catch (e) {
    if (e instanceof InputError) throw e;
    if ((e as NodeJS.ErrnoException).code !== 'ENOENT') throw new InputError(`${what} ${path}: ${fsReason(e)}`);
  }
}

/** Write an output file; a failure (disk full, permissions changed) is an InputError. */
export function writeOutput(path: string, text: string, what: string): void {
  try {
    writeFileSync(path, text);
  } catch (e) {
    throw new InputError(`${what} ${path}: ${fsReason(e)}`);
  }
}

/** Node's error codes in words. */
function fsReason(e: unknown): string {
  const code = (e as NodeJS.ErrnoException)?.code;
  switch (code) {
    case 'ENOENT':
      return 'does not exist';
    case 'EACCES':
    case 'EPERM':
      return 'cannot be accessed (permission denied)';
    case 'EISDIR':
      return 'is a folder, not a file';
    case 'ENOTDIR':
      return 'has a file where a folder should be in its path';
    case 'ENOSPC':
      return 'cannot be written: the disk is full';
    case 'EROFS':
      return 'is on a read-only file system';
    case 'ENAMETOOLONG':
      return 'the name is too long';
    default:
      return `cannot be accessed (${code ?? (e as Error)?.message ?? String(e)})`;
  }
}
