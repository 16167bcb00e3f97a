/**
 * The pattern CLI, for people and for checks (see README):
 *
 *   npm run pattern -- line --mode hable --factor 10.3 [--json] [--fixed] [--max-factor 64]
 *   npm run pattern -- line --mode hable --sweep 1,64,0.001            (one JSON object per line)
 *   npm run pattern -- tri --mode clamped --factors 3.5,7,12 [--reverse 0,1,0] [--json]
 *   npm run pattern -- tri --mode fractional_even --factors 16,16,16 --inside 16 --json
 *   npm run pattern -- tri --mode clamped --factors-file F             (`f0,f1,f2[,inside][;r0,r1,r2]` per line)
 *
 * Points are printed as numbers in [0, 1] (exact: every coordinate is k/2^16), or as the
 * fixed-point integers k with --fixed. Bad arguments: a message on stderr and exit code 2.
 */
import { endQuietlyOnClosedPipe, guardedSync } from '../src/cli/boundary.ts';
import { readInputText } from '../src/cli/files.ts';
import { runPatternCli } from '../src/pattern/cli.ts';

/** The CLI in the project's error boundary (src/cli/boundary.ts): exit 2 for bad input, never a trace. */
export function main(argv: string[]): number {
  return guardedSync('pattern', argv, (a) => {
    const result = runPatternCli(a, (path) => readInputText(path, 'file'));
    if (result.stdout) process.stdout.write(result.stdout);
    if (result.stderr) process.stderr.write(result.stderr);
    return result.code;
  });
}

const isMain = process.argv[1] && /pattern-cli\.ts$/.test(process.argv[1]);
if (isMain) {
  endQuietlyOnClosedPipe();
  process.exitCode = main(process.argv.slice(2));
}
