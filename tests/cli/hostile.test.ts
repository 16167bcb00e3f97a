// The hostile-input corpus of issue 33, case by case, on the CLIs' CPU stages (tessellate up to the
// GPU, subdiv, pattern) and the loader: each ends done or refused with a one-line reason (exit 2),
// never an internal error, a trace, a NaN written, an unbounded allocation or a terminal escape.
import { describe, expect, it } from 'vitest';
import { describeFailure } from '../../src/cli/boundary.ts';
import { decodeHeightPng, encodeHeightPng, HeightMapError } from '../../src/mesh/heightmap-png.ts';
import { CageError, decodeText, escapeControl, heightMapFromFunction, loadCage, MAX_FACE_CORNERS } from '../../src/mesh/index.ts';
import { Surface } from '../../src/subdiv/index.ts';
import { refuseNonFiniteOutput } from '../../scripts/tessellate-input.ts';
import { assertHandled, fan, ngon, pattern, put, subdiv, tempDir, tessellateCpu } from '../support/hostile-cli.ts';

const dir = tempDir();
const CUBE =
  'v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n' +
  'f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n';
const cube = put(dir, 'cube.obj', CUBE);
const out = `${dir}/out.obj`;

/** The cube with every coordinate's magnitude written as `s` (as text, so 1e39 stays 1e39). */
function scaledCube(s: string): string {
  return CUBE.replace(
    /^v (\S+) (\S+) (\S+)$/gm,
    (_, x, y, z) => `v ${[x, y, z].map((c: string) => (c.startsWith('-') ? `-${s}` : s)).join(' ')}`,
  );
}

/** A cube with UVs on one face only would be refused for displacement; this one has a vt on every corner. */
const UV_CUBE = `${CUBE.split('\nf ')[0]}\nvt 0 0\n${CUBE.split('\n')
  .filter((l) => l.startsWith('f '))
  .map((l) => l.replace(/(\d+)/g, '$1/1'))
  .join('\n')}\n`;

