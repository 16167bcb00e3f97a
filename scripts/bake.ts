/**
 * `npm run bake [-- --out DIR] [--max 64,128,256] [--dry-run]`: bake the pattern tables
 * (src/pattern/tables.ts) into DIR (default public/tables, ignored by git: tables are derived,
 * never edited) and print their sizes: for engines that want the binary files. The demo and the
 * headless tools bake them in memory at start-up (bakeTables, ~30 ms at max factor 64).
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { bakeTables, PatternTables } from '../src/pattern/tables.ts';

function arg(name: string): string | undefined {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : undefined;
}

const out = arg('--out') ?? 'public/tables';
const maxes = (arg('--max') ?? '64,128,256').split(',').map(Number);
const write = !process.argv.includes('--dry-run');
if (write) mkdirSync(out, { recursive: true });
console.log('max factor | slots | states | bytes      | MB');
console.log('-----------|-------|--------|------------|------');
for (const m of maxes) {
  const words = bakeTables(m);
  const t = new PatternTables(words);
  const bytes = words.byteLength;
  console.log(
    `${String(m).padStart(10)} | ${String(t.slotCount).padStart(5)} | ${String(t.stateCount).padStart(6)} | ${String(bytes).padStart(10)} | ${(bytes / 1e6).toFixed(2)}`,
  );
  if (write) writeFileSync(join(out, `hable-${m}.bin`), new Uint8Array(words.buffer));
}
if (write) console.log(`written to ${out}/hable-{${maxes.join(',')}}.bin`);
