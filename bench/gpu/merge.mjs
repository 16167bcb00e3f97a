#!/usr/bin/env node
// `node bench/gpu/merge.mjs DIR [BENCHMARKS.md]`: take bench/gpu/run.sh's output (DIR: bench-gpu.md,
// inst.md, inst-cc.md, gpu.txt) into BENCHMARKS.md as one section, "## On a real GPU", replacing the
// one there. Each run's "## " sections become "### " subsections, as the scripts wrote them.
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

const [dir, target = 'BENCHMARKS.md'] = process.argv.slice(2);
if (!dir) {
  console.error('usage: node bench/gpu/merge.mjs DIR [BENCHMARKS.md]');
  process.exit(2);
}
const HEADING = '## On a real GPU';
const read = (f) => (existsSync(join(dir, f)) ? readFileSync(join(dir, f), 'utf8') : '');
const demote = (doc) =>
  doc
    .replace(/^# Benchmarks\n+/m, '')
    .replace(/^## /gm, '### ')
    .trim();
const gpu = read('gpu.txt').trim().split('\n').slice(1).join('; ');
const acc = read('acc.md').trim();
const parts = ['bench-gpu.md', 'inst.md', 'inst-cc.md'].map(read).filter(Boolean).map(demote);
if (acc)
  parts.push(`### Approximate Catmull-Clark: the ACC patch build against the exact one

\`scripts/acc-errors.ts\` as in the ACC section above (its error columns are CPU, f64, and do not
depend on the machine); the build column is this GPU's.

${acc}`);
if (!parts.length) {
  console.error(`merge: nothing in ${dir}`);
  process.exit(1);
}
const section = `${HEADING}

\`bash bench/gpu/run.sh\` on a machine with one GPU${gpu ? ` (nvidia-smi: ${gpu})` : ''}, after
\`bash bench/gpu/pack.sh\` here: the same benchmark scripts as above, bundled, run by Node 20 through
the webgpu package (Dawn on Vulkan). The CPU columns (preparation, OpenSubdiv) are that machine's CPU.

${parts.join('\n\n')}
`;
const doc = readFileSync(target, 'utf8');
const kept = doc.split(/^(?=## )/m).filter((p) => !p.startsWith(HEADING));
writeFileSync(target, `${kept.join('').trimEnd()}\n\n${section}`);
console.log(`${HEADING}: written to ${target}`);
