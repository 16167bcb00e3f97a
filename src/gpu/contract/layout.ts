/**
 * One definition of a uniform struct gives both its WGSL text and its byte layout, so no
 * offset is ever counted by hand on either side. Fields are 4-byte scalars, vec4s or mat4x4s
 * (WGSL uniform layout: scalars 4-aligned, vectors and matrices 16-aligned, size a multiple of 16).
 */
export type FieldType = 'u32' | 'f32' | 'vec4<f32>' | 'mat4x4<f32>';

export interface StructLayout<K extends string> {
  wgsl: string;
  size: number;
  offset: Record<K, number>;
  /** Write values into a buffer's worth of bytes; unnamed fields stay as they are. */
  write(view: DataView, values: Partial<Record<K, number | ArrayLike<number>>>): void;
}

const SIZE: Record<FieldType, number> = { u32: 4, f32: 4, 'vec4<f32>': 16, 'mat4x4<f32>': 64 };
const ALIGN: Record<FieldType, number> = { u32: 4, f32: 4, 'vec4<f32>': 16, 'mat4x4<f32>': 16 };

/** A field: its name, its type, and optionally a comment that the generated WGSL carries. */
export type FieldSpec<K extends string> = readonly [K, FieldType] | readonly [K, FieldType, string];

export function defineStruct<K extends string>(name: string, fields: readonly FieldSpec<K>[]): StructLayout<K> {
  let at = 0;
  const offset = {} as Record<K, number>;
  const types = {} as Record<K, FieldType>;
  for (const [field, type] of fields) {
    at = Math.ceil(at / ALIGN[type]) * ALIGN[type];
    offset[field] = at;
    types[field] = type;
    at += SIZE[type];
  }
  const size = Math.ceil(at / 16) * 16;
  const line = ([f, t, doc]: FieldSpec<K>) => `${doc ? `  // ${doc}\n` : ''}  ${f}: ${t},`;
  const wgsl = `struct ${name} {\n${fields.map(line).join('\n')}\n}\n`;
  return {
    wgsl,
    size,
    offset,
    write(view, values) {
      for (const key of Object.keys(values) as K[]) {
        const v = values[key]!;
        const o = offset[key];
        switch (types[key]) {
          case 'u32':
            view.setUint32(o, v as number, true);
            break;
          case 'f32':
            view.setFloat32(o, v as number, true);
            break;
          default: {
            const arr = v as ArrayLike<number>;
            const n = SIZE[types[key]] / 4;
            if (arr.length !== n) throw new Error(`${name}.${key}: expected ${n} floats, got ${arr.length}`);
            for (let i = 0; i < n; i++) view.setFloat32(o + 4 * i, arr[i], true);
          }
        }
      }
    },
  };
}
