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
import { readFileSync } from 'node:fs';
import { runPatternCli } from '../src/pattern/cli.ts';

const result = runPatternCli(process.argv.slice(2), (path) => readFileSync(path, 'utf8'));
if (result.stdout) process.stdout.write(result.stdout);
if (result.stderr) process.stderr.write(result.stderr);
process.exitCode = result.code;
