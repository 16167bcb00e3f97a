// Multi-page build: the demo at index.html and every HTML page under diagrams/.
import { defineConfig } from 'vite';
import { readdirSync, existsSync } from 'node:fs';
import { resolve } from 'node:path';

const root = import.meta.dirname;

function pages(): Record<string, string> {
  const input: Record<string, string> = { main: resolve(root, 'index.html') };
  const dir = resolve(root, 'diagrams');
  if (existsSync(dir)) {
    for (const f of readdirSync(dir)) {
      if (f.endsWith('.html')) input[`diagrams/${f.slice(0, -5)}`] = resolve(dir, f);
    }
  }
  return input;
}

export default defineConfig({
  base: './',
  build: {
    target: 'es2022',
    rollupOptions: { input: pages() },
  },
});
