// The system Chromium and the flags that give it WebGPU and WebGL on SwiftShader (headless
// canvases included), shared by the browser test project (vitest.config.ts) and the end-to-end
// tests (playwright.config.ts). Set CHROMIUM_PATH to use another Chromium.
export const chromiumPath = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';

export const chromiumArgs = [
  '--enable-unsafe-webgpu',
  '--enable-features=Vulkan',
  '--use-vulkan=swiftshader',
  '--use-webgpu-adapter=swiftshader',
  '--use-angle=swiftshader',
  '--no-sandbox',
];
