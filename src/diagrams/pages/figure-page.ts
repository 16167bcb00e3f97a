/** diagrams/line.html and diagrams/triangle.html: one figure, its parameters in the URL. */
import './page.css';
import { reportHeightToParent } from '../embed.ts';
import type { Kind } from '../params.ts';
import { DiagramPlayer } from '../player.ts';

export function mountFigurePage(kind: Kind): DiagramPlayer {
  const query = new URLSearchParams(location.search);
  const embedded = window.parent !== window || ['1', 'true', ''].includes(query.get('embed') ?? 'no');
  document.documentElement.classList.toggle('embedded', embedded);
  const app = document.getElementById('app') as HTMLElement;
  if (!embedded) {
    const nav = document.createElement('nav');
    nav.className = 'site-nav';
    nav.innerHTML = `<a href="./index.html">← All diagrams</a><span class="sep">·</span><a href="./line.html">Line</a><a href="./triangle.html">Triangle</a><a class="home" href="../index.html">tessellab</a>`;
    app.before(nav);
  }
  const setTheme = (p: DiagramPlayer) => (document.documentElement.dataset.theme = p.resolvedTheme());
  const player = new DiagramPlayer({
    kind,
    input: query,
    mount: app,
    styleRoot: document,
    pagesBase: new URL('.', location.href).href,
    headingLevel: embedded ? 2 : 1,
    onParamsChange: (q) => {
      if (!embedded) history.replaceState(null, '', q ? `?${q}` : location.pathname);
      setTheme(current);
    },
  });
  let current = player;
  player.onReplace = (p) => {
    current = p;
    setTheme(p);
  };
  setTheme(player);
  document.title = `${player.root.getAttribute('aria-label')} — tessellab diagrams`;
  if (embedded) reportHeightToParent();
  (window as unknown as { tessDiagram: DiagramPlayer }).tessDiagram = player;
  return player;
}