describe('tessellate: refused before the GPU, in words, exit 2', () => {
  const cases: [string, () => string[], RegExp][] = [
    [
      // A fan wider than a workgroup has a workgroup of its own (tests/gpu/cc/wide-fans.node.test.ts);
      // its word holds 4,095 sectors.
      'a valence-5,000 vertex (Catmull-Clark)',
      () => [put(dir, 'val5000.obj', fan(5000)), '--fixed', '2', '--out', out],
      /vertex 1 has 5000 faces round it; the Catmull-Clark surface's GPU build takes at most 4095/,
    ],
    [
      'a 4,096-gon',
      () => [put(dir, 'ngon4096.obj', ngon(4096)), '--fixed', '2', '--out', out],
      /face 1 has 4096 corners, more than the 1024/,
    ],
    ['a 10,000-gon', () => [put(dir, 'ngon10000.obj', ngon(10000)), '--fixed', '2', '--out', out], /line 10001: face 1 has 10000 corners/],
    [
      'a cage of holes only',
      () => [put(dir, 'holes.obj', `${CUBE}t hole 6/0/0 0 1 2 3 4 5\n`), '--fixed', '2', '--out', out],
      /every face is a hole/,
    ],
    ['a folder as the model', () => [dir, '--fixed', '2', '--out', out], /model .* is a folder, not a file/],
    ['a missing model', () => [`${dir}/missing.obj`, '--fixed', '2', '--out', out], /model .*missing\.obj: does not exist/],
    [
      'a folder as the height map',
      () => [put(dir, 'uvc.obj', UV_CUBE), '--fixed', '2', '--out', out, '--displacement', dir, '--scale', '1'],
      /height map .* is a folder/,
    ],
    [
      '--out in a missing folder',
      () => [cube, '--fixed', '2', '--out', `${dir}/no/such/out.obj`],
      /--out .*: the folder .* does not exist/,
    ],
    ['--out naming a folder', () => [cube, '--fixed', '2', '--out', dir], /--out .* is a folder, not a file/],
    [
      '--params in a missing folder',
      () => [cube, '--fixed', '2', '--out', out, '--params', `${dir}/no/p.json`],
      /--params .*does not exist/,
    ],
    [
      'coordinates of 1e39',
      () => [put(dir, 'c1e39.obj', scaledCube('1e39')), '--fixed', '2', '--out', out],
      /line 1: vertex 1: coordinate -1e\+39 is beyond ±1e12/,
    ],
    ['coordinates of 1e308', () => [put(dir, 'c1e308.obj', scaledCube('1e308')), '--fixed', '2', '--out', out], /beyond ±1e12/],
    [
      'coordinates of 1e-300',
      () => [put(dir, 'c1e-300.obj', scaledCube('1e-300')), '--fixed', '2', '--out', out],
      /spans only 2\.00e-300.*collapse to a point/,
    ],
    [
      'a unit cube 1e11 from the origin',
      () => [
        put(
          dir,
          'far.obj',
          CUBE.replace(/^v (\S+)/gm, (_, x) => `v ${x === '-1' ? '100000000000' : '100000000001'}`),
        ),
        '--fixed',
        '2',
        '--out',
        out,
      ],
      /lies 1\.00e\+11 from the origin/,
    ],
    [
      '--scale 1e308',
      () => [cube, '--fixed', '2', '--out', out, '--displacement', cube, '--scale', '1e308'],
      /--scale: a number within ±1e12/,
    ],
    ['--eye 1e39,0,0', () => [cube, '--adaptive', '--eye', '1e39,0,0', '--out', out], /--eye: coordinates within ±1e12/],
    ['--target NaN', () => [cube, '--adaptive', '--eye', '1,2,3', '--target', 'NaN,0,0', '--out', out], /--target: expected x,y,z/],
    [
      'a 69-byte PNG declaring 16384²',
      () => [put(dir, 'uv1.obj', UV_CUBE), '--fixed', '2', '--out', out, '--displacement', put(dir, 'huge.png', hugePng()), '--scale', '1'],
      /declares 16384x16384, more than the 67108864 texels/,
    ],
    [
      'a truncated PNG',
      () => [
        put(dir, 'uv2.obj', UV_CUBE),
        '--fixed',
        '2',
        '--out',
        out,
        '--displacement',
        put(dir, 'cut.png', truncatedPng()),
        '--scale',
        '1',
      ],
      /corrupt, truncated or unsupported PNG \(its image data holds \d+ of the 4160 bytes/,
    ],
  ];
  for (const [what, argv, message] of cases)
    it(what, async () => {
      const r = await tessellateCpu(...argv());
      assertHandled(r, what);
      expect(r.code, r.err).toBe(2);
      expect(r.err).toMatch(message);
      expect(r.err).not.toMatch(/CcRuleWord|RangeError|TypeError|ENOENT|EISDIR/);
      expect(r.ms).toBeLessThan(10_000);
    });

  it('warns, and goes on, for zero-area faces, unused vertices and --eye equal to --target', async () => {
    const flat = put(dir, 'flat.obj', `${CUBE}v 0 0 0\nv 5 5 5\nv 6 6 6\nv 7 7 7\nf 10 11 12\n`);
    const r = await tessellateCpu(flat, '--adaptive', '--eye', '1,1,1', '--target', '1,1,1', '--out', out);
    assertHandled(r, 'warnings');
    expect(r.code, r.err).toBe(0);
    expect(r.err).toMatch(/line 19: face 7 has zero area/);
    expect(r.err).toMatch(/1 vertices are not used by any face/);
    expect(r.err).toMatch(/--eye and --target are the same point/);
  });

  it("an output with a NaN or an infinity is refused by both tessellators' check, naming its vertex", () => {
    const positions = new Float32Array([0, 1, 2, 3, 4, 5, 6, Number.NaN, 8, 9, Number.POSITIVE_INFINITY, 11]);
    expect(() => refuseNonFiniteOutput('m.obj', positions, 2)).not.toThrow();
    let refusal: unknown;
    try {
      refuseNonFiniteOutput('m.obj', positions, 4);
    } catch (e) {
      refusal = e;
    }
    expect((refusal as Error).message).toMatch(/^m\.obj: output vertex 3 is not finite: nothing written/);
    expect(describeFailure('tessellate', refusal, false).code).toBe(2);
  });
});

describe('subdiv: exit 2 like every CLI, sizes checked first', () => {
  it('usage, a bad points line, a missing points file, a missing model: 2 (were 64, 65, 66)', () => {
    const cases: [string[], RegExp][] = [
      [['--frob', cube], /unknown option --frob/],
      [['--points', put(dir, 'bad-points.txt', '0 0.5\n'), cube], /bad-points\.txt:1: expected "f u v"/],
      [['--points', `${dir}/none.txt`, cube], /--points file .*none\.txt: does not exist/],
      [['--uniform', '2', `${dir}/none.obj`], /model .*none\.obj: does not exist/],
      [['--uniform', '2', dir], /is a folder, not a file/],
      [['--points', put(dir, 'far-face.txt', '99 0.5 0.5\n'), cube], /far-face\.txt:1: face 99 does not exist/],
    ];
    for (const [argv, message] of cases) {
      const r = subdiv(...argv);
      assertHandled(r, argv.join(' '));
      expect(r.code).toBe(2);
      expect(r.err).toMatch(message);
    }
  });

  it('--uniform 4096 is refused from the counts, before a sample is made', () => {
    const r = subdiv('--uniform', '4096', cube);
    assertHandled(r, '--uniform 4096');
    expect(r.code).toBe(2);
    expect(r.err).toMatch(/--uniform 4096: 100712454 samples would write about 14407 MiB/);
    expect(r.ms).toBeLessThan(2000);
  });

  it('--refine 8 of a large cage is refused from the counts', () => {
    const r = subdiv('--refine', '8', put(dir, 'fan200.obj', fan(200)));
    expect(r.code).toBe(2);
    expect(r.err).toMatch(/200 faces would become 13107200/);
  });

  it('1e308 coordinates are refused at their line instead of written as null', () => {
    const r = subdiv('--uniform', '2', put(dir, 's1e308.obj', scaledCube('1e308')));
    expect(r.code).toBe(2);
    expect(r.out).toBe('');
    expect(r.err).toMatch(/refused:\nline 1: vertex 1: coordinate -1e\+308 is beyond/);
  });

  it('--uniform writes finite samples, a face a line', () => {
    const r = subdiv('--uniform', '3', cube);
    expect(r.code).toBe(0);
    const faces = JSON.parse(r.out).faces as { sub: { P: number[] }[] }[];
    expect(faces).toHaveLength(6);
    expect(faces.every((f) => f.sub.every((s) => s.P.every(Number.isFinite)))).toBe(true);
    expect(r.out.trim().split('\n')).toHaveLength(6 + 2);
  });

  it("an n-gon's evaluator holds a few sub-face trees, not n (its memory was ~ n²)", () => {
    const evaluator = (n: number) => {
      const { cage, topology } = loadCage(ngon(n));
      return new Surface(cage, topology).faceEvaluator(0);
    };
    const large = evaluator(1000);
    for (let k = 0; k < 1000; k += 10) large.evaluate(k, 0.5, 0.5);
    expect(large.cachedSubFaces).toBeGreaterThan(0);
    expect(large.cachedSubFaces).toBeLessThanOrEqual(8);
    // An ordinary n-gon keeps all its trees: its evaluation order costs nothing.
    const small = evaluator(16);
    for (let k = 0; k < 16; k++) small.evaluate(k, 0.5, 0.5);
    expect(small.cachedSubFaces).toBe(16);
  });
});

describe('pattern: sized before the work', () => {
  it('--sweep 1,64,0.000063 is refused at once (was RangeError: Invalid string length)', () => {
    const r = pattern('line', '--mode', 'hable', '--sweep', '1,64,0.000063');
    assertHandled(r, 'sweep');
    expect(r.code).toBe(2);
    expect(r.err).toMatch(/--sweep: the output would be up to about \d+ MiB, more than the 256 MiB/);
    expect(r.ms).toBeLessThan(2000);
  });

  it('a folder as --factors-file', () => {
    const r = pattern('tri', '--mode', 'clamped', '--factors-file', dir);
    assertHandled(r, 'factors-file');
    expect(r.code).toBe(2);
    expect(r.err).toMatch(/is a folder, not a file/);
  });
});

describe('safe text', () => {
  it("a file's escape sequences are printed, not obeyed", async () => {
    const evil = put(dir, 'evil.obj', `${CUBE}\u001b[2J\n\u001b]0;pwned\u0007 1 2\nv 1 2 \u009b31m\n`);
    for (const r of [await tessellateCpu(evil, '--fixed', '2', '--out', out), subdiv('--check', evil)]) {
      assertHandled(r, 'escapes');
      expect(r.code).toBe(2);
      expect(r.err).toContain('unknown statement "\\x1b[2J"');
      expect(r.err).toContain('\\x1b]0;pwned\\x07');
      expect(r.err).toContain('\\x9b31m');
    }
  });

  it('UTF-16 (LE and BE) and UTF-8 with a BOM read as the page reads them', () => {
    const le = new Uint8Array([0xff, 0xfe, ...new Uint8Array(Uint16Array.from([...CUBE].map((c) => c.charCodeAt(0))).buffer)]);
    const be = new Uint8Array(le.length);
    be.set([0xfe, 0xff]);
    for (let i = 2; i < le.length; i += 2) [be[i], be[i + 1]] = [le[i + 1], le[i]];
    const bom8 = new Uint8Array([0xef, 0xbb, 0xbf, ...new TextEncoder().encode(CUBE)]);
    for (const bytes of [le, be, bom8]) {
      expect(decodeText(bytes)).toBe(CUBE);
      const r = subdiv('--check', put(dir, 'enc.obj', bytes));
      expect(r.code, r.err).toBe(0);
      expect(JSON.parse(r.out).faces).toBe(6);
    }
  });

  it('a binary file is refused in one line, not parsed into lines of its bytes', () => {
    const png = encodeHeightPng(heightMapFromFunction(8, 8, 8, (u, v) => u * v));
    const noise = Uint8Array.from({ length: 4000 }, (_, i) => 0x80 + ((i * 37) % 0x7f));
    for (const [name, bytes, why] of [
      ['height.png', png, 'NUL bytes'],
      ['noise.obj', noise, 'not UTF-8 text'],
    ] as const) {
      expect(() => decodeText(bytes)).toThrow(CageError);
      const r = subdiv('--check', put(dir, name, bytes));
      assertHandled(r, name);
      expect(r.code).toBe(2);
      expect(r.err).toContain(`not a text OBJ file: `);
      expect(r.err).toContain(why);
      expect(r.err.trim().split('\n')).toHaveLength(1);
    }
    // A Latin-1 comment is still text: its line parses as a comment.
    expect(decodeText(Uint8Array.from([...new TextEncoder().encode('# caf'), 0xe9, 0x0a, ...new TextEncoder().encode(CUBE)]))).toContain(
      'v ',
    );
  });

  it('escapeControl keeps text, escapes C0, C1, DEL and bidirectional overrides', () => {
    expect(escapeControl('a\tb\nc')).toBe('a\tb\nc');
    expect(escapeControl('a\tb\nc', { newlines: false })).toBe('a\\tb\\nc');
    expect(escapeControl('\u0000\u001b\u007f\u0085\u202e\u2066é')).toBe('\\x00\\x1b\\x7f\\x85\\u202e\\u2066é');
  });
});

describe('the boundary', () => {
  it('an internal error is one line, exit 1, the trace only with --debug; bad input is exit 2', () => {
    const bug = new TypeError('x is undefined');
    const plain = describeFailure('tessellate', bug, false);
    expect(plain.code).toBe(1);
    expect(plain.text).toBe(
      'tessellate: internal error: x is undefined (a bug in tessellab, not in the input; please report it) (--debug prints the trace)',
    );
    expect(describeFailure('tessellate', bug, true).text).toMatch(/\n\s+at /);
    expect(describeFailure('subdiv', new RangeError('Invalid string length'), false).text).toMatch(/too large for this machine/);
    expect(describeFailure('subdiv', new CageError([{ line: 3, message: 'bad' }]), false)).toEqual({
      text: 'subdiv: line 3: bad',
      code: 2,
    });
    expect(describeFailure('x', new HeightMapError('height map: \u001b[2J'), false)).toEqual({ text: 'x: height map: \\x1b[2J', code: 2 });
  });

  it('the loader bounds faces at MAX_FACE_CORNERS, with the line', () => {
    expect(() => loadCage(ngon(MAX_FACE_CORNERS))).not.toThrow();
    expect(() => loadCage(ngon(MAX_FACE_CORNERS + 1))).toThrow(/line 1026: face 1 has 1025 corners/);
  });

  it('a whole PNG still decodes', () => {
    const map = heightMapFromFunction(8, 4, 16, (u, v) => u * v);
    expect(decodeHeightPng(encodeHeightPng(map)).data).toEqual(map.data);
  });
});

/** A PNG of 69 bytes whose header declares 16384×16384 (8-bit grey) over a 1×1 image's data. */
function hugePng(): Uint8Array {
  const bytes = encodeHeightPng(heightMapFromFunction(1, 1, 8, () => 0)).slice();
  const view = new DataView(bytes.buffer);
  view.setUint32(16, 16384);
  view.setUint32(20, 16384);
  // The IHDR's CRC made right, so only the size is hostile.
  view.setUint32(29, crc(bytes.subarray(12, 29)));
  return bytes;
}

/** A whole PNG cut inside its image data, with a valid IDAT CRC and its IEND put back: the rows are
 * missing, not the file's end (pngjs reads such rows as zeros). */
function truncatedPng(): Uint8Array {
  const png = encodeHeightPng(heightMapFromFunction(64, 64, 8, (u, v) => 0.5 + 0.5 * Math.sin(40 * u * v)));
  const view = new DataView(png.buffer, png.byteOffset);
  const keep = Math.floor(view.getUint32(33) / 3);
  const idat = png.slice(33, 41 + keep);
  new DataView(idat.buffer).setUint32(0, keep);
  const crcBytes = new Uint8Array(4);
  new DataView(crcBytes.buffer).setUint32(0, crc(idat.subarray(4)));
  return new Uint8Array([...png.subarray(0, 33), ...idat, ...crcBytes, ...png.subarray(png.length - 12)]);
}

function crc(bytes: Uint8Array): number {
  let c = ~0;
  for (const b of bytes) {
    c ^= b;
    for (let k = 0; k < 8; k++) c = c & 1 ? (c >>> 1) ^ 0xedb88320 : c >>> 1;
  }
  return ~c >>> 0;
}
