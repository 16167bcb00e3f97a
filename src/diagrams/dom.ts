/**
 * The little DOM the diagram player builds with: its stylesheet, injected once per document or
 * shadow root, an element factory (h), and the play and pause icons.
 */
import cssText from './figure.css?inline';

const styled = new WeakSet<Document | ShadowRoot>();
export function injectStyle(root: Document | ShadowRoot): void {
  if (styled.has(root)) return;
  styled.add(root);
  const style = document.createElement('style');
  style.textContent = cssText;
  if (root instanceof Document) root.head.append(style);
  else root.prepend(style);
}

export type Attrs = Record<string, string | number | boolean | undefined>;
export function h<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  attrs: Attrs = {},
  ...children: (Node | string | null | undefined)[]
): HTMLElementTagNameMap[K] {
  const el = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === false) continue;
    if (k === 'class') el.className = String(v);
    else if (k === 'text') el.textContent = String(v);
    else el.setAttribute(k, v === true ? '' : String(v));
  }
  for (const c of children) if (c !== null && c !== undefined) el.append(c);
  return el;
}

export const ICON_PLAY =
  '<svg width="12" height="12" viewBox="0 0 12 12" aria-hidden="true"><path d="M2 1l9 5-9 5z" fill="currentColor"/></svg>';
export const ICON_PAUSE =
  '<svg width="12" height="12" viewBox="0 0 12 12" aria-hidden="true"><path d="M2 1h3v10H2zM7 1h3v10H7z" fill="currentColor"/></svg>';
