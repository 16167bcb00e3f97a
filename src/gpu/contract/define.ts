/**
 * The mechanism of the contract: how one declaration gives both the WGSL text and the TypeScript
 * that reads or writes the same bytes. Packed words (defineBits: WGSL getters `word_field(w)` and a
 * packer `word_pack(...)`, and the TypeScript pack/unpack of the same bits), bind groups
 * (defineBindGroup: declarations generated from one spec; usedBindings: what an entry point reads,
 * for its explicit layout), arenas (defineArena: arrays carved out of one storage buffer, their
 * offsets, the uniform fields that carry them, and WGSL accessors), and WGSL `const` and f32
 * literals. Uniform structs are defined in layout.ts (defineStruct); the declarations that use all
 * this are in the other files of this folder (contract.ts lists them).
 */

/** GPUShaderStage's bits (fixed by the WebGPU specification; the global is absent outside a GPU runtime). */
export const STAGE = { VERTEX: 1, FRAGMENT: 2, COMPUTE: 4 } as const;

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
    // A field is a parameter of the WGSL packer: a keyword or reserved word there fails only on a GPU.
    if (WGSL_RESERVED.has(field)) throw new Error(`${name}.${field}: a WGSL keyword or reserved word cannot name a field`);
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
  const fieldAt = entries.map(([, [at]]) => at);
  const fieldBits = entries.map(([, [, bits]]) => bits);
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
    // Indexed reads of the field tables, no destructuring: both run once per word in a cage's
    // first preparation (cold code, where each destructured pair walks an iterator).
    unpack(word) {
      const out = {} as Record<K, number>;
      for (let i = 0; i < fieldNames.length; i++) out[fieldNames[i]] = extract(word, fieldAt[i], fieldBits[i]);
      return out;
    },
    get(word, field) {
      const f = fields[field];
      return extract(word, f[0], f[1]);
    },
  };
}

/** WGSL's keywords and the reserved words a field is likely to be named (WGSL spec, "Keyword
 * summary" and "Reserved words"; the full reserved list is longer). */
const WGSL_RESERVED = new Set([
  ...['alias', 'break', 'case', 'const', 'const_assert', 'continue', 'continuing', 'default', 'diagnostic', 'discard', 'else'],
  ...['enable', 'false', 'fn', 'for', 'if', 'let', 'loop', 'override', 'requires', 'return', 'struct', 'switch', 'true', 'var', 'while'],
  ...['type', 'typedef', 'typename', 'template', 'this', 'self', 'static', 'unsigned', 'signed', 'union', 'enum', 'class', 'do', 'goto'],
  ...['new', 'null', 'nil', 'module', 'import', 'export', 'extern', 'private', 'public', 'protected', 'auto', 'mut', 'ref', 'in', 'of'],
  ...['sizeof', 'from', 'get', 'set', 'inline', 'interface', 'layout', 'match', 'mod', 'move', 'sample', 'shared', 'uniform', 'where'],
]);

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

// ---------------------------------------------------------------------------------------------
// Storage arrays: bindings, and arrays carved out of one buffer

/** One binding of a bind group: how the WGSL declares it. A buffer has a `space`; a texture or a
 * sampler has its layout entry's `texture` or `sampler` member instead (and its WGSL `type`, e.g.
 * `texture_depth_2d` or `sampler_comparison`). */
export type BindingSpec = {
  binding: number;
  /** The WGSL type: a struct name for a uniform, `array<u32>` and the like for storage, a texture
   * or sampler type. */
  type: string;
  doc?: string;
  /** The stages that see it (STAGE bits), where they differ from the group's. */
  visibility?: number;
} & (
  | {
      /** 'uniform', or a storage buffer's access mode. */
      space: 'uniform' | 'read' | 'read_write';
      /** Bound with a dynamic offset (one buffer of several records, each bind picks one). */
      hasDynamicOffset?: boolean;
      /** The bytes every bind must cover (a dynamic offset's record size). */
      minBindingSize?: number;
    }
  | { texture: GPUTextureBindingLayout }
  | { sampler: GPUSamplerBindingLayout }
);

export interface BindGroupSpec<K extends string> {
  readonly group: number;
  readonly binding: Readonly<Record<K, number>>;
  /** The WGSL declarations of `names` (all when omitted), in binding order. */
  wgsl(names?: readonly K[]): string;
  /** The layout entries of `names` (all when omitted), in binding order. */
  layoutEntries(names?: readonly K[]): GPUBindGroupLayoutEntry[];
  /** The same declarations in another group, the lowest binding at `firstBinding` and the others
   * as far from it as here: for a module that includes another's shader code beside bindings of its
   * own (the instanced tessellator draws with the renderer's lit shading in its groups 2 and 3). */
  moved(group: number, firstBinding: number): BindGroupSpec<K>;
}

