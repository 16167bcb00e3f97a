/**
 * Sizing an iframe to its figure without a library: the page inside posts its height, the page
 * outside sets the iframe's height. Message: { type: 'tessellab:resize', height } (CSS pixels).
 */

export const RESIZE_MESSAGE = 'tessellab:resize';

/** Inside the iframe: report the document's height now and whenever it changes. */
export function reportHeightToParent(win: Window = window): () => void {
  if (win.parent === win) return () => {};
  let last = -1;
  const send = () => {
    const h = Math.ceil(win.document.documentElement.getBoundingClientRect().height);
    if (h === last) return;
    last = h;
    win.parent.postMessage({ type: RESIZE_MESSAGE, height: h }, '*');
  };
  const ro = new ResizeObserver(send);
  ro.observe(win.document.documentElement);
  send();
  return () => ro.disconnect();
}

/** Outside: size every iframe that reports its height. The same code as the snippet in the README. */
export function listenForDiagramHeights(win: Window = window): () => void {
  const onMessage = (e: MessageEvent) => {
    const d = e.data as { type?: unknown; height?: unknown } | null;
    if (!d || d.type !== RESIZE_MESSAGE || typeof d.height !== 'number' || !(d.height > 0)) return;
    for (const f of Array.from(win.document.getElementsByTagName('iframe'))) {
      if (f.contentWindow === e.source) f.style.height = `${Math.min(d.height, 10_000)}px`;
    }
  };
  win.addEventListener('message', onMessage);
  return () => win.removeEventListener('message', onMessage);
}
