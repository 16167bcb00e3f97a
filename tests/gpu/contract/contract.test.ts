/**
 * The TypeScript↔WGSL contract (src/gpu/contract/), checked from the WGSL side: the generated
 * text is parsed back and laid out by WGSL's own rules (written out here, independently of
 * layout.ts), and must give the offsets, sizes and bit fields the TypeScript views use. The
 * renderer's shaders must declare exactly the bindings its pipeline layouts are built from.
 */
import { readdirSync, readFileSync } from 'node:fs';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  defineArena,
  defineBindGroup,
  defineBits,
  STAGE,
  usedBindings,
  wgslPrefix,
  type BitWord,
  wgslF32,
} from '../../../src/gpu/contract/define.ts';
import { constantsWgsl, GRID_X, SCAN_WORKGROUP_SIZE, SHARED_CONSTANTS, WORKGROUP_SIZE } from '../../../src/gpu/contract/constants.ts';
import {
  ACC_TRI_CORNERS,
  ACC_TRI_WORD,
  BARY_CORNER1,
  BARY_CORNER2,
  BARY_WORD,
  decodeBary,
  PATTERN_FRAME_WORD,
  OWNER_WORD,
  TESS_BINDINGS,
  TESS_CAGE,
  TESS_CONSTANTS,
  TESS_GROUP,
  TESS_INPUTS,
  TESS_PARAMS,
  TESS_STATIC,
  TESS_WORK,
  type TessSizes,
} from '../../../src/gpu/contract/tess.ts';
import {
  ACC_BUILD_GROUP,
  ACC_BUILD_PARAMS,
  ACC_SECTOR_WORD,
  ACC_STATIC,
  type AccSection,
  HEAT_BINDINGS,
  HEAT_GROUP,
} from '../../../src/gpu/contract/acc.ts';
import { heatComputeCode } from '../../../src/gpu/acc/heat.ts';
import { CC_BUILD_GROUP, CC_STATIC, type CcSection } from '../../../src/gpu/contract/cc.ts';
import {
  BLIT_GROUP,
  HEAT_RENDER_GROUP,
  PATCH_KIND_GROUP,
  RENDER_BIND_GROUPS,
  RENDER_PIPELINE_GROUPS,
  SCENE_GROUP,
  SCENE_UNIFORMS,
  SHADING_GROUP,
  WIRE_ARGS_GROUP,
  WIRE_LINES_GROUP,
  GROUND_EXTENT,
  PATCH_COLOURS,
} from '../../../src/gpu/contract/render.ts';
import { accBuildPrelude, sceneWgsl, tessPrelude } from '../../../src/gpu/contract/contract.ts';
import { passBindings, tessellatorPasses } from '../../../src/gpu/tess/passes.ts';
import { bakeTables, PatternTables, TABLE_HEADER, TABLE_HEADER_FIELDS } from '../../../src/pattern/tables.ts';
import { defineStruct } from '../../../src/gpu/contract/layout.ts';
import { packPatternFrame } from '../../../src/gpu/tess/prepare.ts';
import { HEAT_SHADER, RENDER_SHADERS } from '../../../src/gpu/render/pipelines.ts';
import { BLIT_SHADER } from '../../../src/gpu/render/srgb-blit.ts';
import { chooseFrame } from '../../../src/pattern/clamped.ts';

// ---- WGSL's uniform layout rules (WGSL spec, "Memory layout"), for the types the contract uses.
const WGSL_TYPES: Record<string, { size: number; align: number }> = {
  f32: { size: 4, align: 4 },
  u32: { size: 4, align: 4 },
  i32: { size: 4, align: 4 },
  'vec2<f32>': { size: 8, align: 8 },
  'vec3<f32>': { size: 12, align: 16 },
  'vec4<f32>': { size: 16, align: 16 },
  'vec4<u32>': { size: 16, align: 16 },
  'mat4x4<f32>': { size: 64, align: 16 },
};

interface ParsedStruct {
  name: string;
  fields: { name: string; type: string; offset: number; size: number }[];
  size: number;
}

/** Parse `struct Name { field: type, … }` (comments allowed) and lay it out as WGSL does for a
 * uniform buffer: each member at its alignment, the struct's size a multiple of 16. */
function parseStruct(wgsl: string): ParsedStruct {
  const m = /struct\s+(\w+)\s*\{([^}]*)\}/.exec(wgsl.replace(/\/\/[^\n]*/g, ''));
  if (!m) throw new Error('no struct');
  let at = 0;
  let align = 1;
  const fields: ParsedStruct['fields'] = [];
  for (const decl of m[2]
    .split(',')
    .map((d) => d.trim())
    .filter(Boolean)) {
    const [, name, type] = /^(\w+)\s*:\s*(.+)$/.exec(decl)!;
    const t = WGSL_TYPES[type.replace(/\s/g, '')];
    if (!t) throw new Error(`unknown type ${type}`);
    at = Math.ceil(at / t.align) * t.align;
    fields.push({ name, type, offset: at, size: t.size });
    at += t.size;
    align = Math.max(align, t.align);
  }
  return { name: m[1], fields, size: Math.ceil((Math.ceil(at / align) * align) / 16) * 16 };
}

describe('uniform structs', () => {
  it('the generated SceneUniforms parses back to the offsets and size the renderer writes at', () => {
    const parsed = parseStruct(SCENE_UNIFORMS.wgsl);
    expect(parsed.name).toBe('SceneUniforms');
    expect(parsed.size).toBe(SCENE_UNIFORMS.size);
    expect(Object.keys(SCENE_UNIFORMS.offset)).toEqual(parsed.fields.map((f) => f.name));
    for (const f of parsed.fields) expect(SCENE_UNIFORMS.offset[f.name as keyof typeof SCENE_UNIFORMS.offset], f.name).toBe(f.offset);
    // The renderer's buffer is this size: 256 bytes (64 floats) when counted by hand, one vec4
    // more since the material (look).
    expect(SCENE_UNIFORMS.size).toBe(272);
  });

  it('write() puts every float of every field where the parsed WGSL layout says, and nothing elsewhere', () => {
    const parsed = parseStruct(SCENE_UNIFORMS.wgsl);
    const view = new DataView(new ArrayBuffer(SCENE_UNIFORMS.size));
    const values: Record<string, number[]> = {};
    let next = 1;
    for (const f of parsed.fields) values[f.name] = Array.from({ length: f.size / 4 }, () => next++);
    SCENE_UNIFORMS.write(view, values);
    const seen = new Set<number>();
    for (const f of parsed.fields) {
      for (let i = 0; i < f.size / 4; i++) {
        expect(view.getFloat32(f.offset + 4 * i, true), `${f.name}[${i}]`).toBe(values[f.name][i]);
        seen.add(f.offset + 4 * i);
      }
    }
    // Padding stays zero.
    for (let o = 0; o < SCENE_UNIFORMS.size; o += 4) if (!seen.has(o)) expect(view.getUint32(o, true)).toBe(0);
  });

  it('mixed scalars and vectors are padded as WGSL pads them, and write() refuses a wrong length', () => {
    const s = defineStruct('Mixed', [
      ['a', 'u32'],
      ['b', 'vec4<f32>', 'a comment that must not confuse the parser, even with: colons, and commas'],
      ['c', 'f32'],
      ['d', 'mat4x4<f32>'],
      ['e', 'u32'],
    ] as const);
    const parsed = parseStruct(s.wgsl);
    expect(parsed.fields.map((f) => f.offset)).toEqual([0, 16, 32, 48, 112]);
    expect(parsed.fields.map((f) => s.offset[f.name as 'a'])).toEqual([0, 16, 32, 48, 112]);
    expect(s.size).toBe(parsed.size);
    expect(() => s.write(new DataView(new ArrayBuffer(s.size)), { b: [1, 2, 3] })).toThrow(/expected 4 floats/);
  });
});