/**
 * A bind group whose bindings each have one WGSL name, e.g. the tessellator's
 * `{ params: { binding: 0, space: 'uniform', type: 'Params' }, work: { binding: 3, space:
 * 'read_write', type: 'array<u32>' }, … }`: the declarations are generated (never typed in a
 * .wgsl file), and a pass's explicit layout is `layoutEntries(usedBindings(code, entry, names))`,
 * so a shared helper that starts reading one more buffer changes the layout with it. `visibility`
 * is every entry's unless the entry names its own.
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
    moved: (to, firstBinding) =>
      defineBindGroup(
        to,
        Object.fromEntries(all.map(([k, e]) => [k, { ...e, binding: firstBinding + e.binding - all[0][1].binding }])) as Record<
          K,
          BindingSpec
        >,
        visibility,
      ),
    wgsl: (names) =>
      pick(names)
        .map(([k, e]) => {
          const space = 'space' in e ? `<${e.space === 'uniform' ? 'uniform' : `storage, ${e.space}`}>` : '';
          return `${e.doc ? `// ${e.doc}\n` : ''}@group(${group}) @binding(${e.binding}) var${space} ${k}: ${e.type};`;
        })
        .join('\n')
        .concat('\n'),
    layoutEntries: (names) =>
      pick(names).map(([, e]): GPUBindGroupLayoutEntry => {
        const common = { binding: e.binding, visibility: e.visibility ?? visibility };
        if ('texture' in e) return { ...common, texture: { ...e.texture } };
        if ('sampler' in e) return { ...common, sampler: { ...e.sampler } };
        const type = e.space === 'uniform' ? 'uniform' : e.space === 'read' ? 'read-only-storage' : 'storage';
        return {
          ...common,
          buffer: {
            type,
            ...(e.hasDynamicOffset ? { hasDynamicOffset: true } : {}),
            ...(e.minBindingSize !== undefined ? { minBindingSize: e.minBindingSize } : {}),
          },
        };
      }),
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

export type OffsetField<K extends string, P extends string = 'off'> = `${P}${Capitalize<K>}`;

export interface Arena<K extends string, S, P extends string = 'off'> {
  readonly names: readonly K[];
  /** The uniform fields that carry the offsets (`offEdgeF: u32` for `edgeF`; the prefix is the
   * arena's, `off` unless named): spread them into the Params struct's defineStruct. */
  readonly offsetFields: readonly (readonly [OffsetField<K, P>, 'u32'])[];
  layout(sizes: S): ArenaLayout<K>;
  /** The offset fields' values for PARAMS.write, each plus `base` (where the arena starts in a
   * larger buffer, 0 by default). */
  offsets(layout: ArenaLayout<K>, base?: number): Record<OffsetField<K, P>, number>;
  /** WGSL `fn name_at(i: u32) -> u32 { return buffer[params.offName + i]; }` for each array. */
  wgslAccessors(buffer: string, params: string): string;
}

/**
 * Several u32 arrays carved one after another out of one storage buffer (the tessellator's
 * scratch `work`), each sized from `S` (e.g. the edge and triangle counts). Adding an array is one
 * entry here; its offset reaches the shaders through `offsetFields` in the uniform struct, whose
 * names are `prefix` and the array's name (`off` by default: `offEdgeF` for `edgeF`).
 */
export function defineArena<K extends string, S, P extends string = 'off'>(
  arrays: readonly (readonly [K, (sizes: S) => number])[],
  prefix: P = 'off' as P,
): Arena<K, S, P> {
  const names = arrays.map(([k]) => k);
  if (new Set(names).size !== names.length) throw new Error('an arena array is named twice');
  const field = (k: K) => `${prefix}${k[0].toUpperCase()}${k.slice(1)}` as OffsetField<K, P>;
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
    offsets(layout, base = 0) {
      return Object.fromEntries(names.map((k) => [field(k), base + layout.offset[k]])) as Record<OffsetField<K, P>, number>;
    },
    wgslAccessors(buffer, params) {
      return names
        .map((k) => `fn ${k}_at(i: u32) -> u32 { return ${buffer}[${params}.${field(k)} + i]; }`)
        .join('\n')
        .concat('\n');
    },
  };
}

/** A WGSL f32 literal of `x` (an integer gets its `.0`; JavaScript's shortest round-trip digits). */
export function wgslF32(x: number): string {
  if (!Number.isFinite(x)) throw new Error(`${x} has no WGSL literal`);
  return Number.isInteger(x) ? `${x}.0` : String(x);
}
