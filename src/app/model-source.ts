/**
 * Where `?model=` may point: one of the project's models by name, or an OBJ on this page's own
 * site (a relative path, or an absolute URL of the same origin). Anything else is refused with
 * a reason, never fetched: a link must not make a visitor's browser request another site, a
 * loopback port or a `data:` payload of the link's choosing. Pure, so unit-tested without a browser.
 */

export type ModelSource = { kind: 'builtin'; name: string } | { kind: 'url'; url: string } | { kind: 'refused'; reason: string };

/** A model parameter that names a file rather than one of the project's models. */
export function isModelUrl(model: string): boolean {
  return /[/.:]/.test(model);
}

/** What `?model=` asks for, resolved against the page's own URL. */
export function modelSource(model: string, pageUrl: string): ModelSource {
  if (!isModelUrl(model)) return { kind: 'builtin', name: model };
  let url: URL;
  let page: URL;
  try {
    page = new URL(pageUrl);
    url = new URL(model, page);
  } catch {
    return { kind: 'refused', reason: `the model link '${shown(model)}' is not a valid address` };
  }
  if (url.protocol !== 'http:' && url.protocol !== 'https:')
    return { kind: 'refused', reason: `the model link uses '${shown(url.protocol)}': only files on this site are loaded from a link` };
  if (url.origin !== page.origin)
    return {
      kind: 'refused',
      reason: `the model link points to another site (${shown(url.origin)}): only files on this site are loaded from a link; download the OBJ and drop it on the page instead`,
    };
  return { kind: 'url', url: url.href };
}

/** A link's text cut short for a message (textContent shows it as text, never as markup). */
function shown(s: string): string {
  return s.length > 60 ? `${s.slice(0, 57)}...` : s;
}
