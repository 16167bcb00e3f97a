/**
 * The demo's controller (src/app/controller.ts) without a GPU or a page: fake models, a fake
 * surface-data step whose answers the test releases in any order, and a fake upload that records
 * what would be on the GPU. The rules under test: one flow (model → surface data → upload →
 * commit), the latest request wins, a failure changes nothing, Catmull-Clark falls back to Phong.
 */
import { describe, expect, it } from 'vitest';
import { CageError } from '../../src/mesh/index.ts';
import { DemoController, errorMessage, type DemoControllerOptions, type DemoPorts } from '../../src/app/controller.ts';
import type { Surface } from '../../src/app/params.ts';

interface Model {
  title: string;
}
interface Data {
  of: string;
}

/** A promise the test settles when it wants. */
function deferred<T>() {
  let resolve!: (v: T) => void;
  let reject!: (e: unknown) => void;
  const promise = new Promise<T>((res, rej) => {
    resolve = res;
    reject = rej;
  });
  return { promise, resolve, reject };
}

/** Let every settled promise's continuations run. */
const flush = () => new Promise((r) => setTimeout(r, 0));

function harness(surface: Surface = 'catmull-clark', options: DemoControllerOptions = {}) {
  const log: string[] = [];
  const pending = new Map<string, ReturnType<typeof deferred<Data>>>();
  const ready = new Set<string>();
  /** Titles whose surface data is refused, and titles whose Catmull-Clark / any upload throws. */
  const refuse = new Set<string>();
  const ccUploadFails = new Set<string>();
  const uploadFails = new Set<string>();
  let gpu: { model: string; surface: Surface; data: string | null } | null = null;
  let busy = false;
  const ports: DemoPorts<Model, Data, string> = {
    prepareSurface(model) {
      log.push(`prepare ${model.title}`);
      if (refuse.has(model.title)) return Promise.reject(new Error(`no tables for ${model.title}`));
      if (ready.has(model.title)) return Promise.resolve({ of: model.title });
      const d = deferred<Data>();
      pending.set(model.title, d);
      return d.promise;
    },
    surfaceReady: (model) => ready.has(model.title),
    upload(model, s, data) {
      log.push(`upload ${model.title} ${s}${data ? ` +${data.of}` : ''}`);
      if (uploadFails.has(model.title) || (s === 'catmull-clark' && ccUploadFails.has(model.title))) {
        throw new Error(`cannot upload ${model.title} as ${s}`);
      }
      expect(s === 'catmull-clark').toBe(data !== null);
      gpu = { model: model.title, surface: s, data: data?.of ?? null };
    },
    loading: (m, surface) => log.push(`loading ${m}${surface ? ' (the surface)' : ''}`),
    preparing: (b) => {
      busy = b;
    },
    failed: (title, message) => log.push(`failed ${title}: ${message}`),
    fellBack: (model, reason) => log.push(`fell back ${model.title}: ${reason}`),
    shown: (model, previous, placement) => log.push(`shown ${model.title} (was ${previous?.title ?? 'none'}) ${placement ?? '-'}`),
  };
  const c = new DemoController<Model, Data, string>(ports, surface, options);
  const release = (title: string) => {
    ready.add(title);
    pending.get(title)!.resolve({ of: title });
  };
  return { c, log, refuse, ccUploadFails, uploadFails, release, gpu: () => gpu, busy: () => busy };
}

const model = (title: string) => () => Promise.resolve({ title });

