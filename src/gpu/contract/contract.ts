/**
 * What the TypeScript and the WGSL must agree on, declared once. Each declaration gives both
 * sides: the WGSL text that is prepended to the shaders, and the TypeScript that writes or reads
 * the same bytes. Nothing here is counted by hand twice.
 *
 *   constants     shared numbers (workgroup sizes, the dispatch grid's width, sentinels), exported
 *                 as TypeScript values and as a WGSL `const` prelude (constantsWgsl)
 *   packed words  bit-field specs (defineBits): WGSL getters `word_field(w)` and a packer
 *                 `word_pack(...)`, and the TypeScript pack/unpack of the same bits
 *   uniforms      uniform structs (defineStruct in layout.ts): the WGSL struct and its byte offsets
 *   bindings      the renderer's bind group layouts and which pipeline uses which, as the
 *                 descriptors the renderer creates (RENDER_BIND_GROUPS, RENDER_PIPELINE_GROUPS);
 *                 for compute code, defineBindGroup (declarations generated from one spec) and
 *                 usedBindings (what an entry point reads, for its explicit layout)
 *   arenas        arrays carved out of one storage buffer (defineArena): offsets, the uniform
 *                 fields that carry them, and WGSL accessors
 *
 * The compute tessellator's side: its three buffers as arenas (TESS_STATIC, TESS_CAGE, TESS_WORK),
 * whose offsets are fields of its uniforms (TESS_PARAMS); its one bind group (TESS_GROUP), of
 * which each pass binds what its entry point uses; the scan's uniforms (SCAN_PARAMS); the owner
 * word, the table header, its constants; and tessPrelude, what its shaders start with.
 * (The Catmull-Clark words of src/gpu/cc/build.ts are still decoded by hand there and in
 * wgsl/cc/build.wgsl and wgsl/cc/surface.wgsl: that code is being rewritten.)
 *
 * tests/gpu/contract/contract.test.ts parses the generated WGSL back and checks it against the TypeScript
 * views; tests/gpu/contract/contract.gpu.test.ts runs it through a real WGSL compiler.
 */
import { ONE } from '../../pattern/fixed.ts';
import { TABLE_HEADER_FIELDS } from '../../pattern/tables.ts';
import { STRIP_DP_VERTICES } from '../../pattern/clamped.ts';
import { defineStruct } from './layout.ts';

// ---------------------------------------------------------------------------------------------
// Constants

/** Threads per workgroup of the tessellator's one-thread-per-item passes. */
export const WORKGROUP_SIZE = 64;
/** Threads per workgroup of the prefix-sum passes (wgsl/tess/scan.wgsl): 128, the most WebGPU's
 * compatibility mode allows (maxComputeInvocationsPerWorkgroup), so no pass needs more. */
export const SCAN_WORKGROUP_SIZE = 128;
/** Values each scan thread sums serially (wgsl/tess/scan.wgsl): one scan workgroup covers
 * SCAN_WORKGROUP_SIZE × SCAN_ITEMS = 4096 values. */
export const SCAN_ITEMS = 32;
/** Widest dispatch in x (WebGPU's default maxComputeWorkgroupsPerDimension); wider ones fold into y. */
export const GRID_X = 65535;

/** GPUShaderStage's bits (fixed by the WebGPU specification; the global is absent outside a GPU runtime). */
export const STAGE = { VERTEX: 1, FRAGMENT: 2, COMPUTE: 4 } as const;

/** The numbers every shader may read, by their WGSL names (all u32). */
export const SHARED_CONSTANTS = { WORKGROUP_SIZE, SCAN_WORKGROUP_SIZE, SCAN_ITEMS, GRID_X } as const;

/** `const NAME: u32 = value;` for each entry (u32 only: the shared numbers are counts and sizes). */
export function wgslConstants(constants: Readonly<Record<string, number>>): string {
  return Object.entries(constants)
    .map(([name, value]) => {
      if (!Number.isInteger(value) || value < 0 || value > 0xffffffff) throw new Error(`${name} = ${value} is not a u32`);
      return `const ${name}: u32 = ${value}u;`;
    })
    .join('\n')
    .concat('\n');
}

/** Workgroup counts as a 2D grid: WebGPU caps each dimension at GRID_X (an over-limit indirect
 * dispatch silently does nothing; a direct one is a validation error). Shaders fold y back:
 * (wid.y * GRID_X + wid.x) * WORKGROUP_SIZE + lid. */
export function grid2d(groups: number): [number, number] {
  if (groups <= GRID_X) return [Math.max(groups, 1), 1];
  return [GRID_X, Math.ceil(groups / GRID_X)];
}

/** Workgroups of WORKGROUP_SIZE threads for one thread per item, folded into 2D. */
export function groupsFor(items: number): [number, number] {
  return grid2d(Math.ceil(items / WORKGROUP_SIZE));
}

/** The WGSL prelude of the shared constants. */
export const constantsWgsl = wgslConstants(SHARED_CONSTANTS);

// ---------------------------------------------------------------------------------------------
// Packed words

/** A bit field: its lowest bit and its width. */
export type BitRange = readonly [at: number, bits: number];

export interface BitWord<K extends string> {
  readonly name: string;
  readonly fields: Readonly<Record<K, BitRange>>;
  /** WGSL: `fn name_field(w: u32) -> u32` for each field and `fn name_pack(field, …) -> u32`
   * (the low bits of each value; shifts and masks). */
  readonly wgsl: string;
  /** The word with these field values (every field named; booleans as 0/1). Throws on a value
   * that does not fit its field: the WGSL packer would silently truncate it. */
  pack(values: Readonly<Record<K, number | boolean>>): number;
  unpack(word: number): Record<K, number>;
  get(word: number, field: K): number;
}