// ---- Packed words: the WGSL getters and packers (shifts and masks) are parsed back into bit
// ranges and evaluated as WGSL's u32 arithmetic would.

/** The bits [at, at + bits) of u32 e, as WGSL `(e >> at) & mask` gives them. */
function wgslExtractBits(e: number, at: number, bits: number): number {
  return Math.floor((e >>> 0) / 2 ** at) % 2 ** bits;
}

/** `e | ((v & mask) << at)` for unsigned values, on bits that are clear in e. */
function wgslInsertBits(e: number, v: number, at: number, bits: number): number {
  const cleared = (e >>> 0) - (Math.floor((e >>> 0) / 2 ** at) % 2 ** bits) * 2 ** at;
  return cleared + (v % 2 ** bits) * 2 ** at;
}

/** The width of a WGSL mask literal 0x…u of the form 2^bits − 1. */
function maskBits(mask: string): number {
  const m = Number.parseInt(mask, 16);
  const bits = Math.log2(m + 1);
  expect(Number.isInteger(bits), `mask 0x${mask}`).toBe(true);
  return bits;
}

/** Each getter `fn prefix_field(w: u32) -> u32 { return (w >> at) & mask; }` (either part may be
 * absent) as [at, bits]. */
function parseGetters(word: BitWord<string>): Map<string, [number, number]> {
  const prefix = wgslPrefix(word.name);
  const re = new RegExp(`fn ${prefix}_(\\w+)\\(w: u32\\) -> u32 \\{ return (.*); \\}`, 'g');
  const out = new Map<string, [number, number]>();
  for (const m of word.wgsl.matchAll(re)) {
    const e = /^(?:w|\(w >> (\d+)u\))(?: & 0x([0-9a-f]+)u)?$/.exec(m[2]);
    if (!e) throw new Error(`unexpected getter body ${m[2]}`);
    const at = Number(e[1] ?? 0);
    out.set(m[1], [at, e[2] ? maskBits(e[2]) : 32 - at]);
  }
  return out;
}

/** Parse `fn prefix_pack(a: u32, …)` and run its `w = w | ((a & mask) << at);` statements. */
function runWgslPacker(word: BitWord<string>, values: Record<string, number>): number {
  const prefix = wgslPrefix(word.name);
  const head = new RegExp(`fn ${prefix}_pack\\(([^)]*)\\) -> u32 \\{([\\s\\S]*?)\\n\\}`).exec(word.wgsl);
  if (!head) throw new Error('no packer');
  const args = head[1].split(',').map((a) => a.trim().split(':')[0]);
  expect(args).toEqual(Object.keys(word.fields));
  let w = 0;
  let statements = 0;
  for (const m of head[2].matchAll(/w = w \| \((?:\((\w+) & 0x([0-9a-f]+)u\)|(\w+)) << (\d+)u\);/g)) {
    const at = Number(m[4]);
    w = wgslInsertBits(w, values[m[1] ?? m[3]], at, m[2] ? maskBits(m[2]) : 32 - at);
    statements++;
  }
  expect(statements).toBe(args.length);
  return w;
}

const WORDS: BitWord<string>[] = [
  PATTERN_FRAME_WORD,
  BARY_WORD,
  OWNER_WORD,
  ACC_SECTOR_WORD,
  ACC_TRI_WORD,
  ACC_TRI_CORNERS,
] as BitWord<string>[];

