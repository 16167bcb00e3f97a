// The site and the <tess-diagram> element are served from whatever folder they are copied to (a
// project page, a blog's assets): every URL they build is relative. Vite accepts only './' (or ''
// or an absolute URL) as a relative base and warns, then writes broken asset paths, for anything
// else; the element's share links resolve its base against its own URL. A path rewrite once
// turned all three into './/' and no other test noticed.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import config from '../../vite.config.ts';

describe('relative bases', () => {
  it("the site build's base is './'", () => {
    expect((config as { base?: string }).base).toBe('./');
  });

  it("the element build points its share links at the pages beside it ('./'), and the site's copy at ../diagrams/", () => {
    const build = readFileSync(new URL('../../src/diagrams/build-element.ts', import.meta.url), 'utf8');
    expect(build).toMatch(/process\.env\.VITE_TESS_DIAGRAMS_BASE = '\.\/';/);
    const element = readFileSync(new URL('../../src/diagrams/element.ts', import.meta.url), 'utf8');
    expect(element).toContain("VITE_TESS_DIAGRAMS_BASE ?? '../diagrams/'");
    expect(element).not.toMatch(/'\.\/\/'/);
  });
});
