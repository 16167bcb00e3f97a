// The page's ?model= policy and its notes for adjusted URL numbers, without a browser.
import { describe, expect, it } from 'vitest';
import { modelSource } from '../../src/app/model-source.ts';
import { checkFileSize, MAX_HEIGHT_MAP_FILE_BYTES, MAX_MODEL_FILE_BYTES } from '../../src/app/file-size.ts';
import { readHeightMap } from '../../src/app/model-loading.ts';
import { loadModelFromFile } from '../../src/app/models.ts';
import { paramNotes, parseParams } from '../../src/app/params.ts';

const PAGE = 'https://example.org/tessellab/index.html?model=x';

describe('?model= takes the project models and this site only', () => {
  it('names are the project models; same-origin paths are URLs on this site', () => {
    expect(modelSource('torus', PAGE)).toEqual({ kind: 'builtin', name: 'torus' });
    expect(modelSource('./models/gear.obj', PAGE)).toEqual({ kind: 'url', url: 'https://example.org/tessellab/models/gear.obj' });
    expect(modelSource('/shared-cages/suzanne.obj', PAGE)).toEqual({ kind: 'url', url: 'https://example.org/shared-cages/suzanne.obj' });
    expect(modelSource('https://example.org/a.obj', PAGE).kind).toBe('url');
  });

  it('data:, javascript:, other sites, loopback ports and protocol-relative links are refused with a reason', () => {
    const cases: [string, RegExp][] = [
      ['data:text/plain,v 0 0 0%0Av 1 0 0%0Av 0 1 0%0Af 1 2 3', /data:/],
      ['javascript:alert(1)', /javascript:/],
      ['http://127.0.0.1:9229/x.obj', /another site.*127\.0\.0\.1:9229/],
      ['https://evil.example/x.obj', /another site/],
      ['//evil.example/x.obj', /another site/],
      ['http://example.org/a.obj', /another site/], // http on an https page: another origin
      ['file:///etc/passwd', /file:/],
      ['blob:https://example.org/1234', /blob:/],
    ];
    for (const [model, reason] of cases) {
      const s = modelSource(model, PAGE);
      expect(s.kind, model).toBe('refused');
      if (s.kind === 'refused') expect(s.reason).toMatch(reason);
    }
  });
});

describe('URL numbers the page adjusts are named', () => {
  it('out of range, not a number, rounded: one note each, with the value in effect', () => {
    const search = '?cap=1e9&lod=abc&level=5&factor=8&pitch=-400&dist=NaN';
    const p = parseParams(search);
    const notes = paramNotes(search);
    expect(notes).toContain(`cap=1e9 is outside what the page takes: ${p.capacity} is used`);
    expect(notes).toContain(`lod=abc is not a number: ${p.lod} is used`);
    expect(notes).toContain('level=5 is outside what the page takes: 4 is used');
    expect(notes).toContain('pitch=-400 is outside what the page takes: -89 is used');
    expect(notes).toContain('dist=NaN is not a number: the default is used');
    expect(notes.some((n) => n.startsWith('factor='))).toBe(false);
    expect(notes).toHaveLength(5);
  });

  it('values in range give no note', () => {
    expect(paramNotes('?model=torus&cap=0.5&factor=4&t=0&level=8&errrange=2')).toEqual([]);
  });
});

describe("the page's loader (a dropped file)", () => {
  const CUBE =
    'v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n' +
    'f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n';

  it('reads UTF-16 with its BOM as the CLIs do', async () => {
    const utf16 = new Uint8Array([0xff, 0xfe, ...new Uint8Array(Uint16Array.from([...CUBE].map((c) => c.charCodeAt(0))).buffer)]);
    const m = await loadModelFromFile(new File([utf16], 'cube.obj'));
    expect(m.topology.nFaces).toBe(6);
  });

  it('says why a model would draw nothing: coordinates beyond 32-bit floats, every face a hole', async () => {
    const huge = CUBE.replace(/^v .*$/gm, (line) => line.replace(/1/g, '1e39'));
    await expect(loadModelFromFile(new File([huge], 'huge.obj'))).rejects.toThrow(/line 1: vertex 1: coordinate -1e\+39 is beyond/);
    await expect(loadModelFromFile(new File([`${CUBE}t hole 6/0/0 0 1 2 3 4 5\n`], 'holes.obj'))).rejects.toThrow(
      /every face of the model is a hole/,
    );
  });
});

describe('a file over the size cap is refused before it is read', () => {
  it('checks File.size only: at the cap taken, one byte over refused with both sizes', () => {
    expect(() => checkFileSize({ name: 'a.obj', size: MAX_MODEL_FILE_BYTES }, MAX_MODEL_FILE_BYTES, 'model files')).not.toThrow();
    expect(() => checkFileSize({ name: 'a.obj', size: MAX_MODEL_FILE_BYTES + 1 }, MAX_MODEL_FILE_BYTES, 'model files')).toThrow(
      'a.obj is 256.0 MiB: the page reads model files of up to 256.0 MiB, so it was not opened.',
    );
    expect(() => checkFileSize({ name: 'h.png', size: 3 * 2 ** 30 }, MAX_HEIGHT_MAP_FILE_BYTES, 'height maps')).toThrow(
      /h\.png is 3072\.0 MiB: the page reads height maps of up to 256\.0 MiB/,
    );
  });

  it("the page's loader refuses a 3 GiB file without asking for its bytes", async () => {
    const read = () => {
      throw new Error('the file was read');
    };
    const huge = { name: 'huge.obj', size: 3 * 2 ** 30, arrayBuffer: read, text: read, stream: read } as unknown as File;
    await expect(loadModelFromFile(huge)).rejects.toThrow(/huge\.obj is 3072\.0 MiB: the page reads model files of up to/);
  });

  it('a height map too: refused from its size on a model with uvs, before the image is decoded', async () => {
    const quad = await loadModelFromFile(
      new File(['v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n'], 'quad.obj'),
    );
    const read = () => {
      throw new Error('the file was read');
    };
    const huge = { name: 'huge.png', size: 2 ** 30, arrayBuffer: read, text: read, stream: read, slice: read } as unknown as File;
    await expect(readHeightMap(huge, quad)).rejects.toThrow(/huge\.png is 1024\.0 MiB: the page reads height maps of up to 256\.0 MiB/);
  });
});