describe('packed words', () => {
  for (const word of WORDS) {
    describe(word.name, () => {
      it('the WGSL getters name every field with the TypeScript bits, inside a u32, without overlap', () => {
        const getters = parseGetters(word);
        expect([...getters.keys()]).toEqual(Object.keys(word.fields));
        const owner = new Array<string | null>(32).fill(null);
        for (const [field, [at, bits]] of getters) {
          expect(word.fields[field]).toEqual([at, bits]);
          expect(at + bits).toBeLessThanOrEqual(32);
          for (let b = at; b < at + bits; b++) {
            expect(owner[b], `bit ${b} of ${field}`).toBeNull();
            owner[b] = field;
          }
        }
      });

      const fieldValues = fc.record(
        Object.fromEntries(Object.entries(word.fields).map(([f, [, bits]]) => [f, fc.integer({ min: 0, max: 2 ** bits - 1 })])),
      );

      it('pack → unpack, pack → WGSL getters, and the WGSL packer → TypeScript unpack round-trip', () => {
        const getters = parseGetters(word);
        fc.assert(
          fc.property(fieldValues, (values) => {
            const w = word.pack(values);
            expect(w).toBeGreaterThanOrEqual(0);
            expect(w).toBeLessThanOrEqual(0xffffffff);
            expect(word.unpack(w)).toEqual(values);
            for (const [field, [at, bits]] of getters) expect(wgslExtractBits(w, at, bits)).toBe(values[field]);
            expect(runWgslPacker(word, values)).toBe(w);
          }),
          { numRuns: 300 },
        );
      });

      it('any u32 unpacks to fields that pack back to the same word when the fields cover all its bits', () => {
        const covered = Object.values(word.fields).reduce((n, [, bits]) => n + bits, 0);
        fc.assert(
          fc.property(fc.integer({ min: 0, max: 0xffffffff }), (w) => {
            const u = word.unpack(w);
            for (const f of Object.keys(word.fields)) expect(word.get(w, f)).toBe(u[f]);
            const mask = Object.values(word.fields).reduce((m, [at, bits]) => m + (2 ** bits - 1) * 2 ** at, 0);
            expect(word.pack(u)).toBe(covered === 32 ? w : Number(BigInt(w) & BigInt(mask)));
          }),
          { numRuns: 300 },
        );
      });

      it('pack refuses a value that does not fit its field', () => {
        const [field, [, bits]] = Object.entries(word.fields)[0];
        const values = Object.fromEntries(Object.keys(word.fields).map((f) => [f, 0]));
        expect(() => word.pack({ ...values, [field]: 2 ** bits })).toThrow(/does not fit/);
        expect(() => word.pack({ ...values, [field]: -1 })).toThrow(/does not fit/);
      });
    });
  }

  it('defineBits refuses a field named by a WGSL keyword or reserved word (the packer takes it as a parameter)', () => {
    expect(() => defineBits('SectorWord', { type: [0, 2], k: [2, 14] })).toThrow(/WGSL keyword or reserved word/);
    expect(() => defineBits('W', { let: [0, 1] })).toThrow(/SectorWord|W\.let/);
  });

  it('defineBits refuses overlapping fields and fields past bit 31', () => {
    expect(() => defineBits('Bad', { a: [0, 3], b: [2, 2] })).toThrow(/overlaps/);
    expect(() => defineBits('Bad', { a: [30, 3] })).toThrow(/do not fit/);
    expect(() => defineBits('Bad', { a: [0, 0] })).toThrow(/do not fit/);
    // A field that reaches bit 31 packs to a positive u32.
    const top = defineBits('Top', { lo: [0, 31], hi: [31, 1] });
    expect(top.pack({ lo: 0, hi: 1 })).toBe(0x80000000);
    expect(top.unpack(0xffffffff)).toEqual({ lo: 0x7fffffff, hi: 1 });
  });

  it('packPatternFrame (prepare.ts) gives the bits the hand-written packer gave, for every reverse combination', () => {
    for (let r = 0; r < 8; r++) {
      const reverse = [(r & 1) === 1, (r & 2) === 2, (r & 4) === 4] as const;
      const f = chooseFrame(reverse as unknown as Parameters<typeof chooseFrame>[0]);
      const byHand =
        f.a |
        (f.b << 2) |
        (f.c << 4) |
        (f.bottomEdge << 6) |
        (f.leftEdge << 8) |
        (f.rightEdge << 10) |
        (Number(f.flipBottom) << 12) |
        (Number(f.flipLeft) << 13) |
        (Number(f.flipRight) << 14) |
        (Number(f.mirrored) << 15);
      expect(packPatternFrame(reverse as unknown as Parameters<typeof packPatternFrame>[0])).toBe(byHand);
      expect(PATTERN_FRAME_WORD.unpack(byHand)).toEqual({
        a: f.a,
        b: f.b,
        c: f.c,
        bottomEdge: f.bottomEdge,
        leftEdge: f.leftEdge,
        rightEdge: f.rightEdge,
        flipBottom: Number(f.flipBottom),
        flipLeft: Number(f.flipLeft),
        flipRight: Number(f.flipRight),
        mirrored: Number(f.mirrored),
      });
    }
  });

  it('decodeBary: the sentinels are corners 1 and 2, and every real word sums to 2^16', () => {
    expect(decodeBary(BARY_CORNER1)).toEqual([0, 65536, 0]);
    expect(decodeBary(BARY_CORNER2)).toEqual([0, 0, 65536]);
    expect(decodeBary(0)).toEqual([65536, 0, 0]);
    // The sentinels cannot be real points: their fields sum past 2^16.
    for (const s of [BARY_CORNER1, BARY_CORNER2]) {
      const { w1, w2 } = BARY_WORD.unpack(s);
      expect(w1 + w2).toBeGreaterThan(65536);
    }
    fc.assert(
      fc.property(fc.integer({ min: 0, max: 65535 }), fc.integer({ min: 0, max: 65535 }), (a, b) => {
        fc.pre(a + b <= 65536);
        const w = decodeBary(BARY_WORD.pack({ w1: a, w2: b }));
        expect(w).toEqual([65536 - a - b, a, b]);
      }),
    );
  });
});

describe('shared constants', () => {
  it('the WGSL prelude declares each constant once with its TypeScript value', () => {
    const parsed = [...constantsWgsl.matchAll(/const (\w+): u32 = (\d+)u;/g)].map((m) => [m[1], Number(m[2])]);
    expect(Object.fromEntries(parsed)).toEqual(SHARED_CONSTANTS);
    expect(parsed.length).toBe(Object.keys(SHARED_CONSTANTS).length);
  });

  it("the tessellator's shaders take their numbers and declarations from the generated prelude only", () => {
    for (const f of TESS_WGSL_FILES) {
      const code = readFileSync(new URL(`../../../wgsl/${f}.wgsl`, import.meta.url), 'utf8').replace(/\/\/[^\n]*/g, '');
      expect(code, f).not.toMatch(/@binding|struct Params/);
      for (const name of [...Object.keys(SHARED_CONSTANTS), ...Object.keys(TESS_CONSTANTS)]) {
        expect(code, `${f}: ${name}`).not.toMatch(new RegExp(`const ${name}\\b`));
      }
      // Workgroup sizes by name (WORKGROUP_SIZE, wgsl/tess/scan.wgsl THREADS = SCAN_WORKGROUP_SIZE), never typed.
      for (const m of code.matchAll(/@workgroup_size\(([^)]*)\)/g)) expect(m[1], f).toMatch(/^(WORKGROUP_SIZE|THREADS)$/);
      expect(code, f).not.toMatch(/\b(63|64|255|256|65535)u?\b/);
    }
    // The patch build likewise (its prelude: ccBuildPrelude; its words: src/gpu/cc/words.ts).
    const cc = readFileSync(new URL('../../../wgsl/cc/build.wgsl', import.meta.url), 'utf8').replace(/\/\/[^\n]*/g, '');
    expect(cc).not.toMatch(/@binding|struct Params|struct Range|const (GRID_X|WG|NONE|CC_NONE)\b/);
    for (const m of cc.matchAll(/@workgroup_size\(([^)]*)\)/g)) expect(m[1]).toBe('WORKGROUP_SIZE');
    // No packed word shifted by hand in the Catmull-Clark shaders.
    const surface = readFileSync(new URL('../../../wgsl/cc/surface.wgsl', import.meta.url), 'utf8').replace(/\/\/[^\n]*/g, '');
    for (const code of [cc, surface]) expect(code).not.toMatch(/>> \d+u\)? & |& (255|63|15|3|0xfff+)u\b/);
    // The instanced tessellator's and the ACC build's compute shaders likewise (constantsWgsl).
    for (const f of ['instanced/levels', 'instanced/headless', 'acc/build']) {
      const code = readFileSync(new URL(`../../../wgsl/${f}.wgsl`, import.meta.url), 'utf8').replace(/\/\/[^\n]*/g, '');
      expect(code, f).not.toMatch(/const (GRID_X|WORKGROUP_SIZE)\b|\b65535u?\b|\* 64u|workgroup_size\(64\)/);
    }
    // What the old shaders typed by hand, now from the prelude.
    expect(GRID_X).toBe(65535);
    expect([WORKGROUP_SIZE, SCAN_WORKGROUP_SIZE]).toEqual([64, 128]);
  });
});

