/**
 * Labels over the two halves of a view drawn twice side by side (the comparison, `compare=`, and
 * the split view, `split=1`), and a line between the halves, so a reader knows which half is
 * which and where one ends. DOM only: the halves themselves are the renderer's regions.
 */
export class SideLabels {
  #els: [HTMLElement, HTMLElement, HTMLElement] | null = null;

  /** `prefix` names the elements' test ids (`${prefix}-left`, `-right`, `-divider`). */
  constructor(private readonly prefix: string) {}

  /** Shown with `text()` (left, right) when `on`, else hidden. */
  show(on: boolean, text: () => [string, string]): void {
    if (!on && !this.#els) return;
    if (!this.#els) {
      const make = (cls: string, id: string) => {
        const el = document.createElement('div');
        el.className = cls;
        el.dataset.testid = `${this.prefix}-${id}`;
        document.body.append(el);
        return el;
      };
      this.#els = [make('side-label left', 'left'), make('side-label right', 'right'), make('side-divider', 'divider')];
    }
    const [left, right, divider] = this.#els;
    left.hidden = right.hidden = divider.hidden = !on;
    if (!on) return;
    [left.textContent, right.textContent] = text();
  }
}
