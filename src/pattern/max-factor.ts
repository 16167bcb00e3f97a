/**
 * The largest tess factor the patterns, their baked tables and the tessellators use by default
 * (D3D11's, and the instanced tessellator's top level), declared once. In the pattern layer, which
 * imports nothing from src/gpu: the GPU side reads it from here (src/gpu/contract/constants.ts).
 */
export const MAX_FACTOR = 64;