// ---- The renderer's bindings: what each pipeline's WGSL declares against the contract's layouts.

type Declared = { group: number; binding: number; kind: string };

/** `@group(g) @binding(b) var<…> name: type;` → what kind of resource the layout must give. */
function declaredBindings(code: string): Declared[] {
  const out: Declared[] = [];
  const re = /@group\((\d+)\)\s*@binding\((\d+)\)\s*var(<[^>]*>)?\s+\w+\s*:\s*([^;]+);/g;
  for (const m of code.replace(/\/\/[^\n]*/g, '').matchAll(re)) {
    const space = (m[3] ?? '').replace(/[<>\s]/g, '');
    const type = m[4].trim();
    let kind: string;
    if (space === 'uniform') kind = 'buffer:uniform';
    else if (space === 'storage' || space === 'storage,read') kind = 'buffer:read-only-storage';
    else if (space === 'storage,read_write') kind = 'buffer:storage';
    else if (type === 'texture_depth_2d') kind = 'texture:depth';
    else if (type === 'sampler_comparison') kind = 'sampler:comparison';
    else if (type === 'sampler') kind = 'sampler:filtering';
    else if (type === 'texture_2d<f32>') kind = 'texture:f32';
    else kind = `unknown:${space}:${type}`;
    out.push({ group: Number(m[1]), binding: Number(m[2]), kind });
  }
  return out.sort((a, b) => a.group - b.group || a.binding - b.binding);
}

function layoutKind(e: GPUBindGroupLayoutEntry): string {
  if (e.buffer) return `buffer:${e.buffer.type ?? 'uniform'}`;
  if (e.texture) {
    const t = e.texture.sampleType ?? 'float';
    return `texture:${t === 'float' || t === 'unfilterable-float' ? 'f32' : t}`;
  }
  if (e.sampler) return `sampler:${e.sampler.type ?? 'filtering'}`;
  return 'other';
}

describe("the renderer's bindings", () => {
  for (const [name, groups] of Object.entries(RENDER_PIPELINE_GROUPS)) {
    it(`${name}: the shader declares exactly the bindings of its pipeline layout`, () => {
      const code = RENDER_SHADERS[name as keyof typeof RENDER_SHADERS].join('\n');
      const expected = groups
        .flatMap((g, group) =>
          (RENDER_BIND_GROUPS[g] as readonly GPUBindGroupLayoutEntry[]).map((e) => ({ group, binding: e.binding, kind: layoutKind(e) })),
        )
        .sort((a, b) => a.group - b.group || a.binding - b.binding);
      expect(declaredBindings(code)).toEqual(expected);
    });
  }

  it('every layout entry is visible to a stage, and compute layouts only to compute', () => {
    for (const [name, entries] of Object.entries(RENDER_BIND_GROUPS)) {
      for (const e of entries) {
        expect(e.visibility & (STAGE.VERTEX | STAGE.FRAGMENT | STAGE.COMPUTE), name).toBeGreaterThan(0);
        if (e.visibility & STAGE.COMPUTE) expect(e.visibility, name).toBe(STAGE.COMPUTE);
      }
    }
  });

  it('the scene uniforms are declared once, by the generated prelude, and read by every render shader', () => {
    for (const [name, sources] of Object.entries(RENDER_SHADERS)) {
      const code = sources.join('\n');
      const structs = code.match(/struct SceneUniforms/g)?.length ?? 0;
      if (name === 'wireArgs') expect(structs).toBe(0);
      else {
        expect(structs, name).toBe(1);
        expect(code, name).toMatch(/\bscene\.\w+/);
      }
    }
  });
});

/** Every `.wgsl` file of these folders of wgsl/, by its path under wgsl/. */
function wgslFiles(...dirs: string[]): string[] {
  return dirs.flatMap((d) =>
    readdirSync(new URL(`../../../wgsl/${d}/`, import.meta.url))
      .filter((f) => f.endsWith('.wgsl'))
      .map((f) => `${d}/${f}`),
  );
}

/** The bindings `spec`'s layout entries give, as declaredBindings reads them. */
function specBindings(spec: { group: number; layoutEntries(): GPUBindGroupLayoutEntry[] }): Declared[] {
  return spec.layoutEntries().map((e) => ({ group: spec.group, binding: e.binding, kind: layoutKind(e) }));
}

