// End-to-end tests of the pages (e2e/*.spec.ts), in the system Chromium (Playwright never
// downloads a browser here; set CHROMIUM_PATH to use another). The flags give WebGPU and WebGL on
// SwiftShader, so the WebGPU pages run headless too, and canvases appear in screenshots.
// Screenshots: e2e/__screenshots__/<spec file>/<name>.png, compared strictly (2D drawing on
// SwiftShader is deterministic on one machine; give a spec its own tolerance for 3D views).
import { defineConfig, devices } from '@playwright/test';
import { chromiumArgs, chromiumPath } from './chromium-flags.ts';

// E2E_PORT: run beside another server (or another run) on 4173.
const port = Number(process.env.E2E_PORT ?? 4173);

export default defineConfig({
  testDir: './e2e',
  fullyParallel: false,
  // Two workers: a page's time is mostly its pipelines compiling on SwiftShader, one CPU thread
  // per page, so two pages at once use both cores of a CI machine (the suite took 25 min with one).
  workers: 2,
  retries: process.env.CI ? 1 : 0,
  timeout: 60_000,
  forbidOnly: !!process.env.CI,
  reporter: process.env.CI ? 'list' : [['list']],
  snapshotPathTemplate: '{testDir}/__screenshots__/{testFilePath}/{arg}{ext}',
  expect: {
    timeout: 10_000,
    toHaveScreenshot: { maxDiffPixelRatio: 0.002, threshold: 0.1, animations: 'disabled', caret: 'hide' },
  },
  use: {
    baseURL: `http://localhost:${port}`,
    trace: 'retain-on-failure',
  },
  projects: [
    {
      name: 'chromium-swiftshader',
      use: {
        ...devices['Desktop Chrome'],
        viewport: { width: 800, height: 600 },
        deviceScaleFactor: 1,
        launchOptions: {
          executablePath: chromiumPath,
          args: chromiumArgs,
        },
      },
    },
  ],
  webServer: {
    command: `npx vite --port ${port} --strictPort`,
    url: `http://localhost:${port}`,
    reuseExistingServer: !process.env.CI,
    timeout: 60_000,
    stdout: 'ignore',
    stderr: 'pipe',
  },
});