/** The WGSL function prefix of a word: its name with a lower-case first letter (NodeWord → nodeWord). */
export function wgslPrefix(name: string): string {
  return name[0].toLowerCase() + name.slice(1);
}

/**
 * A u32 split into named bit fields, declared once for both languages, e.g.
 * `defineBits('NodeWord', { kind: [0, 2], child: [2, 30] })` gives the WGSL getters
 * `nodeWord_kind(w)` and `nodeWord_child(w)`, the WGSL packer `nodeWord_pack(kind, child)`, and
 * `.pack({ kind, child })` / `.unpack(w)` in TypeScript. Fields must fit in 32 bits and not overlap;
 * the order of declaration is the packer's argument order.
 */
export function defineBits<K extends string>(name: string, fields: Readonly<Record<K, BitRange>>): BitWord<K> {
  const entries = Object.entries(fields) as [K, BitRange][];
  let used = 0;
  for (const [field, [at, bits]] of entries) {
    if (!Number.isInteger(at) || !Number.isInteger(bits) || bits < 1 || at < 0 || at + bits > 32) {
      throw new Error(`${name}.${field}: bits [${at}, ${at + bits}) do not fit a u32`);
    }
    const mask = maskOf(at, bits);
    if (used & mask) throw new Error(`${name}.${field} overlaps another field`);
    used |= mask;
  }
  const fieldNames = entries.map(([f]) => f);
  const fieldScale = entries.map(([, [at]]) => 2 ** at);
  const fieldLimit = entries.map(([, [, bits]]) => 2 ** bits);
  const prefix = wgslPrefix(name);
  // Shifts and masks rather than extractBits/insertBits: the same bits, but Tint polyfills those
  // two builtins (clamping their offset and count) and a software GPU's compiler keeps the calls.
  const getters = entries.map(([f, [at, bits]]) => `fn ${prefix}_${f}(w: u32) -> u32 { return ${wgslField('w', at, bits)}; }`);
  const packer = [
    `fn ${prefix}_pack(${entries.map(([f]) => `${f}: u32`).join(', ')}) -> u32 {`,
    '  var w = 0u;',
    ...entries.map(([f, [at, bits]]) => `  w = w | (${bits === 32 ? f : `(${f} & ${hex(2 ** bits - 1)})`} << ${at}u);`),
    '  return w;',
    '}',
  ];
  const wgsl = `// ${name}: ${entries.map(([f, [at, bits]]) => `${f} [${at}, ${at + bits})`).join(', ')}\n${getters.join('\n')}\n${packer.join('\n')}\n`;
  return {
    name,
    fields,
    wgsl,
    pack(values) {
      // Hot (the Catmull-Clark preparation packs a word per refined point): plain arrays, no
      // destructuring, no Number() of numbers.
      let w = 0;
      for (let i = 0; i < fieldNames.length; i++) {
        const raw: number | boolean = values[fieldNames[i]];
        const v = raw === true ? 1 : raw === false ? 0 : raw;
        if (!(v >= 0 && v < fieldLimit[i]) || v !== Math.floor(v)) {
          throw new Error(`${name}.${fieldNames[i]} = ${raw} does not fit ${entries[i][1][1]} bits`);
        }
        w += v * fieldScale[i]; // arithmetic, not <<: a field reaching bit 31 must stay positive
      }
      return w;
    },
    unpack(word) {
      const out = {} as Record<K, number>;
      for (const [f, [at, bits]] of entries) out[f] = extract(word, at, bits);
      return out;
    },
    get(word, field) {
      const [at, bits] = fields[field];
      return extract(word, at, bits);
    },
  };
}

/** WGSL for bits [at, at + bits) of the u32 `w`. */
function wgslField(w: string, at: number, bits: number): string {
  if (bits === 32) return w;
  const shifted = at ? `(${w} >> ${at}u)` : w;
  return at + bits === 32 ? shifted : `${shifted} & ${hex(2 ** bits - 1)}`;
}

function hex(x: number): string {
  return `0x${x.toString(16)}u`;
}

function maskOf(at: number, bits: number): number {
  return bits === 32 ? -1 : ((2 ** bits - 1) * 2 ** at) | 0;
}

function extract(word: number, at: number, bits: number): number {
  return Math.floor((word >>> 0) / 2 ** at) % 2 ** bits;
}

/**
 * The pattern frame of a triangle (src/pattern/clamped.ts chooseFrame; packed per triangle by
 * prepare.ts packPatternFrame and read by wgsl/tess/pattern.wgsl): the corners playing A, B, C, the
 * edges playing bottom, left, right, whether each of those runs against its edge's line, and
 * whether the frame is mirrored.
 */
export const PATTERN_FRAME_WORD = defineBits('PatternFrameWord', {
  a: [0, 2],
  b: [2, 2],
  c: [4, 2],
  bottomEdge: [6, 2],
  leftEdge: [8, 2],
  rightEdge: [10, 2],
  flipBottom: [12, 1],
  flipLeft: [13, 1],
  flipRight: [14, 1],
  mirrored: [15, 1],
});

/**
 * An output vertex's barycentric weights on its source triangle (TessellatedMesh.bary, types.ts):
 * w1 and w2 in units of 2^-16. A vertex at corner 1 or 2 is stored as a sentinel instead
 * (BARY_CORNER1, BARY_CORNER2): their fields would sum past 2^16, which no real point does
 * (w1 + w2 ≤ 2^16, and a weight of exactly 2^16 is a corner).
 */
export const BARY_WORD = defineBits('BaryWord', { w1: [0, 16], w2: [16, 16] });
export const BARY_CORNER1 = 0xffffffff;
export const BARY_CORNER2 = 0xfffffffe;

