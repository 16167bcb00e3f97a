/**
 * The largest tess factors, declared once. In the pattern layer, which imports nothing from
 * src/gpu: the GPU side reads them from here (src/gpu/contract/constants.ts).
 *
 * MAX_FACTOR: the talk's patterns, their baked tables and the compute tessellator (the Hable line
 * is built for any power of two up to 256, src/pattern/hable-line.ts). 128, so that the talk's
 * models reach the talk's triangle counts (suzanne's 15.9 M is 968 triangles at 128²); a line's
 * points at factors up to 64 are the same as with a top of 64 (the slots are born in the same order).
 *
 * D3D11_MAX_FACTOR: D3D11's tessellator (its partitionings, src/pattern/d3d11.ts) and the
 * instanced tessellator's top level, 64, as their hardware and sample have it.
 */
export const MAX_FACTOR = 128;
export const D3D11_MAX_FACTOR = 64;