describe("the renderer's, wireframe's and blit's bindings come from the contract", () => {
  it('no render WGSL file declares a binding by hand', () => {
    const files = wgslFiles('render');
    expect(files.length).toBeGreaterThan(5);
    for (const f of files) {
      const code = readFileSync(new URL(`../../../wgsl/${f}`, import.meta.url), 'utf8').replace(/\/\/[^\n]*/g, '');
      expect(code, f).not.toMatch(/@binding|@group/);
    }
  });

  it('the layouts are the ones written out by hand before (behaviour unchanged)', () => {
    const V = STAGE.VERTEX;
    const F = STAGE.FRAGMENT;
    const C = STAGE.COMPUTE;
    expect(RENDER_BIND_GROUPS).toEqual({
      scene: [{ binding: 0, visibility: V | F, buffer: { type: 'uniform' } }],
      shading: [
        { binding: 0, visibility: F, texture: { sampleType: 'depth' } },
        { binding: 1, visibility: F, sampler: { type: 'comparison' } },
      ],
      vertexStorage: [
        { binding: 0, visibility: V, buffer: { type: 'read-only-storage' } },
        { binding: 1, visibility: V, buffer: { type: 'read-only-storage' } },
      ],
      wireArgs: [
        { binding: 0, visibility: C, buffer: { type: 'read-only-storage' } },
        { binding: 1, visibility: C, buffer: { type: 'storage' } },
      ],
    });
    expect(HEAT_RENDER_GROUP.layoutEntries()).toEqual([
      { binding: 0, visibility: V, buffer: { type: 'read-only-storage' } },
      { binding: 1, visibility: V | F, buffer: { type: 'uniform' } },
    ]);
    // src/gpu/acc/heat.ts still spells the same layout out (no longer used by the renderer).
    expect(BLIT_GROUP.layoutEntries()).toEqual([{ binding: 0, visibility: F, texture: { sampleType: 'unfilterable-float' } }]);
  });

  it('the wireframe and the patch colours share one layout (vertexStorage) under other names', () => {
    expect(WIRE_LINES_GROUP.layoutEntries()).toEqual(PATCH_KIND_GROUP.layoutEntries());
    expect(RENDER_PIPELINE_GROUPS.wireframe.indexOf('vertexStorage')).toBe(WIRE_LINES_GROUP.group);
    expect(RENDER_PIPELINE_GROUPS.lit.indexOf('vertexStorage')).toBe(PATCH_KIND_GROUP.group);
    expect(RENDER_PIPELINE_GROUPS.lit.indexOf('shading')).toBe(SHADING_GROUP.group);
    expect(RENDER_PIPELINE_GROUPS.ground.indexOf('shading')).toBe(SHADING_GROUP.group);
    expect(RENDER_PIPELINE_GROUPS.wireArgs.indexOf('wireArgs')).toBe(WIRE_ARGS_GROUP.group);
    expect(RENDER_PIPELINE_GROUPS.shadow.indexOf('scene')).toBe(SCENE_GROUP.group);
  });

  it('the heat and blit shaders declare exactly the bindings of their layouts', () => {
    const heatExpected = [...specBindings(SCENE_GROUP), ...specBindings(HEAT_RENDER_GROUP)];
    expect(declaredBindings(HEAT_SHADER.join('\n'))).toEqual(heatExpected);
    expect(declaredBindings(BLIT_SHADER.join('\n'))).toEqual(specBindings(BLIT_GROUP));
  });

  it('a texture or sampler entry is declared without an address space, with its own visibility', () => {
    const g = defineBindGroup(
      3,
      {
        t: { binding: 0, type: 'texture_depth_2d', texture: { sampleType: 'depth' } },
        s: { binding: 1, type: 'sampler_comparison', sampler: { type: 'comparison' }, visibility: STAGE.VERTEX },
      },
      STAGE.FRAGMENT,
    );
    expect(g.wgsl()).toBe('@group(3) @binding(0) var t: texture_depth_2d;\n@group(3) @binding(1) var s: sampler_comparison;\n');
    expect(g.layoutEntries()).toEqual([
      { binding: 0, visibility: STAGE.FRAGMENT, texture: { sampleType: 'depth' } },
      { binding: 1, visibility: STAGE.VERTEX, sampler: { type: 'comparison' } },
    ]);
  });
});

// ---- Tools the tessellator will use: bind groups from one spec, bindings used by an entry point, arenas.

describe('defineBindGroup and usedBindings', () => {
  const group = defineBindGroup(0, {
    params: { binding: 0, space: 'uniform', type: 'Params' },
    cage: { binding: 2, space: 'read', type: 'array<f32>', doc: 'xyz per vertex' },
    work: { binding: 3, space: 'read_write', type: 'array<u32>' },
    out: { binding: 5, space: 'read_write', type: 'array<f32>' },
  });

  it('the generated declarations parse back to the layout entries', () => {
    const expected = group.layoutEntries().map((e) => ({ group: 0, binding: e.binding, kind: layoutKind(e) }));
    expect(declaredBindings(group.wgsl())).toEqual(expected);
    expect(declaredBindings(group.wgsl(['work', 'params']))).toEqual(expected.filter((e) => e.binding === 0 || e.binding === 3));
    expect(group.layoutEntries(['out']).map((e) => [e.binding, e.visibility, e.buffer?.type])).toEqual([[5, STAGE.COMPUTE, 'storage']]);
    expect(() =>
      defineBindGroup(0, { a: { binding: 1, space: 'read', type: 'array<u32>' }, b: { binding: 1, space: 'read', type: 'array<u32>' } }),
    ).toThrow(/share binding 1/);
  });

  it('usedBindings follows the calls of an entry point, and only its own', () => {
    const code = `${group.wgsl()}
fn cageAt(i: u32) -> f32 { return cage[i]; } // out is named in a comment only
fn count(i: u32) -> u32 { return work[params.n + i] + u32(cageAt(i)); }
@compute @workgroup_size(64) fn countMain(@builtin(global_invocation_id) id: vec3<u32>) {
  work[id.x] = count(id.x);
}
@compute @workgroup_size(64) fn emitMain(@builtin(global_invocation_id) id: vec3<u32>) {
  out[id.x] = 1.0; /* cage[0] in a block comment */
}`;
    const names = ['params', 'cage', 'work', 'out'] as const;
    expect(usedBindings(code, 'countMain', names)).toEqual(['params', 'cage', 'work']);
    expect(usedBindings(code, 'emitMain', names)).toEqual(['out']);
    expect(() => usedBindings(code, 'missing', names)).toThrow(/no fn missing/);
  });

  it("on the renderer's shaders: every binding a pipeline's layout holds is used by one of its entry points", () => {
    const entries: Record<keyof typeof RENDER_SHADERS, string[]> = {
      shadow: ['shadowVertex'],
      lit: ['litVertex', 'litFragment'],
      ground: ['groundVertex', 'groundFragment'],
      backdrop: ['backdropVertex', 'backdropFragment'],
      wireframe: ['wireVertex', 'wireFragment'],
      cage: ['cageVertex', 'cageFragment'],
      wireArgs: ['wireArgsMain'],
    };
    for (const [name, sources] of Object.entries(RENDER_SHADERS) as [keyof typeof RENDER_SHADERS, readonly string[]][]) {
      const code = sources.join('\n');
      const declared = [...code.matchAll(/@group\(\d+\)\s*@binding\(\d+\)\s*var(?:<[^>]*>)?\s+(\w+)/g)].map((m) => m[1]);
      const used = new Set(entries[name].flatMap((e) => usedBindings(code, e, declared)));
      expect([...used].sort(), name).toEqual([...declared].sort());
    }
  });
});

