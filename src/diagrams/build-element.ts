/**
 * Builds the <tess-diagram> element as ONE file with a stable name, for blogs:
 *
 *   npm run build && npx tsx src/diagrams/build-element.ts [outDir]   → dist/diagrams/tess-diagram.js
 *
 * The site build (vite.config.ts) names its chunks by content hash, which a blog cannot link to;
 * this library build puts the element, the pattern code and the styles in `tess-diagram.js`
 * (the video and GIF encoders stay in chunks beside it, loaded only on export). The element's
 * share links then point at the pages in the same folder.
 */
import { resolve } from 'node:path';
import { build } from 'vite';

const root = resolve(import.meta.dirname, '../..');
process.env.VITE_TESS_DIAGRAMS_BASE = './';

await build({
  configFile: false,
  root,
  logLevel: 'warn',
  publicDir: false,
  build: {
    outDir: resolve(process.argv[2] ?? resolve(root, 'dist/diagrams')),
    emptyOutDir: false,
    target: 'es2022',
    minify: true,
    lib: { entry: resolve(root, 'src/diagrams/element.ts'), formats: ['es'], fileName: () => 'tess-diagram.js' },
    rollupOptions: { output: { chunkFileNames: 'tess-diagram-[name]-[hash].js' } },
  },
});
console.log(`${process.argv[2] ?? 'dist/diagrams'}/tess-diagram.js`);
