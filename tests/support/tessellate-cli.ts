/**
 * `npm run tessellate` for the CLI tests (tests/gpu/tess/tessellate-cli.node.test.ts,
 * tests/gpu/instanced/instanced-cli.node.test.ts), two ways:
 * - `runCli`: scripts/tessellate-cli.ts `main(argv)` called in this process, its console output
 *   captured, on one device lent for every run of the process (each pipeline compiles once per
 *   device; a run that loses the device gets a new one for the next). The exit code is main's return value, which scripts/vite-run.mjs hands to
 *   process.exit unchanged, and the output is the same console.log / console.error lines. A
 *   spawned process costs Node's start, a Vite server that transforms every module again and a
 *   fresh Dawn; on SwiftShader on a two-core machine that was most of each case's time.
 * - `spawnCli`: the real process, as `npm run tessellate` starts it, for the cases whose claim is
 *   about the process itself (its exit status and what reaches its stdout).
 */
import { spawnSync } from 'node:child_process';
import { vi } from 'vitest';
import { type LentDevice, main } from '../../scripts/tessellate-cli.ts';
import { createNodeDevice } from '../../src/gpu/device/node-device.ts';

export interface CliResult {
  status: number | null;
  stdout: string;
  stderr: string;
}

/** One console call as Node prints it for the strings and numbers the CLI logs. */
const line = (args: unknown[]) => `${args.map((a) => (typeof a === 'string' ? a : String(a))).join(' ')}\n`;

let lent: Promise<LentDevice & { lost: boolean }> | undefined;

/** The device the runs of this process share (unquantised timestamps, as --stats asks). */
async function lentDevice(): Promise<LentDevice> {
  lent ??= createNodeDevice(['disable-dawn-features=timestamp_quantization']).then((d) => {
    const held = { ...d, lost: false };
    d.device.lost.then(() => {
      held.lost = true;
    });
    return held;
  });
  const held = await lent;
  if (!held.lost) return held;
  lent = undefined;
  return lentDevice();
}

export async function runCli(...args: string[]): Promise<CliResult> {
  let stdout = '';
  let stderr = '';
  const log = vi.spyOn(console, 'log').mockImplementation((...a: unknown[]) => {
    stdout += line(a);
  });
  const error = vi.spyOn(console, 'error').mockImplementation((...a: unknown[]) => {
    stderr += line(a);
  });
  try {
    const status = await main(args, await lentDevice());
    return { status, stdout, stderr };
  } finally {
    log.mockRestore();
    error.mockRestore();
  }
}

export function spawnCli(...args: string[]): CliResult {
  const r = spawnSync(process.execPath, ['scripts/vite-run.mjs', 'scripts/tessellate-cli.ts', ...args], {
    encoding: 'utf8',
    timeout: 120_000,
  });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

/** The one JSON line that --stats prints on stdout, parsed. */
// biome-ignore lint/suspicious/noExplicitAny: the stats line's fields are the test's to read
export function statsLine(stdout: string): any {
  return JSON.parse(
    stdout
      .trim()
      .split('\n')
      .filter((l) => l.startsWith('{'))[0],
  );
}