/** The three weights (w0, w1, w2) of a bary word, in units of 2^-16 (they sum to 2^16). */
export function decodeBary(word: number): [number, number, number] {
  if (word === BARY_CORNER1) return [0, 65536, 0];
  if (word === BARY_CORNER2) return [0, 0, 65536];
  const { w1, w2 } = BARY_WORD.unpack(word);
  return [65536 - w1 - w2, w1, w2];
}

// ---------------------------------------------------------------------------------------------
// Storage arrays: bindings, and arrays carved out of one buffer

/** One binding of a bind group: how the WGSL declares it. */
export interface BindingSpec {
  binding: number;
  /** 'uniform', or a storage buffer's access mode. */
  space: 'uniform' | 'read' | 'read_write';
  /** The WGSL type: a struct name for a uniform, `array<u32>` and the like for storage. */
  type: string;
  doc?: string;
}

export interface BindGroupSpec<K extends string> {
  readonly group: number;
  readonly binding: Readonly<Record<K, number>>;
  /** The WGSL declarations of `names` (all when omitted), in binding order. */
  wgsl(names?: readonly K[]): string;
  /** The layout entries of `names` (all when omitted), in binding order. */
  layoutEntries(names?: readonly K[]): GPUBindGroupLayoutEntry[];
}

/**
 * A bind group whose bindings each have one WGSL name, e.g. the tessellator's
 * `{ params: { binding: 0, space: 'uniform', type: 'Params' }, work: { binding: 3, space:
 * 'read_write', type: 'array<u32>' }, … }`: the declarations are generated (never typed in a
 * .wgsl file), and a pass's explicit layout is `layoutEntries(usedBindings(code, entry, names))`,
 * so a shared helper that starts reading one more buffer changes the layout with it.
 */
export function defineBindGroup<K extends string>(
  group: number,
  entries: Readonly<Record<K, BindingSpec>>,
  visibility: number = STAGE.COMPUTE,
): BindGroupSpec<K> {
  const all = (Object.entries(entries) as [K, BindingSpec][]).sort((a, b) => a[1].binding - b[1].binding);
  for (let i = 1; i < all.length; i++) {
    if (all[i][1].binding === all[i - 1][1].binding)
      throw new Error(`${all[i - 1][0]} and ${all[i][0]} share binding ${all[i][1].binding}`);
  }
  const pick = (names?: readonly K[]) => (names ? all.filter(([k]) => names.includes(k)) : all);
  const binding = Object.fromEntries(all.map(([k, e]) => [k, e.binding])) as Record<K, number>;
  return {
    group,
    binding,
    wgsl: (names) =>
      pick(names)
        .map(([k, e]) => {
          const space = e.space === 'uniform' ? 'uniform' : `storage, ${e.space}`;
          return `${e.doc ? `// ${e.doc}\n` : ''}@group(${group}) @binding(${e.binding}) var<${space}> ${k}: ${e.type};`;
        })
        .join('\n')
        .concat('\n'),
    layoutEntries: (names) =>
      pick(names).map(([, e]) => ({
        binding: e.binding,
        visibility,
        buffer: { type: e.space === 'uniform' ? 'uniform' : e.space === 'read' ? 'read-only-storage' : 'storage' },
      })),
  };
}

/**
 * The subset of `names` (module-scope variables) that entry point `entry` of `code` reads or
 * writes, directly or through the functions it calls: what its pipeline layout must bind.
 * A lexical walk of WGSL's `fn name(…) … { … }` bodies (comments stripped), enough for code
 * that does not shadow a binding's name with a local.
 */