describe('defineArena', () => {
  const arena = defineArena<'edgeF' | 'edgeBase' | 'rows', { edges: number; tris: number }>([
    ['edgeF', (s) => s.edges],
    ['edgeBase', (s) => s.edges + 1],
    ['rows', (s) => 2 * s.tris],
  ]);

  it('lays the arrays one after another without overlap, for any sizes', () => {
    fc.assert(
      fc.property(fc.nat(10_000), fc.nat(10_000), (edges, tris) => {
        const l = arena.layout({ edges, tris });
        let at = 0;
        for (const k of arena.names) {
          expect(l.offset[k]).toBe(at);
          at += l.length[k];
        }
        expect(l.words).toBe(at);
        expect(l.length).toEqual({ edgeF: edges, edgeBase: edges + 1, rows: 2 * tris });
      }),
    );
    expect(() => arena.layout({ edges: -2, tris: 0 })).toThrow(/words/);
  });

  it('its offset fields fit a uniform struct, and the accessors read through them', () => {
    const params = defineStruct('Params', [['nEdges', 'u32'], ...arena.offsetFields] as const);
    const parsed = parseStruct(params.wgsl);
    expect(parsed.fields.map((f) => f.name)).toEqual(['nEdges', 'offEdgeF', 'offEdgeBase', 'offRows']);
    const l = arena.layout({ edges: 5, tris: 7 });
    const view = new DataView(new ArrayBuffer(params.size));
    params.write(view, arena.offsets(l));
    expect([4, 8, 12].map((o) => view.getUint32(o, true))).toEqual([0, 5, 11]);
    expect(arena.wgslAccessors('work', 'params')).toContain('fn edgeBase_at(i: u32) -> u32 { return work[params.offEdgeBase + i]; }');
  });
});

describe('render constants', () => {
  it('the prelude declares the ground extent and the patch palette with the TypeScript values', () => {
    expect(Number(/const GROUND_EXTENT: f32 = ([\d.]+);/.exec(sceneWgsl)?.[1])).toBe(GROUND_EXTENT);
    const palette = /const PATCH_SRGB = array<vec3f, (\d+)>\((.*)\);/.exec(sceneWgsl);
    expect(Number(palette?.[1])).toBe(PATCH_COLOURS.length);
    const colours = [...(palette?.[2] ?? '').matchAll(/vec3f\(([^)]*)\)/g)].map((m) => m[1].split(',').map(Number));
    // Indexed by kind: the shader's PATCH_SRGB[k] is kind k's colour.
    expect(colours).toEqual(PATCH_COLOURS.map((p) => [...p.srgb]));
    expect(PATCH_COLOURS.map((p) => p.kind)).toEqual(PATCH_COLOURS.map((_, i) => i));
    // Each f32 literal reads back as the same f32 as the TypeScript number.
    for (const x of [4, 0.56, 0.8, 1e-7, 123.25]) expect(Math.fround(Number(wgslF32(x)))).toBe(Math.fround(x));
    expect(wgslF32(4)).toBe('4.0');
  });

  it('no render shader types a colour of the palette or the ground extent again', () => {
    const files = ['wgsl/render/lit.wgsl', 'wgsl/render/ground.wgsl', 'wgsl/render/common.wgsl', 'wgsl/render/shading.wgsl'];
    for (const f of files) {
      const text = readFileSync(new URL(`../../../${f}`, import.meta.url), 'utf8').replace(/\/\/[^\n]*/g, '');
      expect(text, f).not.toMatch(/const\s+(GROUND_EXTENT|PATCH_SRGB)\b/);
      for (const p of PATCH_COLOURS) expect(text, `${f}: ${p.name}`).not.toContain(`vec3f(${p.srgb.join(', ')})`);
    }
  });
});

// ---- The compute tessellator's contract: Params, its arenas, its bindings, its prelude.

/** The tessellator's WGSL files (the Catmull-Clark ones are another team's, read here only). */
const TESS_WGSL_FILES = [
  'tess/common',
  'tess/outputs',
  'tess/factors',
  'tess/count',
  'tess/weld',
  'tess/pattern',
  'tess/plan',
  'tess/emit',
  'tess/scan',
];

