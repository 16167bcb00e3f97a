// The error boundary every CLI entry point (tessellate, subdiv, pattern, bench) runs inside: a
// failure becomes one line in the user's terms and an exit code, never a stack trace.
//
// Exit codes: 0 done; 2 the input (arguments, files, the model) cannot be used, and the message
// says why; 1 an internal error (a bug, not the input): its message, and its trace with --debug.
import { AccError } from '../subdiv/acc.ts';
import { CageError, LimitError } from '../mesh/errors.ts';
import { escapeControl } from '../mesh/text.ts';

export const EXIT_OK = 0;
export const EXIT_INTERNAL = 1;
export const EXIT_BAD_INPUT = 2;

/** Bad input found by a CLI (an argument, a file, a size): its message is what the user reads. */
export class InputError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'InputError';
  }
}

/** Errors whose message is written for the user: the input's fault, exit 2. HeightMapError (Node
 * only, src/mesh/heightmap-png.ts) is matched by name so this file stays free of pngjs. */
export function isInputError(e: unknown): e is Error {
  return (
    e instanceof InputError ||
    e instanceof CageError ||
    e instanceof LimitError ||
    e instanceof AccError ||
    (e instanceof Error && (e.name === 'HeightMapError' || e.name === 'UsageError'))
  );
}

/** Where a boundary writes (stderr by default; the tests capture it). */
export type Write = (line: string) => void;

/**
 * The message for a failure and its exit code. Input errors keep their (multi-line, line-numbered)
 * message; anything else is reported as internal, its first line only, the trace with `debug`.
 * Every character that could drive a terminal is escaped: messages quote the user's files.
 */
export function describeFailure(program: string, e: unknown, debug: boolean): { text: string; code: number } {
  const message = e instanceof Error ? e.message : String(e);
  if (isInputError(e)) return { text: escapeControl(`${program}: ${message}`), code: EXIT_BAD_INPUT };
  const first = message.split('\n')[0];
  const hint = outOfMemory(e) ? 'the input is too large for this machine' : 'a bug in tessellab, not in the input; please report it';
  const trace = debug && e instanceof Error && e.stack ? `\n${e.stack}` : debug ? '' : ' (--debug prints the trace)';
  return { text: escapeControl(`${program}: internal error: ${first} (${hint})${trace}`), code: EXIT_INTERNAL };
}

/** V8's own "too large" failures: a string or array past its engine limit. */
function outOfMemory(e: unknown): boolean {
  return e instanceof RangeError && /Invalid (string|array|typed array) length|Array buffer allocation failed/.test(e.message);
}

/**
 * Run a CLI's body inside the boundary: its return value is the exit code, or the failure's.
 * `--debug` in argv (taken out before the body sees it) adds the trace to an internal error.
 */
export async function guarded(
  program: string,
  argv: string[],
  body: (argv: string[]) => number | Promise<number>,
  write: Write = (line) => process.stderr.write(`${line}\n`),
): Promise<number> {
  const debug = argv.includes('--debug');
  try {
    return await body(argv.filter((a) => a !== '--debug'));
  } catch (e) {
    const { text, code } = describeFailure(program, e, debug);
    write(text);
    return code;
  }
}

/** The same, for a synchronous body (the subdiv and pattern CLIs, whose tests call them directly). */
export function guardedSync(
  program: string,
  argv: string[],
  body: (argv: string[]) => number,
  write: Write = (line) => process.stderr.write(`${line}\n`),
): number {
  const debug = argv.includes('--debug');
  try {
    return body(argv.filter((a) => a !== '--debug'));
  } catch (e) {
    const { text, code } = describeFailure(program, e, debug);
    write(text);
    return code;
  }
}

/**
 * A reader that stops early (`| head`) closes the pipe: the next write fails with EPIPE, which Node
 * raises as an unhandled 'error' event with a trace. The output was not wanted any more, so the
 * process ends quietly, as a command killed by SIGPIPE does in a shell pipeline.
 */
export function endQuietlyOnClosedPipe(): void {
  for (const stream of [process.stdout, process.stderr])
    stream.on('error', (e: NodeJS.ErrnoException) => {
      if (e.code === 'EPIPE') process.exit(0);
      throw e;
    });
}