export function usedBindings<K extends string>(code: string, entry: string, names: readonly K[]): K[] {
  const src = code.replace(/\/\/[^\n]*/g, '').replace(/\/\*[\s\S]*?\*\//g, '');
  const bodies = new Map<string, string>();
  for (const m of src.matchAll(/\bfn\s+(\w+)\s*\(/g)) {
    const open = src.indexOf('{', m.index);
    let depth = 0;
    let end = open;
    for (; end < src.length; end++) {
      if (src[end] === '{') depth++;
      else if (src[end] === '}' && --depth === 0) break;
    }
    // The signature too: a parameter's type may name a struct, never a binding; the body is what counts.
    bodies.set(m[1], src.slice(open, end + 1));
  }
  if (!bodies.has(entry)) throw new Error(`no fn ${entry} in the code`);
  const seen = new Set<string>();
  const used = new Set<K>();
  const walk = (fn: string) => {
    if (seen.has(fn)) return;
    seen.add(fn);
    const body = bodies.get(fn)!;
    for (const m of body.matchAll(/\b(\w+)\b/g)) {
      const id = m[1];
      if ((names as readonly string[]).includes(id)) used.add(id as K);
      if (bodies.has(id)) walk(id);
    }
  };
  walk(entry);
  return names.filter((n) => used.has(n));
}

/** Where each array of an arena lies, in words, for one set of sizes. */
export interface ArenaLayout<K extends string> {
  offset: Record<K, number>;
  length: Record<K, number>;
  /** Words in all: the buffer's size / 4. */
  words: number;
}

export type OffsetField<K extends string> = `off${Capitalize<K>}`;

export interface Arena<K extends string, S> {
  readonly names: readonly K[];
  /** The uniform fields that carry the offsets (`offEdgeF: u32` for `edgeF`): spread them into the
   * Params struct's defineStruct. */
  readonly offsetFields: readonly (readonly [OffsetField<K>, 'u32'])[];
  layout(sizes: S): ArenaLayout<K>;
  /** The offset fields' values for PARAMS.write. */
  offsets(layout: ArenaLayout<K>): Record<OffsetField<K>, number>;
  /** WGSL `fn name_at(i: u32) -> u32 { return buffer[params.offName + i]; }` for each array. */
  wgslAccessors(buffer: string, params: string): string;
}

/**
 * Several u32 arrays carved one after another out of one storage buffer (the tessellator's
 * scratch `work`), each sized from `S` (e.g. the edge and triangle counts). Adding an array is one
 * entry here; its offset reaches the shaders through `offsetFields` in the uniform struct.
 */
export function defineArena<K extends string, S>(arrays: readonly (readonly [K, (sizes: S) => number])[]): Arena<K, S> {
  const names = arrays.map(([k]) => k);
  if (new Set(names).size !== names.length) throw new Error('an arena array is named twice');
  const field = (k: K) => `off${k[0].toUpperCase()}${k.slice(1)}` as OffsetField<K>;
  return {
    names,
    offsetFields: names.map((k) => [field(k), 'u32'] as const),
    layout(sizes) {
      const offset = {} as Record<K, number>;
      const length = {} as Record<K, number>;
      let at = 0;
      for (const [k, size] of arrays) {
        const n = size(sizes);
        if (!Number.isInteger(n) || n < 0) throw new Error(`arena array ${k}: ${n} words`);
        offset[k] = at;
        length[k] = n;
        at += n;
      }
      return { offset, length, words: at };
    },
    offsets(layout) {
      return Object.fromEntries(names.map((k) => [field(k), layout.offset[k]])) as Record<OffsetField<K>, number>;
    },
    wgslAccessors(buffer, params) {
      return names
        .map((k) => `fn ${k}_at(i: u32) -> u32 { return ${buffer}[${params}.${field(k)} + i]; }`)
        .join('\n')
        .concat('\n');
    },
  };
}

// ---------------------------------------------------------------------------------------------
// The compute tessellator (tessellator.ts, wgsl/tess/*.wgsl)

/** Budget attempts per rebuild: scale 1, a scale that fits, then factor 1 everywhere. */
export const ATTEMPTS = 3;
export const SCAN_BLOCK = SCAN_WORKGROUP_SIZE * SCAN_ITEMS;
/** Prefix sums per budget attempt: edge interior points, triangle interior vertices, triangles, rows. */
export const SCANS = 4;
/** 1.0 in the 16.16 fixed point of factors and barycentric weights (src/pattern/fixed.ts). */
export { ONE };
/** A cage vertex that no triangle uses (its OwnerWord). */
export const NO_OWNER = 0xffffffff;
/** The budget state words (work's `budget` array), by index. */
export const BUDGET = { ACCEPTED: 0, ATTEMPT: 1, SCALE: 2, FITS: 3 } as const;

/** The tessellator shaders' numbers beyond the shared ones (all u32), by their WGSL names. */
export const TESS_CONSTANTS = {
  ATTEMPTS,
  ONE,
  NO_OWNER,
  BARY_CORNER1,
  BARY_CORNER2,
  STRIP_DP_VERTICES,
  ...Object.fromEntries(Object.entries(BUDGET).map(([k, v]) => [`BUDGET_${k}`, v])),
  BUDGET_WORDS: Object.keys(BUDGET).length,
} as Readonly<Record<string, number>>;

/**
 * Which triangle of the mesh owns a welded vertex (prepare.ts vertexOwner, edgeOwner; read by
 * wgsl/tess/weld.wgsl): the triangle, and its corner (a vertex) or its local edge i, which runs
 * from corner i to corner i + 1 (an edge). NO_OWNER marks a vertex no triangle uses.
 */
export const OWNER_WORD = defineBits('OwnerWord', { corner: [0, 2], tri: [2, 30] });

/** WGSL getters of the pattern tables' header words (src/pattern/tables.ts TABLE_HEADER_FIELDS,
 * which its writer and reader index by): `fn tableHeader_stateCount() -> u32` and so on, reading
 * `buffer[params.offTables + i]`. */
export function tableHeaderWgsl(buffer: string, params: string): string {
  return TABLE_HEADER_FIELDS.map((f, i) => `fn tableHeader_${f}() -> u32 { return ${buffer}[${params}.offTables + ${i}u]; }`)
    .join('\n')
    .concat('\n');
}

/** What the tessellator's arenas are sized from. */
export interface TessSizes {
  vertices: number;
  /** Output vertices past the vertices: the extra sectors of crease and corner vertices
   * (prepare.ts slotOwner) where the surface splits normals at creases, else 0. */
  extraSlots: number;
  edges: number;
  triangles: number;
  /** The pattern tables' largest factor (a triangle has at most maxFactor + 1 rows). */
  maxFactor: number;
  /** Words of the pattern tables. */
  tableWords: number;
  /** Words of the Catmull-Clark tables (src/gpu/cc/build.ts), 0 without them. */
  ccWords: number;
  /** Refined Catmull-Clark points (3 floats each), 0 without them. */
  ccPoints: number;
  /** Cage vertices whose limit position and normal the patch build writes: all of them with the
   * Catmull-Clark surface, else 0. */
  limitVertices: number;
  /** Triangles with an ACC patch word (ACC_TRI_WORD): all of them with an ACC surface, else 0. */
  accTriangles: number;
  /** Words of the ACC patch table (2 per patch) and ACC control points, 0 without an ACC surface. */
  accPatchWords: number;
  accPoints: number;
  /** Displacement (src/gpu/tess/displacement-map.ts), all 0 without it: words of the packed height map,
   * triangles with three DISP_TRI words (all of them), edges with three factor words (all of
   * them), and face corners with a uv (2 floats each). */
  heightWords: number;
  dispTriangles: number;
  dispEdges: number;
  cornerUvs: number;
}

/**
 * staticBuf (u32, read-only, written once per mesh): the pattern tables, the mesh topology of
 * prepare.ts (named as its PreparedMesh arrays), then the Catmull-Clark tables (their own offsets
 * within, cc/build.ts, reach the shaders as the cc* fields of Params).
 */
export const TESS_STATIC = defineArena<
  | 'tables'
  | 'triVerts'
  | 'triEdges'
  | 'triPatternFrame'
  | 'edgeVerts'
  | 'edgeOwner'
  | 'edgeTwin'
  | 'vertexOwner'
  | 'cornerSlot'
  | 'slotOwner'
  | 'edgeSplit'
  | 'cc'
  | 'accTri'
  | 'accPatches'
  | 'heightTexels'
  | 'dispTri'
  | 'dispEdge',
  TessSizes
>([
  ['tables', (s) => s.tableWords],
  ['triVerts', (s) => 3 * s.triangles],
  ['triEdges', (s) => 3 * s.triangles],
  ['triPatternFrame', (s) => s.triangles],
  ['edgeVerts', (s) => 2 * s.edges],
  ['edgeOwner', (s) => s.edges],
  ['edgeTwin', (s) => s.edges],
  ['vertexOwner', (s) => s.vertices],
  // Split normals at infinitely sharp creases (prepare.ts splitCreases; the Catmull-Clark surface
  // only, elsewhere cornerSlot is triVerts and edgeSplit 0): the output vertex of each triangle
  // corner, the owner corner of each extra output vertex, and per edge 1 where its points are
  // output once per side.
  ['cornerSlot', (s) => 3 * s.triangles],
  ['slotOwner', (s) => s.extraSlots],
  ['edgeSplit', (s) => s.edges],
  ['cc', (s) => s.ccWords],
  ['accTri', (s) => s.accTriangles],
  ['accPatches', (s) => s.accPatchWords],
  // Displacement (src/gpu/tess/displacement-map.ts has the layout): the height map's texels packed 4
  // (8-bit) or 2 (16-bit) to a word, row-major from the image's top row; per triangle three
  // words (its face's first corner in cornerUvs, DISP_TRI_WORD, the face); per edge three f32 words for
  // the factor rule (the lowest and highest height SAMPLE over its faces, its length in texels).
  ['heightTexels', (s) => s.heightWords],
  ['dispTri', (s) => 3 * s.dispTriangles],
  ['dispEdge', (s) => 3 * s.dispEdges],
]);

/**
 * Word 3t + 1 of dispTri (word 3t is the first corner of the triangle's face in cornerUvs, word
 * 3t + 2 the face): the face's corner count and which triangle of it t is (prepare.ts triFan:
 * corners (0, fan, fan + 1), or (centre, fan, fan + 1 mod n) when centred), from which
 * wgsl/tess/displace.wgsl maps the triangle's weights to the face parameter that the uvs are
 * interpolated over (src/mesh/uv.ts: bilinear on quads, the kite sub-faces on other faces).
 */
export const DISP_TRI_WORD = defineBits('DispTriWord', { corners: [0, 15], centred: [15, 1], fan: [16, 16] });

/**
 * Per triangle with an ACC surface (wgsl/acc/surface-tess.wgsl): its ACC patch (= cage face) and
 * the patch parameter (u, v) of its three corners, each 0 or 1 (bit 2i: u_i, bit 2i + 1: v_i), so
 * that (u, v) = Σ w_i (u_i, v_i) for the triangle's weights w (src/gpu/acc/error.ts
 * accTriangleMap builds it: quads split on their 0–2 diagonal, triangles (u, v) = (w1, w2)).
 */
export const ACC_TRI_WORD = defineBits('AccTriWord', { corners: [0, 6], face: [6, 26] });

/**
 * cageBuf (f32, rewritten when the cage moves): positions and vertex normals, 3 floats each; the
 * Phong surface's α of each triangle's three edges (prepare.ts triPhongAlpha, which follows the
 * normals); with the Catmull-Clark surface, its refined points (point p ≥ ccCageVerts at
 * offCtrl + 3(p − ccCageVerts)) and the limit positions and normals of the cage vertices
 * (wgsl/cc/build.wgsl writes them).
 */
export const TESS_CAGE = defineArena<
  'positions' | 'normals' | 'phongAlpha' | 'ctrl' | 'limitPositions' | 'limitNormals' | 'accPoints' | 'cornerUvs',
  TessSizes
>([
  ['positions', (s) => 3 * s.vertices],
  ['normals', (s) => 3 * s.vertices],
  ['phongAlpha', (s) => 3 * s.triangles],
  ['ctrl', (s) => 3 * s.ccPoints],
  ['limitPositions', (s) => 3 * s.limitVertices],
  ['limitNormals', (s) => 3 * s.limitVertices],
  // ACC control points (4 floats each: xyz, w unused), copied from the ACC patch build's buffer
  // every frame, so the emit passes read no more storage buffers than with the other surfaces.
  ['accPoints', (s) => 4 * s.accPoints],
  // Displacement: the uv of every face corner (2 floats, at 2h for corner h = faceOffsets[f] + j:
  // src/mesh/uv.ts faceCornerUvs), so a seam is just two corners with different uvs.
  ['cornerUvs', (s) => 2 * s.cornerUvs],
]);

/**
 * work (u32 scratch, rewritten every rebuild): the factor each triangle's bulge asks for (an f32's
 * bits, wgsl/tess/factor-bulge.wgsl), per-edge and per-triangle counts and their exclusive prefix sums
 * (n + 1 words: the total at n), the planned rows (two words per row,
 * at most maxFactor + 1 rows a triangle), each triangle's gap-strip moves (gapMoveWords words a
 * triangle), the scans' block sums, the budget state (BUDGET).
 */
export const TESS_WORK = defineArena<
  | 'edgeF'
  | 'edgeState'
  | 'edgeSegs'
  | 'edgeInterior'
  | 'edgeBase'
  | 'triBulge'
  | 'triVertCount'
  | 'triVertBase'
  | 'triTriCount'
  | 'triTriBase'
  | 'triRowCount'
  | 'triRowBase'
  | 'rows'
  | 'gapMoves'
  | 'sums'
  | 'budget',
  TessSizes
>([
  ['edgeF', (s) => s.edges],
  ['edgeState', (s) => s.edges],
  ['edgeSegs', (s) => s.edges],
  ['edgeInterior', (s) => s.edges],
  ['edgeBase', (s) => s.edges + 1],
  ['triBulge', (s) => s.triangles],
  ['triVertCount', (s) => s.triangles],
  ['triVertBase', (s) => s.triangles + 1],
  ['triTriCount', (s) => s.triangles],
  ['triTriBase', (s) => s.triangles + 1],
  ['triRowCount', (s) => s.triangles],
  ['triRowBase', (s) => s.triangles + 1],
  ['rows', (s) => 2 * (s.maxFactor + 1) * s.triangles],
  ['gapMoves', (s) => gapMoveWords(s.maxFactor) * s.triangles],
  ['sums', (s) => SCANS * scanSumsWords(Math.max(s.edges, s.triangles))],
  ['budget', () => Object.keys(BUDGET).length],
]);

/**
 * Words of one triangle's gap strip (wgsl/tess/plan.wgsl writes them, the emit reads them): a
 * large strip's moves, one bit a move, as src/pattern/clamped.ts gapMergeSteps (at most
 * (nb − 1) + nl + nr − 1 moves, and a line has at most maxFactor + 1 segments, 3 on [1, 2], so
 * 3·(maxFactor + 1) bits are enough), or a small strip's triangles (clamped.ts
 * stripTriangulation, at most STRIP_DP_VERTICES − 2 of them, 16 bits each).
 * wgsl/tess/pattern.wgsl gapMoveWords computes the same.
 */
export function gapMoveWords(maxFactor: number): number {
  return Math.max(Math.ceil((3 * (maxFactor + 1)) / 32), Math.ceil((STRIP_DP_VERTICES - 2) / 2));
}

/** Block-sum words one scan of up to n values needs (its blocks, and one spare). */
export function scanSumsWords(n: number): number {
  return Math.ceil(Math.max(n, 1) / SCAN_BLOCK) + 1;
}

/** The prefix sums of each budget attempt, in order: what is summed into what (TESS_WORK arrays),
 * over edges or triangles. */
export const TESS_SCANS = [
  { from: 'edgeInterior', to: 'edgeBase', over: 'edges' },
  { from: 'triVertCount', to: 'triVertBase', over: 'triangles' },
  { from: 'triTriCount', to: 'triTriBase', over: 'triangles' },
  { from: 'triRowCount', to: 'triRowBase', over: 'triangles' },
] as const satisfies readonly { from: string; to: string; over: 'edges' | 'triangles' }[];

/**
 * The tessellator's uniforms (`params` in every tessellator shader). The arenas' offsets are
 * spread in from TESS_STATIC, TESS_CAGE and TESS_WORK; the Catmull-Clark fields are named by
 * src/gpu/cc/build.ts and read by wgsl/cc/build.wgsl and wgsl/cc/surface.wgsl.
 */
export const TESS_PARAMS = defineStruct('Params', [
  ['viewProj', 'mat4x4<f32>', 'World to clip space of the camera (frustum culling of edges).'],
  ['eye', 'vec4<f32>', "xyz: the camera's position."],
  ['nVerts', 'u32'],
  ['nSlots', 'u32', 'Output vertices of the corners: nVerts, then the extra sectors (slotOwner); the edge points follow.'],
  ['nTris', 'u32'],
  ['nEdges', 'u32'],
  ['maxFactor', 'u32'],
  ['vertexCapacity', 'u32'],
  ['triangleCapacity', 'u32'],
  ['mode', 'u32', '0: fixedFactor everywhere; 1: adaptive (screen-space error).'],
  ['fixedFactor', 'f32'],
  ['lodScale', 'f32'],
  ['pixelAngle', 'f32'],
  ...TESS_STATIC.offsetFields,
  ...TESS_CAGE.offsetFields,
  ...TESS_WORK.offsetFields,
  // What the factor rule reads (cageBuf offsets): the cage, or the limit surface at its vertices.
  ['offFactorPos', 'u32'],
  ['offFactorNormal', 'u32'],
  // Catmull-Clark (src/gpu/cc/build.ts): staticBuf word offsets of its tables and their sizes.
  ['ccCageVerts', 'u32', 'Points p below it are the cage vertices (cageBuf 3p), the rest refined points (offCtrl).'],
  ['ccTri', 'u32'],
  ['ccPoly', 'u32'],
  ['ccRegions', 'u32'],
  ['ccPatchIdx', 'u32'],
  ['ccFans', 'u32'],
  ['ccSectors', 'u32'],
  ['ccThreads', 'u32'],
  ['ccCos', 'u32'],
  ['ccRules', 'u32'],
  ['ccInputs', 'u32'],
  ['ccVertexFan', 'u32'],
  ['nFans', 'u32'],
  ['ccSliceGroups', 'u32'],
  ['ccMaxDepth', 'u32'],
  ['ccFlat', 'u32', 'Blend from the flat triangle by tess factor (TessellatorOptions.flatBaseline).'],
  // Displacement (src/gpu/tess/displacement-map.ts, wgsl/tess/displace.wgsl): h = (sample − dispMid)·dispScale
  // along the surface normal; the map is dispWidth × dispHeight texels of dispBits bits.
  ['dispOn', 'u32', '1: displace every output vertex (and count the heights in the factor rule).'],
  ['dispBits', 'u32', '8 or 16.'],
  ['dispWidth', 'u32'],
  ['dispHeight', 'u32'],
  ['dispWrap', 'u32', '0: repeat, 1: clamp to edge (src/mesh/heightmap.ts).'],
  ['dispScale', 'f32'],
  ['dispMid', 'f32'],
] as const);

/** Words of the tessellator's fixed-size outputs: drawIndexedIndirect's arguments, the counts
 * (src/gpu/contract/tessellated-mesh.ts: vertices, triangles, the accepted scale as f32 bits, the attempt), and the
 * indirect dispatches the budget pass sizes (the emit passes' vertices, then triangles, then the
 * weld's edge points: 3 words each). */
export const TESS_FIXED_WORDS = { drawArgs: 5, counts: 4, emitArgs: 9 } as const;
/** Byte offset of the triangles' dispatch in emitArgs. */
export const EMIT_TRIANGLES_ARGS_OFFSET = 4 * 3;
/** Byte offset of the weld's edge-point dispatch in emitArgs. */
export const WELD_EDGES_ARGS_OFFSET = 4 * 6;

/** One binding group for every tessellator pass; each pass's layout holds the bindings its entry
 * point uses (usedBindings), so the numbers below are the only place they are written. */
export const TESS_GROUP = defineBindGroup(0, {
  params: { binding: 0, space: 'uniform', type: 'Params' },
  staticBuf: { binding: 1, space: 'read', type: 'array<u32>', doc: 'TESS_STATIC: pattern tables, topology, Catmull-Clark tables.' },
  cageBuf: { binding: 2, space: 'read', type: 'array<f32>', doc: 'TESS_CAGE: positions, normals (Catmull-Clark: refined points, limits).' },
  work: { binding: 3, space: 'read_write', type: 'array<u32>', doc: 'TESS_WORK: counts, prefix sums, rows, budget state.' },
  outPositions: {
    binding: 4,
    space: 'read_write',
    type: 'array<f32>',
    doc: 'The output mesh (src/gpu/contract/tessellated-mesh.ts TessellatedMesh).',
  },
  outNormals: { binding: 5, space: 'read_write', type: 'array<f32>' },
  outBary: { binding: 6, space: 'read_write', type: 'array<u32>' },
  outSrcTri: { binding: 7, space: 'read_write', type: 'array<u32>' },
  outIndices: { binding: 8, space: 'read_write', type: 'array<u32>' },
  drawArgs: {
    binding: 9,
    space: 'read_write',
    type: `array<u32, ${TESS_FIXED_WORDS.drawArgs}>`,
    doc: 'Written by the budget pass, as counts and emitArgs (TESS_FIXED_WORDS).',
  },
  counts: { binding: 10, space: 'read_write', type: `array<u32, ${TESS_FIXED_WORDS.counts}>` },
  emitArgs: { binding: 11, space: 'read_write', type: `array<u32, ${TESS_FIXED_WORDS.emitArgs}>` },
});
export type TessBinding = keyof typeof TESS_GROUP.binding;
export const TESS_BINDINGS = Object.keys(TESS_GROUP.binding) as TessBinding[];
/** What any evaluation over the mesh reads (no outputs): e.g. src/gpu/cc/sample.ts. */
export const TESS_INPUTS: readonly TessBinding[] = ['params', 'staticBuf', 'cageBuf', 'work'];

/** The point range of one level dispatch of the patch build (face points, or edge and vertex points). */
export const CC_RANGE = defineStruct('Range', [
  ['first', 'u32', 'Global index of the range’s first point.'],
  ['count', 'u32'],
] as const);

/**
 * The patch build's group (wgsl/cc/build.wgsl): it reads the static words, writes cageBuf, and its
 * level dispatches take their point range in `range`.
 */
export const CC_BUILD_GROUP = defineBindGroup(0, {
  params: { binding: 0, space: 'uniform', type: 'Params' },
  staticBuf: { binding: 1, space: 'read', type: 'array<u32>' },
  cageBuf: { binding: 2, space: 'read_write', type: 'array<f32>' },
  range: { binding: 3, space: 'uniform', type: 'Range' },
});
export type CcBuildBinding = keyof typeof CC_BUILD_GROUP.binding;
export const CC_BUILD_BINDINGS = Object.keys(CC_BUILD_GROUP.binding) as CcBuildBinding[];
/** Sentinel of the Catmull-Clark words: no fan, no region, an idle slice thread. */
export const CC_NONE = 0xffffffff;

/** What wgsl/cc/build.wgsl starts with (then the packed words' getters, src/gpu/cc/shaders.ts). */
export function ccBuildPrelude(): string {
  return [TESS_PARAMS.wgsl, constantsWgsl, wgslConstants({ CC_NONE }), CC_RANGE.wgsl, CC_BUILD_GROUP.wgsl()].join('\n');
}

/** What every tessellator shader starts with: Params, the constants, the bindings `names` (all by
 * default), the packed words' getters and the table header's. */
export function tessPrelude(names: readonly TessBinding[] = TESS_BINDINGS): string {
  return [
    TESS_PARAMS.wgsl,
    constantsWgsl,
    wgslConstants(TESS_CONSTANTS),
    TESS_GROUP.wgsl(names),
    PATTERN_FRAME_WORD.wgsl,
    BARY_WORD.wgsl,
    OWNER_WORD.wgsl,
    ACC_TRI_WORD.wgsl,
    DISP_TRI_WORD.wgsl,
    tableHeaderWgsl('staticBuf', 'params'),
  ].join('\n');
}

/** The prefix sums' uniforms (wgsl/tess/scan.wgsl reads them as `scan`): word offsets in `work`. */
export const SCAN_PARAMS = defineStruct('ScanParams', [
  ['inOff', 'u32', 'The n values summed.'],
  ['outOff', 'u32', 'Their exclusive prefix sums, n + 1 words (the total last).'],
  ['n', 'u32'],
  ['sumsOff', 'u32', "This scan's block sums (scanSumsWords)."],
  ['skipOff', 'u32', 'Skip the scan when this word is non-zero (the budget has accepted).'],
] as const);

export const SCAN_GROUP = defineBindGroup(0, {
  scan: { binding: 0, space: 'uniform', type: 'ScanParams' },
  work: { binding: 1, space: 'read_write', type: 'array<u32>' },
});

/** What wgsl/tess/scan.wgsl starts with. */
export const scanPrelude = [SCAN_PARAMS.wgsl, constantsWgsl, SCAN_GROUP.wgsl()].join('\n');

// ---------------------------------------------------------------------------------------------
// The renderer's uniforms and bindings

/**
 * The renderer's per-frame uniforms (wgsl/render/common.wgsl reads them as `scene`), written by
 * Renderer every frame. The fields' comments travel into the generated WGSL.
 */
export const SCENE_UNIFORMS = defineStruct('SceneUniforms', [
  ['viewProj', 'mat4x4<f32>', 'World to clip space of the camera (WebGPU clip space, z in 0..1).'],
  ['lightViewProj', 'mat4x4<f32>', 'World to clip space of the light (the shadow map).'],
  ['model', 'mat4x4<f32>', "Model to world: a rotation only (the model's up axis to +Y), so it also turns normals."],
  ['eye', 'vec4<f32>', "xyz: the camera's position; w: the model's bounding radius."],
  ['toLight', 'vec4<f32>', 'xyz: unit vector towards the light; w: one shadow-map texel in uv units.'],
  ['center', 'vec4<f32>', "xyz: the bounding sphere's centre; w: the ground's height."],
  ['viewport', 'vec4<f32>', 'x, y: render target size in pixels; z: wireframe opacity; w: 1 for patch colours, else 0.'],
] as const);

/** The renderer's bind group layouts, entry for entry. The WGSL declares each at its group index
 * in the pipelines of RENDER_PIPELINE_GROUPS (tests/gpu/contract/contract.test.ts compares them). */
export const RENDER_BIND_GROUPS = {
  /** The per-frame uniforms (SCENE_UNIFORMS). */
  scene: [{ binding: 0, visibility: STAGE.VERTEX | STAGE.FRAGMENT, buffer: { type: 'uniform' } }],
  /** The shadow map and its comparison sampler. */
  shading: [
    { binding: 0, visibility: STAGE.FRAGMENT, texture: { sampleType: 'depth' } },
    { binding: 1, visibility: STAGE.FRAGMENT, sampler: { type: 'comparison' } },
  ],
  /** Two arrays read by vertex index: the wireframe's indices and positions, or the patch
   * colours' source triangles and kinds. */
  vertexStorage: [
    { binding: 0, visibility: STAGE.VERTEX, buffer: { type: 'read-only-storage' } },
    { binding: 1, visibility: STAGE.VERTEX, buffer: { type: 'read-only-storage' } },
  ],
  /** The mesh's drawIndexedIndirect args in, the wireframe's drawIndirect args out. */
  wireArgs: [
    { binding: 0, visibility: STAGE.COMPUTE, buffer: { type: 'read-only-storage' } },
    { binding: 1, visibility: STAGE.COMPUTE, buffer: { type: 'storage' } },
  ],
} as const satisfies Record<string, readonly GPUBindGroupLayoutEntry[]>;

export type RenderBindGroup = keyof typeof RENDER_BIND_GROUPS;

/** Which bind group layout sits at each group index of each of the renderer's pipelines. */
export const RENDER_PIPELINE_GROUPS = {
  shadow: ['scene'],
  lit: ['scene', 'shading', 'vertexStorage'],
  ground: ['scene', 'shading'],
  backdrop: ['scene'],
  wireframe: ['scene', 'vertexStorage'],
  cage: ['scene'],
  wireArgs: ['wireArgs'],
} as const satisfies Record<string, readonly RenderBindGroup[]>;

export type RenderPipelineName = keyof typeof RENDER_PIPELINE_GROUPS;

/** How far the ground plane reaches from the model's centre, in bounding radii: the ground shader
 * draws it that far, camera.ts fits the clip planes and the light's box around it. */
export const GROUND_EXTENT = 4;

/** Patch kinds (src/gpu/cc/build.ts PatchKind) in patch-colour mode, sRGB, indexed by kind: the
 * lit shader's palette (PATCH_SRGB) and the demo's legend. */
export const PATCH_COLOURS: readonly { kind: number; name: string; srgb: readonly [number, number, number] }[] = [
  { kind: 0, name: 'regular', srgb: [0.56, 0.8, 0.52] },
  // As NVIDIA's sample's "show irregular patches": irregular quads blue, triangles purple.
  { kind: 1, name: 'irregular quad', srgb: [0.36, 0.56, 0.98] },
  { kind: 2, name: 'triangle / n-gon region', srgb: [0.72, 0.46, 0.92] },
  { kind: 3, name: 'crease', srgb: [0.96, 0.82, 0.3] },
];

/** A WGSL f32 literal of `x` (an integer gets its `.0`; JavaScript's shortest round-trip digits). */
export function wgslF32(x: number): string {
  if (!Number.isFinite(x)) throw new Error(`${x} has no WGSL literal`);
  return Number.isInteger(x) ? `${x}.0` : String(x);
}

/** What every render shader starts with: the per-frame uniforms (the struct and its binding,
 * group 0 everywhere) and the constants the TypeScript shares with the render shaders. */
export const sceneWgsl = [
  SCENE_UNIFORMS.wgsl,
  '@group(0) @binding(0) var<uniform> scene: SceneUniforms;',
  `const GROUND_EXTENT: f32 = ${wgslF32(GROUND_EXTENT)};`,
  `const PATCH_SRGB = array<vec3f, ${PATCH_COLOURS.length}>(${PATCH_COLOURS.map((p) => `vec3f(${p.srgb.map(wgslF32).join(', ')})`).join(', ')});`,
  '',
].join('\n');