describe("the tessellator's contract", () => {
  for (const struct of [TESS_PARAMS] as {
    wgsl: string;
    size: number;
    offset: Record<string, number>;
    write: (v: DataView, x: Record<string, number | number[]>) => void;
  }[]) {
    const parsed = parseStruct(struct.wgsl);
    it(`${parsed.name}: the generated struct parses back to the offsets and size TypeScript writes at, every word of it`, () => {
      expect(parsed.size).toBe(struct.size);
      expect(Object.keys(struct.offset)).toEqual(parsed.fields.map((f) => f.name));
      const view = new DataView(new ArrayBuffer(struct.size));
      const values: Record<string, number | number[]> = {};
      let next = 1;
      for (const f of parsed.fields) {
        expect(struct.offset[f.name], f.name).toBe(f.offset);
        values[f.name] = f.size === 4 ? next++ : Array.from({ length: f.size / 4 }, () => next++);
      }
      struct.write(view, values);
      for (const f of parsed.fields) {
        const words = Array.from({ length: f.size / 4 }, (_, i) =>
          f.type === 'u32' ? view.getUint32(f.offset + 4 * i, true) : view.getFloat32(f.offset + 4 * i, true),
        );
        expect(words, f.name).toEqual(typeof values[f.name] === 'number' ? [values[f.name]] : values[f.name]);
      }
    });
  }

  const sizes = fc.record({
    vertices: fc.nat(50_000),
    extraSlots: fc.nat(10_000),
    edges: fc.nat(150_000),
    triangles: fc.nat(100_000),
    maxFactor: fc.constantFrom(8, 64, 256),
    tableWords: fc.nat(100_000),
    ccWords: fc.nat(100_000),
    ccPoints: fc.nat(100_000),
    limitVertices: fc.nat(50_000),
    accTriangles: fc.nat(100_000),
    accPatchWords: fc.nat(100_000),
    accPoints: fc.nat(100_000),
    heightWords: fc.nat(100_000),
    dispTriangles: fc.nat(100_000),
    dispEdges: fc.nat(100_000),
    cornerUvs: fc.nat(100_000),
  }) as fc.Arbitrary<TessSizes>;

  it('each arena lays its arrays one after another, and its offsets reach Params at the fields the shaders read', () => {
    const parsed = parseStruct(TESS_PARAMS.wgsl);
    const at = Object.fromEntries(parsed.fields.map((f) => [f.name, f]));
    fc.assert(
      fc.property(sizes, (s) => {
        for (const arena of [TESS_STATIC, TESS_CAGE, TESS_WORK] as unknown as (typeof TESS_WORK)[]) {
          const l = arena.layout(s);
          let words = 0;
          for (const k of arena.names) {
            expect(l.offset[k]).toBe(words);
            words += l.length[k];
          }
          expect(l.words).toBe(words);
          const view = new DataView(new ArrayBuffer(TESS_PARAMS.size));
          const offsets = arena.offsets(l);
          TESS_PARAMS.write(view, offsets);
          for (const [field, value] of Object.entries(offsets)) {
            expect(at[field]?.type, field).toBe('u32');
            expect(view.getUint32(at[field].offset, true)).toBe(value);
          }
        }
      }),
      { numRuns: 50 },
    );
  });

  it('the Catmull-Clark words lay their sections one after another, and their offsets plus cc reach Params at ccTri, ccPoly, …', () => {
    const parsed = parseStruct(TESS_PARAMS.wgsl);
    const at = Object.fromEntries(parsed.fields.map((f) => [f.name, f]));
    // The fields the Catmull-Clark shaders read, in the order the Params struct has always held them.
    const fields = [
      'ccTri',
      'ccPoly',
      'ccRegions',
      'ccPatchIdx',
      'ccFans',
      'ccSectors',
      'ccThreads',
      'ccCos',
      'ccRules',
      'ccInputs',
      'ccVertexFan',
    ];
    expect(CC_STATIC.offsetFields.map(([f]) => f)).toEqual(fields);
    const first = at.ccTri.offset;
    fields.forEach((f, i) => expect(at[f].offset, f).toBe(first + 4 * i));
    const sizes = fc.record(
      Object.fromEntries(CC_STATIC.names.map((k) => [k, fc.nat(100_000)])) as Record<CcSection, fc.Arbitrary<number>>,
    );
    fc.assert(
      fc.property(sizes, fc.nat(1_000_000), (s, base) => {
        const l = CC_STATIC.layout(s);
        let words = 0;
        for (const k of CC_STATIC.names) {
          expect(l.offset[k]).toBe(words);
          expect(l.length[k]).toBe(s[k]);
          words += s[k];
        }
        expect(l.words).toBe(words);
        const view = new DataView(new ArrayBuffer(TESS_PARAMS.size));
        const offsets = CC_STATIC.offsets(l, base);
        TESS_PARAMS.write(view, offsets);
        CC_STATIC.names.forEach((k, i) => expect(view.getUint32(at[fields[i]].offset, true)).toBe(base + l.offset[k]));
      }),
      { numRuns: 50 },
    );
  });

  it("every Params field a shader reads exists (the tessellator's files and the Catmull-Clark ones)", () => {
    const fields = new Set(Object.keys(TESS_PARAMS.offset));
    for (const f of [...TESS_WGSL_FILES, 'surface/phong', 'cc/surface', 'cc/build']) {
      const code = readFileSync(new URL(`../../../wgsl/${f}.wgsl`, import.meta.url), 'utf8').replace(/\/\/[^\n]*/g, '');
      for (const m of code.matchAll(/\bparams\.(\w+)/g)) expect(fields.has(m[1]), `${f}: params.${m[1]}`).toBe(true);
    }
  });

  it('the prelude declares each binding of the group once, as the layout entries say; sample evaluation gets the inputs only', () => {
    const kinds = (entries: GPUBindGroupLayoutEntry[]) => entries.map((e) => ({ group: 0, binding: e.binding, kind: layoutKind(e) }));
    expect(declaredBindings(tessPrelude())).toEqual(kinds(TESS_GROUP.layoutEntries()));
    expect(declaredBindings(tessPrelude(TESS_INPUTS))).toEqual(kinds(TESS_GROUP.layoutEntries([...TESS_INPUTS])));
    // The names in the WGSL are the group's keys.
    const names = [...tessPrelude().matchAll(/var<[^>]*>\s+(\w+)\s*:/g)].map((m) => m[1]);
    expect(names).toEqual(TESS_BINDINGS);
  });

  it("the prelude's constants hold the TypeScript values, each declared once (shared, then the tessellator's)", () => {
    const parsed = [...tessPrelude().matchAll(/const (\w+): u32 = (\d+)u;/g)].map((m) => [m[1], Number(m[2])] as const);
    expect(new Set(parsed.map(([n]) => n)).size).toBe(parsed.length);
    expect(Object.fromEntries(parsed)).toEqual({ ...SHARED_CONSTANTS, ...TESS_CONSTANTS });
  });

  it('the table header getters read the words that the tables writer and reader use', () => {
    const prelude = tessPrelude();
    const getters = [...prelude.matchAll(/fn tableHeader_(\w+)\(\) -> u32 \{ return staticBuf\[params\.offTables \+ (\d+)u\]; \}/g)];
    expect(getters.map((m) => [m[1], Number(m[2])])).toEqual(TABLE_HEADER_FIELDS.map((f) => [f, TABLE_HEADER[f]]));
    const words = bakeTables(8);
    const t = new PatternTables(words);
    expect([t.maxFactor, t.slotCount, t.stateCount]).toEqual([
      words[TABLE_HEADER.maxFactor],
      words[TABLE_HEADER.slotCount],
      words[TABLE_HEADER.stateCount],
    ]);
    expect(words[TABLE_HEADER.totalWords]).toBe(words.length);
  });

  // The hand table the derived bindings replaced (tessellator.ts PASS_BINDINGS, with 'auto'
  // layouts, which bind exactly what an entry point uses): derivation must give the same.
  // (bulge came after it: params, static, cage, work, as the factors pass.)
  const HAND_TABLE: Record<string, number[]> = {
    bulge: [0, 1, 2, 3],
    // (the factors pass: [0, 1, 2, 3], folded into count since)
    count: [0, 1, 2, 3],
    // (the scan's steps and the budget became tessellator passes with the one-chain rebuild)
    scanReduce: [0, 3],
    // (the budget: [0, 3, 9, 10, 11], folded into scanDown since)
    scanDown: [0, 1, 3, 9, 10, 11], // the tables: the edges' lines at the chosen candidate
    plan: [0, 1, 3],
    // (the weld's corners and edges, in emit's vertices since)
    emitVertices: [0, 1, 2, 3, 4, 5, 6, 7],
    emitTriangles: [0, 1, 3, 8],
    ccPoints: [0, 1, 2, 3],
    ccSlices: [0, 1, 2],
    ccLimits: [0, 1, 2],
  };
  for (const surface of ['phong', 'catmull-clark'] as const) {
    it(`${surface}: each pass binds what its entry point uses, as the hand table did, from the contract's group`, () => {
      const passes = tessellatorPasses(surface);
      expect(passes.length).toBe(surface === 'phong' ? 7 : 10);
      for (const pass of passes) {
        const { names, entries } = passBindings(pass);
        expect(
          entries.map((e) => e.binding),
          pass.name,
        ).toEqual(HAND_TABLE[pass.name]);
        const group = pass.group === 'ccBuild' ? CC_BUILD_GROUP : TESS_GROUP;
        expect(entries, pass.name).toEqual(group.layoutEntries(names as never[]));
      }
    });
  }
});

