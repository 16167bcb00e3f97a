/**
 * The page's messages: the loading state, toasts for recoverable errors (a bad OBJ), the
 * fatal dialog (no WebGPU, a missing feature or limit), in the spirit of webgpu-samples'
 * quitIf… helpers: never a blank page, always a reason and somewhere to go.
 */
import type { GpuProblem } from '../gpu/device/device.ts';
import { escapeControl } from '../mesh/text.ts';

export type PageState = 'loading' | 'ready' | 'error' | 'no-webgpu' | 'lost';

/** The page's state, for styling and for tests to wait on (`body[data-state=ready]`). */
export function setPageState(state: PageState): void {
  document.body.dataset.state = state;
}

export function setLoading(text: string | null): void {
  const box = document.getElementById('loading')!;
  box.hidden = text === null;
  if (text !== null) document.getElementById('loading-text')!.textContent = text;
}

export interface ToastOptions {
  kind?: 'error' | 'info';
  title?: string;
  /** Milliseconds before it goes by itself; errors stay until dismissed. */
  timeout?: number;
}

export function showToast(message: string, options: ToastOptions = {}): HTMLElement {
  const kind = options.kind ?? 'info';
  const toast = document.createElement('div');
  toast.className = `toast ${kind}`;
  toast.setAttribute('role', kind === 'error' ? 'alert' : 'status');
  toast.dataset.testid = `toast-${kind}`;
  if (options.title) {
    const h = document.createElement('strong');
    h.textContent = escapeControl(options.title, { newlines: false });
    toast.append(h);
  }
  const body = document.createElement('pre');
  // Messages quote file names and file text: their control characters and direction overrides shown, not applied.
  body.textContent = escapeControl(message);
  toast.append(body);
  const close = document.createElement('button');
  close.className = 'close';
  close.type = 'button';
  close.setAttribute('aria-label', 'Dismiss');
  close.textContent = '×';
  close.addEventListener('click', () => toast.remove());
  toast.append(close);
  const list = document.getElementById('toasts')!;
  // One error at a time: a new one replaces the old.
  if (kind === 'error') list.querySelectorAll('.toast.error').forEach((t) => t.remove());
  list.append(toast);
  const timeout = options.timeout ?? (kind === 'error' ? 0 : 4000);
  if (timeout > 0) setTimeout(() => toast.remove(), timeout);
  return toast;
}

const HELP_LINKS = `<p class="links">
  <a href="https://caniuse.com/webgpu">Which browsers support WebGPU</a> ·
  <a href="https://github.com/gpuweb/gpuweb/wiki/Implementation-Status">Implementation status</a></p>
  <p>Meanwhile, the <a href="./diagrams/index.html">animated diagrams of the patterns</a> need no WebGPU.</p>`;

const FATAL_TEXT: Record<GpuProblem | 'lost' | 'other', { title: string; html: string }> = {
  'no-webgpu': {
    title: 'WebGPU is not available',
    html: `<p>This demo needs <strong>WebGPU</strong>, and this browser does not provide it
      (<code>navigator.gpu</code> is undefined).</p>
      <ul>
        <li>Chrome and Edge 113+ on Windows, macOS and ChromeOS, and Chrome 121+ on Android, have it.
          On Linux it may still need <code>chrome://flags/#enable-unsafe-webgpu</code> (and Vulkan).</li>
        <li>Firefox 141+ on Windows and Safari 26+ have it.</li>
        <li>WebGPU needs a secure context: <code>https://</code> or <code>http://localhost</code>.</li>
      </ul>${HELP_LINKS}`,
  },
  'no-adapter': {
    title: 'No WebGPU adapter',
    html: `<p>The browser supports WebGPU, but it did not give us a GPU adapter
      (<code>requestAdapter()</code> returned null). The GPU or driver may be blocklisted,
      or hardware acceleration is turned off.</p>
      <p>Check <code>chrome://gpu</code> (or <code>about:support</code>) and make sure hardware
      acceleration is on.</p>${HELP_LINKS}`,
  },
  'missing-feature': {
    title: 'A required WebGPU feature is missing',
    html: `<p>This GPU does not offer a WebGPU feature the demo needs.</p>`,
  },
  limit: {
    title: "This GPU's limits are too small",
    html: `<p>The demo needs larger WebGPU limits than this GPU offers.</p>`,
  },
  'device-failed': {
    title: 'Could not create a WebGPU device',
    html: `<p>The adapter refused to create a device.</p>`,
  },
  lost: {
    title: 'The GPU device was lost',
    html: `<p>The GPU device was lost and could not be recreated. Reloading the page usually helps.</p>`,
  },
  other: {
    title: 'Something went wrong',
    html: `<p>The demo could not start.</p>`,
  },
};

/** The page-blocking dialog: the canvas cannot show anything, so say why and where to look. */
export function showFatal(problem: GpuProblem | 'lost' | 'other', detail?: string): void {
  const text = FATAL_TEXT[problem];
  const dialog = document.getElementById('fatal') as HTMLDialogElement;
  dialog.dataset.problem = problem;
  document.getElementById('fatal-title')!.textContent = text.title;
  const body = document.getElementById('fatal-body')!;
  body.innerHTML = text.html;
  if (detail) {
    const pre = document.createElement('pre');
    pre.textContent = detail;
    body.append(pre);
  }
  if (problem === 'lost' || problem === 'other') {
    const p = document.createElement('p');
    const button = document.createElement('button');
    button.textContent = 'Reload';
    button.addEventListener('click', () => location.reload());
    p.append(button);
    body.append(p);
  }
  setLoading(null);
  setPageState(problem === 'no-webgpu' || problem === 'no-adapter' ? 'no-webgpu' : 'error');
  if (!dialog.open) dialog.showModal();
}
