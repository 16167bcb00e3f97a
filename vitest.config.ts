// `npm test` runs the `unit` project only: pure TypeScript, no GPU, no browser.
// `npm run test:gpu` runs the WGSL checks in Node (Dawn via the `webgpu` package on
// SwiftShader) and in headless Chromium; it needs the Debian `chromium` package.
import { defineConfig } from 'vitest/config';
import { playwright } from '@vitest/browser-playwright';
import { chromiumArgs, chromiumPath } from './chromium-flags.ts';

const icd = process.env.VK_ICD_FILENAMES ?? '/usr/lib/chromium/vk_swiftshader_icd.json';

export default defineConfig({
  test: {
    projects: [
      {
        test: {
          name: 'unit',
          environment: 'node',
          include: ['tests/**/*.test.ts', 'src/**/*.test.ts'],
          exclude: ['**/*.gpu.test.ts', '**/*.browser.test.ts', '**/*.node.test.ts', '**/node_modules/**'],
          testTimeout: 60_000,
        },
      },
      {
        test: {
          name: 'gpu-node',
          pool: 'forks',
          env: { VK_ICD_FILENAMES: icd },
          include: ['tests/**/*.gpu.test.ts', 'tests/**/*.node.test.ts'],
          testTimeout: 120_000,
          fileParallelism: false,
        },
      },
      {
        test: {
          name: 'gpu-browser',
          include: ['tests/**/*.gpu.test.ts', 'tests/**/*.browser.test.ts'],
          testTimeout: 120_000,
          fileParallelism: false,
          browser: {
            enabled: true,
            headless: true,
            instances: [{ browser: 'chromium' }],
            provider: playwright({
              launchOptions: {
                executablePath: chromiumPath,
                args: chromiumArgs,
              },
            }),
          },
        },
      },
    ],
  },
});