describe("the ACC build's contract", () => {
  const read = (f: string) => readFileSync(new URL(`../../../wgsl/${f}.wgsl`, import.meta.url), 'utf8').replace(/\/\/[^\n]*/g, '');

  it('AccBuildParams parses back to the offsets and size TypeScript writes at: nPatches, then an offset per section', () => {
    const parsed = parseStruct(ACC_BUILD_PARAMS.wgsl);
    expect(parsed.name).toBe('AccBuildParams');
    expect(parsed.size).toBe(ACC_BUILD_PARAMS.size);
    // The hand-typed struct it replaced: 10 u32 and two pads, 48 bytes.
    expect(ACC_BUILD_PARAMS.size).toBe(48);
    expect(parsed.fields.map((f) => f.name)).toEqual(['nPatches', ...ACC_STATIC.offsetFields.map(([f]) => f)]);
    for (const f of parsed.fields) {
      expect(f.type, f.name).toBe('u32');
      expect(ACC_BUILD_PARAMS.offset[f.name as keyof typeof ACC_BUILD_PARAMS.offset], f.name).toBe(f.offset);
    }
    // The fields the shader reads, where the hand-typed struct had them (word i).
    const hand = [
      'nPatches',
      'offCorners',
      'offRingOffs',
      'offRingData',
      'offValOffs',
      'offValData',
      'offSectors',
      'offSecOffs',
      'offSecData',
      'offOrder',
    ];
    hand.forEach((f, i) => expect(ACC_BUILD_PARAMS.offset[f as keyof typeof ACC_BUILD_PARAMS.offset], f).toBe(4 * i));
    const fields = new Set(Object.keys(ACC_BUILD_PARAMS.offset));
    for (const m of read('acc/build').matchAll(/\bbp\.(\w+)/g)) expect(fields.has(m[1]), `bp.${m[1]}`).toBe(true);
  });

  it('ACC_STATIC lays its sections one after another, and its offsets reach AccBuildParams', () => {
    const parsed = parseStruct(ACC_BUILD_PARAMS.wgsl);
    const at = Object.fromEntries(parsed.fields.map((f) => [f.name, f]));
    const sizes = fc.record(
      Object.fromEntries(ACC_STATIC.names.map((k) => [k, fc.nat(100_000)])) as Record<AccSection, fc.Arbitrary<number>>,
    );
    fc.assert(
      fc.property(sizes, fc.nat(100_000), (s, nPatches) => {
        const l = ACC_STATIC.layout(s);
        let words = 0;
        for (const k of ACC_STATIC.names) {
          expect(l.offset[k]).toBe(words);
          words += s[k];
        }
        expect(l.words).toBe(words);
        const view = new DataView(new ArrayBuffer(ACC_BUILD_PARAMS.size));
        ACC_BUILD_PARAMS.write(view, { nPatches, ...ACC_STATIC.offsets(l) });
        // The words the old positional write gave: nPatches, the offsets in section order, two zero pads.
        const expected = [nPatches, ...ACC_STATIC.names.map((k) => l.offset[k]), 0, 0];
        expect(Array.from(new Uint32Array(view.buffer))).toEqual(expected);
        expect(view.getUint32(at.offSectors.offset, true)).toBe(l.offset.sectors);
      }),
      { numRuns: 50 },
    );
  });

  it('the prelude declares each binding of the group once, as the layout entries say, and the shader none by hand', () => {
    const prelude = accBuildPrelude();
    const kinds = ACC_BUILD_GROUP.layoutEntries().map((e) => ({ group: 0, binding: e.binding, kind: layoutKind(e) }));
    expect(declaredBindings(prelude)).toEqual(kinds);
    expect([...prelude.matchAll(/var<[^>]*>\s+(\w+)\s*:/g)].map((m) => m[1])).toEqual(Object.keys(ACC_BUILD_GROUP.binding));
    expect(prelude).toContain(ACC_SECTOR_WORD.wgsl);
    const code = read('acc/build');
    expect(code).not.toMatch(/@binding|struct AccBuildParams/);
    // No packed word shifted by hand: the sector word through its getters.
    expect(code).not.toMatch(/>> \d+u\)? & |& (255|63|15|3|0x3fff)u\b|\bsec >> /);
    expect(code).toMatch(/accSectorWord_kind\(sec\)/);
  });

  it("ACC_TRI_WORD's corners are read bit by bit through AccTriCorners, which fills that field exactly, never shifted by hand", () => {
    const [, width] = ACC_TRI_WORD.fields.corners;
    const bits = Object.values(ACC_TRI_CORNERS.fields).reduce((n, [at, b]) => Math.max(n, at + b), 0);
    expect(bits).toBe(width);
    // Bit 2i: u_i, bit 2i + 1: v_i (src/gpu/acc/surface.ts accTriangleWords packs them so).
    for (let i = 0; i < 3; i++) {
      expect(ACC_TRI_CORNERS.fields[`u${i}` as 'u0']).toEqual([2 * i, 1]);
      expect(ACC_TRI_CORNERS.fields[`v${i}` as 'v0']).toEqual([2 * i + 1, 1]);
    }
    expect(tessPrelude()).toContain(ACC_TRI_CORNERS.wgsl);
    for (const f of ['acc/surface-tess', 'acc/heat']) {
      const code = read(f);
      expect(code, f).not.toMatch(/>> \d+u\)? & |\b[cm] & 1u\b|\bm >> 6u/);
      expect(code, f).toMatch(/accTriCorners_u0\(c\)/);
    }
  });

  it('the error pass declares its bindings from HEAT_GROUP, after the inputs it shares with the tessellator, each entry point using what heat.ts binds', () => {
    const code = heatComputeCode();
    const kinds = (entries: GPUBindGroupLayoutEntry[]) => entries.map((e) => ({ group: 0, binding: e.binding, kind: layoutKind(e) }));
    const group0 = declaredBindings(code).filter((d) => d.group === 0);
    expect(group0).toEqual(kinds([...TESS_GROUP.layoutEntries([...TESS_INPUTS]), ...HEAT_GROUP.layoutEntries()]));
    expect(
      declaredBindings(code)
        .filter((d) => d.group === 1)
        .map((d) => [d.binding, d.kind]),
    ).toEqual([
      [0, 'buffer:read-only-storage'],
      [1, 'buffer:read-only-storage'],
    ]);
    // What src/gpu/acc/heat.ts encode() binds for each entry point: its explicit layouts must hold exactly these.
    const used = (entry: string) => [...usedBindings(code, entry, TESS_INPUTS), ...usedBindings(code, entry, HEAT_BINDINGS)];
    expect(used('heatArgs')).toEqual(['aux', 'heatPass', 'outCounts', 'dispatchArgs']);
    expect(used('heatErrors')).toEqual(['params', 'staticBuf', 'cageBuf', 'work', 'srcTri', 'bary', 'aux', 'heatPass']);
    expect(used('heatTotals')).toEqual(['aux', 'heatPass']);
    expect(read('acc/heat')).not.toMatch(/@binding/);
  });
});
