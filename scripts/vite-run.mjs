#!/usr/bin/env node
// Run a TypeScript module that imports WGSL with `?raw` (which plain Node and tsx cannot
// load) through Vite's module runner, then call its exported `main(argv)`; its return value
// is the exit code. Used by `npm run tessellate` and `npm run bench`.
import { createServer, createServerModuleRunner } from 'vite';
import { fileURLToPath } from 'node:url';
import { resolve } from 'node:path';

const [entry, ...args] = process.argv.slice(2);
if (!entry) {
  console.error('usage: node scripts/vite-run.mjs MODULE.ts [args...]');
  process.exit(2);
}
// A reader that stops early (`| head`) closes the pipe: end quietly, not with an EPIPE trace
// (src/cli/boundary.ts endQuietlyOnClosedPipe, for the CLIs that tsx runs).
for (const stream of [process.stdout, process.stderr])
  stream.on('error', (e) => {
    if (e.code === 'EPIPE') process.exit(0);
    throw e;
  });
const root = resolve(fileURLToPath(import.meta.url), '../..');
const server = await createServer({
  configFile: false,
  root,
  logLevel: 'error',
  appType: 'custom',
  server: { middlewareMode: true, hmr: false, ws: false },
});
const runner = createServerModuleRunner(server.environments.ssr, { hmr: false });
let code = 1;
try {
  const mod = await runner.import(resolve(process.cwd(), entry));
  code = (await mod.main(args)) ?? 0;
} catch (e) {
  console.error(e instanceof Error ? e.stack : e);
  code = 1;
} finally {
  await runner.close();
  await server.close();
}
process.exit(code);