describe('DemoController', () => {
  it('one flow: model, then its surface data, then the upload, then the page is told', async () => {
    const h = harness();
    const done = h.c.loadModel(model('torus'), 'torus', 'place-torus');
    await flush();
    expect(h.busy()).toBe(true);
    expect(h.c.model).toBeNull(); // nothing changes before the data is there
    h.release('torus');
    expect(await done).toBe(true);
    expect(h.log).toEqual([
      'loading Loading torus…',
      'loading Preparing subdivision data… (the surface)',
      'prepare torus',
      'upload torus catmull-clark +torus',
      'shown torus (was none) place-torus',
    ]);
    expect(h.busy()).toBe(false);
    expect(h.c.model?.title).toBe('torus');
    expect(h.c.shownSurface).toBe('catmull-clark');
    expect(h.c.data).toEqual({ of: 'torus' });
    expect(h.gpu()).toEqual({ model: 'torus', surface: 'catmull-clark', data: 'torus' });
  });

  it('the latest request wins: an earlier model whose data comes last is dropped', async () => {
    const h = harness();
    const first = h.c.loadModel(model('creature'), 'creature');
    await flush();
    const second = h.c.loadModel(model('torus'), 'torus');
    await flush();
    h.release('torus');
    expect(await second).toBe(true);
    h.release('creature');
    expect(await first).toBe(false);
    expect(h.c.model?.title).toBe('torus');
    expect(h.gpu()?.model).toBe('torus');
    expect(h.log.filter((l) => l.startsWith('upload'))).toEqual(['upload torus catmull-clark +torus']);
    expect(h.busy()).toBe(false);
  });

  it('the latest request wins: a slow model file is dropped when another arrives first', async () => {
    const h = harness('phong');
    const slow = deferred<Model>();
    const first = h.c.loadModel(() => slow.promise, 'big.obj');
    const second = h.c.loadModel(model('gear'), 'gear');
    expect(await second).toBe(true);
    slow.resolve({ title: 'big.obj' });
    expect(await first).toBe(false);
    expect(h.c.model?.title).toBe('gear');
    expect(h.log.some((l) => l.includes('big.obj') && l.startsWith('upload'))).toBe(false);
  });

  it('a model that fails to load changes nothing, says why and what is still shown', async () => {
    const h = harness('phong');
    await h.c.loadModel(model('torus'), 'torus');
    const bad = new CageError([{ line: 4, message: 'face refers to vertex 7 of 3' }]);
    expect(await h.c.loadModel(() => Promise.reject(bad), 'broken.obj')).toBe(false);
    expect(h.c.model?.title).toBe('torus');
    expect(h.gpu()?.model).toBe('torus');
    const failed = h.log.find((l) => l.startsWith('failed'))!;
    expect(failed).toContain('Could not load broken.obj');
    expect(failed).toContain('line 4');
    expect(failed).toContain('Still showing torus.');
    // The wait is over before the message comes.
    expect(h.log.at(-2)).toBe('loading null');
    // A surface change afterwards applies to the model still shown, not to the broken one.
    expect(await h.c.setSurface('cage')).toBe(true);
    expect(h.gpu()).toEqual({ model: 'torus', surface: 'cage', data: null });
  });

  it('Catmull-Clark refused by the data step: Phong is shown, and the page is told why', async () => {
    const h = harness();
    h.refuse.add('sheet');
    expect(await h.c.loadModel(model('sheet'), 'sheet')).toBe(true);
    expect(h.c.shownSurface).toBe('phong');
    expect(h.c.dataError).toBe('no tables for sheet');
    expect(h.gpu()).toEqual({ model: 'sheet', surface: 'phong', data: null });
    expect(h.log).toContain('fell back sheet: no tables for sheet');
  });

  it('Catmull-Clark refused by the upload: Phong is uploaded instead, and the page is told why', async () => {
    const h = harness();
    h.ccUploadFails.add('gear');
    const done = h.c.loadModel(model('gear'), 'gear');
    await flush();
    h.release('gear');
    expect(await done).toBe(true);
    expect(h.gpu()).toEqual({ model: 'gear', surface: 'phong', data: null });
    expect(h.c.shownSurface).toBe('phong');
    expect(h.c.dataError).toBe('cannot upload gear as catmull-clark');
    expect(h.c.data).toBeNull();
    expect(h.log).toContain('fell back gear: cannot upload gear as catmull-clark');
  });

  it('an upload that fails outright keeps the previous model, and puts it back on the GPU', async () => {
    const h = harness('phong');
    await h.c.loadModel(model('torus'), 'torus');
    h.uploadFails.add('huge');
    expect(await h.c.loadModel(model('huge'), 'huge')).toBe(false);
    expect(h.c.model?.title).toBe('torus');
    expect(h.gpu()).toEqual({ model: 'torus', surface: 'phong', data: null });
    expect(h.log.filter((l) => l.startsWith('upload'))).toEqual(['upload torus phong', 'upload huge phong', 'upload torus phong']);
    expect(h.log.find((l) => l.startsWith('failed'))).toContain('Could not tessellate huge');
  });

  it('switching surfaces keeps the model, prepares the data only when Catmull-Clark needs it, once', async () => {
    const h = harness('phong');
    await h.c.loadModel(model('pawn'), 'pawn', 'p');
    const toCc = h.c.setSurface('catmull-clark');
    await flush();
    // The old picture stays while the data is prepared.
    expect(h.gpu()).toEqual({ model: 'pawn', surface: 'phong', data: null });
    expect(h.c.preparing).toBe(true);
    h.release('pawn');
    expect(await toCc).toBe(true);
    expect(h.gpu()).toEqual({ model: 'pawn', surface: 'catmull-clark', data: 'pawn' });
    expect(await h.c.setSurface('cage')).toBe(true);
    expect(await h.c.setSurface('catmull-clark')).toBe(true);
    expect(h.log.filter((l) => l.startsWith('prepare'))).toEqual(['prepare pawn']);
    // A surface change is not a new model: no placement, the same model object.
    expect(h.log.filter((l) => l.startsWith('shown'))).toEqual([
      'shown pawn (was none) p',
      'shown pawn (was pawn) -',
      'shown pawn (was pawn) -',
      'shown pawn (was pawn) -',
    ]);
  });

  it('a surface change while a model loads applies to that model, which keeps its placement', async () => {
    const h = harness('phong');
    const slow = deferred<Model>();
    const load = h.c.loadModel(() => slow.promise, 'creature', 'place');
    const toCc = h.c.setSurface('catmull-clark');
    slow.resolve({ title: 'creature' });
    await flush();
    h.release('creature');
    expect(await toCc).toBe(true);
    expect(await load).toBe(false); // overtaken by the surface change, which showed it
    expect(h.gpu()).toEqual({ model: 'creature', surface: 'catmull-clark', data: 'creature' });
    expect(h.log.filter((l) => l.startsWith('shown'))).toEqual(['shown creature (was none) place']);
  });

  it('switching away while the data is prepared drops the wait and clears the busy flag', async () => {
    const h = harness('phong');
    await h.c.loadModel(model('creature'), 'creature');
    const toCc = h.c.setSurface('catmull-clark');
    await flush();
    expect(h.busy()).toBe(true);
    expect(await h.c.setSurface('phong')).toBe(true);
    h.release('creature');
    expect(await toCc).toBe(false);
    expect(h.busy()).toBe(false);
    expect(h.gpu()).toEqual({ model: 'creature', surface: 'phong', data: null });
  });

  it('slow surface data: the model is shown at once as its flat cage, placed once; the surface follows in place', async () => {
    const h = harness('catmull-clark', { interimAfterMs: 5 });
    const first = h.c.loadModel(model('torus'), 'torus', 'place-torus');
    await flush();
    h.release('torus');
    expect(await first).toBe(true);
    const done = h.c.loadModel(model('pawn'), 'pawn', 'place-pawn');
    await new Promise((r) => setTimeout(r, 20));
    // The interim picture: pawn's cage, placed with its camera, the wait still said.
    expect(h.c.model?.title).toBe('pawn');
    expect(h.c.shownSurface).toBe('cage');
    expect(h.c.preparing).toBe(true);
    expect(h.gpu()).toEqual({ model: 'pawn', surface: 'cage', data: null });
    expect(h.log.at(-1)).toBe('loading Preparing subdivision data… (the surface)');
    h.release('pawn');
    expect(await done).toBe(true);
    expect(h.gpu()).toEqual({ model: 'pawn', surface: 'catmull-clark', data: 'pawn' });
    // Placed once (with the cage); the surface's arrival is the same model: no new placement.
    expect(h.log.filter((l) => l.startsWith('shown') && l.includes('pawn'))).toEqual([
      'shown pawn (was torus) place-pawn',
      'shown pawn (was pawn) -',
    ]);
    expect(h.busy()).toBe(false);
  });

  it('surface data that comes in time shows no interim cage; a request overtaken while waiting shows nothing', async () => {
    const h = harness('catmull-clark', { interimAfterMs: 50 });
    const first = h.c.loadModel(model('torus'), 'torus');
    await flush();
    h.release('torus');
    expect(await first).toBe(true);
    expect(h.log.filter((l) => l.startsWith('upload'))).toEqual(['upload torus catmull-clark +torus']);
    const slow = h.c.loadModel(model('creature'), 'creature');
    await flush();
    const other = h.c.loadModel(model('gear'), 'gear');
    await new Promise((r) => setTimeout(r, 80));
    // gear's own wait went past the delay: its cage is shown; creature's never was.
    expect(h.log.some((l) => l.startsWith('upload creature'))).toBe(false);
    expect(h.gpu()).toEqual({ model: 'gear', surface: 'cage', data: null });
    h.release('creature');
    h.release('gear');
    expect(await slow).toBe(false);
    expect(await other).toBe(true);
    expect(h.gpu()).toEqual({ model: 'gear', surface: 'catmull-clark', data: 'gear' });
  });

  it('reupload puts the shown state on a new device', async () => {
    const h = harness();
    const done = h.c.loadModel(model('torus'), 'torus');
    await flush();
    h.release('torus');
    await done;
    const version = h.c.version;
    h.c.reupload();
    expect(h.log.at(-1)).toBe('upload torus catmull-clark +torus');
    expect(h.c.version).toBeGreaterThan(version);
  });
});

describe('errorMessage', () => {
  it('gives the message of errors (a CageError lists its lines), and the text of anything else', () => {
    expect(errorMessage(new Error('boom'))).toBe('boom');
    expect(errorMessage(new CageError([{ line: 3, message: 'bad face' }]))).toContain('line 3');
    expect(errorMessage('plain')).toBe('plain');
    expect(errorMessage({ message: 'from a worker' })).toBe('from a worker');
    expect(errorMessage(null)).toBe('null');
    expect(errorMessage(42)).toBe('42');
  });
});
