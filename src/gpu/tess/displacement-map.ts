/**
 * Displacement on the GPU (issue 12): what the compute tessellator needs to move every output
 * vertex along the surface normal by a height map, in the pass that evaluates the surface
 * (wgsl/tess/displace.wgsl surfaceAt, called by wgsl/tess/outputs.wgsl for every surface). The CPU
 * reference of the same surface is src/subdiv/displace.ts.
 *
 * Data layout (arenas of src/gpu/contract/tess.ts, packed here once per cage and map):
 *   TESS_STATIC heightTexels  the map's raw texels, row-major from the image's top row, 4 per
 *                             word for 8-bit maps (texel i at bits 8·(i mod 4) of word i/4), 2
 *                             per word for 16-bit ones: 1 or 2 bytes a texel, as the talk counts.
 *   TESS_STATIC dispTri       per triangle three words: its face's first corner
 *                             (faceOffsets[f]), DISP_TRI_WORD (the face's corner count, the fan
 *                             index k of its triangle (0, k, k + 1), or (centre, k, k + 1) when
 *                             centred: src/gpu/tess/prepare.ts triFan), and the
 *                             face f itself (for surfaces addressed by face, e.g. ACC patches).
 *   TESS_STATIC dispEdge      per edge, three f32 words for the factor rule: the lowest and
 *                             highest SAMPLE value (in [0, 1]) a lookup on either face of the edge
 *                             can return (src/mesh/uv.ts faceSampleRange), and the edge's length
 *                             in texels (the longest over its faces' uvs).
 *   TESS_CAGE   cornerUvs     two f32 per face corner (src/mesh/uv.ts faceCornerUvs).
 * Params: dispOn, dispBits, dispWidth, dispHeight, dispWrap, dispScale, dispMid.
 *
 * Seam rule (crack-free by construction): a vertex on a cage edge or at a cage vertex is written
 * once, by the weld, through its owner triangle (prepare.ts edgeOwner, vertexOwner: the first
 * triangle that has it, in face order), so its uv, height and normal come from ONE face however
 * many faces (with however many different uvs) meet there; every triangle then refers to that one
 * vertex by index. src/subdiv/displace.ts names the same owners for the CPU reference.
 *
 * The factor rule (wgsl/tess/factors.wgsl, adaptive mode) counts the heights: an edge whose faces'
 * heights vary by A (world units) gets at least min(2·texels along it, max(A in pixels, its own
 * length in pixels / 2 · min(A in pixels, 1)) × lodScale) segments: once the heights span a pixel
 * the map is sampled a segment per two pixels, up to two segments a texel (a mortar line is
 * narrower than it is deep), and the frustum test grows the edge's sphere by the largest |h|. The budget pass still scales
 * every factor down when the output would not fit.
 */
import type { Cage } from '../../mesh/types.ts';
import type { HeightMap, HeightWrap } from '../../mesh/heightmap.ts';
import { faceCornerUvs, faceSampleRange } from '../../mesh/uv.ts';
import { DISP_TRI_WORD } from '../contract/tess.ts';
import { fannedRoundCentre, type PreparedMesh } from './prepare.ts';

/** What may change without re-uploading the map: the uniforms. */
export interface DisplacementSettings {
  /** World units per unit of (sample − midLevel). */
  scale: number;
  /** Sample value in [0, 1] that means no displacement. */
  midLevel: number;
  /** Off: the surface as it is (the data stay on the GPU). */
  enabled: boolean;
}

export interface DisplacementData {
  map: HeightMap;
  wrap: HeightWrap;
  heightTexels: Uint32Array;
  dispTri: Uint32Array;
  dispEdge: Uint32Array;
  cornerUvs: Float32Array;
  /** Bytes these take on the GPU (the height map's share: heightTexels). */
  bytes: number;
}

/** Pack a height map's texels: 4 (8-bit) or 2 (16-bit) to a little-endian word. */
export function packHeightTexels(map: HeightMap): Uint32Array {
  const per = map.bits === 8 ? 4 : 2;
  const shift = map.bits;
  const out = new Uint32Array(Math.ceil(map.data.length / per));
  for (let i = 0; i < map.data.length; i++) out[(i / per) | 0] |= map.data[i] << (shift * (i % per));
  return out;
}

/**
 * The GPU data of a height map over a cage with uvs, for the tessellator's mesh (setMesh).
 * Throws, naming what is wrong, when the cage has no uvs on some face (src/mesh/uv.ts
 * requireUvs) or a face has more corners than DISP_TRI_WORD holds.
 */
export function prepareDisplacement(cage: Cage, mesh: PreparedMesh, map: HeightMap, wrap: HeightWrap = 'repeat'): DisplacementData {
  const cornerUvs = faceCornerUvs(cage);
  const range = faceSampleRange(cage, map, wrap);
  const nt = mesh.triangleCount;
  const dispTri = new Uint32Array(3 * nt);
  const edgeLo = new Float32Array(mesh.edgeCount).fill(1);
  const edgeHi = new Float32Array(mesh.edgeCount).fill(0);
  const edgeTexels = new Float32Array(mesh.edgeCount);
  // A centre-fanned face's centre uv (the mean of its corners'), once per face: its n triangles share it.
  const centreUvs = new Map<number, [number, number]>();
  const centreUv = (f: number): [number, number] => {
    let c = centreUvs.get(f);
    if (!c) {
      const h0 = cage.faceOffsets[f],
        n = cage.faceOffsets[f + 1] - h0;
      c = [0, 0];
      for (let j = 0; j < n; j++) {
        c[0] += cornerUvs[2 * (h0 + j)] / n;
        c[1] += cornerUvs[2 * (h0 + j) + 1] / n;
      }
      centreUvs.set(f, c);
    }
    return c;
  };
  for (let t = 0; t < nt; t++) {
    const f = mesh.triFace[t];
    const fan = mesh.triFan[t];
    const h0 = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - h0;
    if (n > 0x7fff) throw new RangeError(`face ${f} has ${n} corners; displacement handles up to 32767`);
    const centred = fannedRoundCentre(n);
    dispTri[3 * t] = h0;
    dispTri[3 * t + 1] = DISP_TRI_WORD.pack({ corners: n, centred: centred ? 1 : 0, fan });
    dispTri[3 * t + 2] = f;
    // The triangle's corners' uvs: the face's corners 0 (or its centre: their mean), fan, fan + 1.
    const uvOf = (j: number): [number, number] => [cornerUvs[2 * (h0 + (j % n))], cornerUvs[2 * (h0 + (j % n)) + 1]];
    const corner = [centred ? centreUv(f) : uvOf(0), uvOf(fan), uvOf(fan + 1)];
    for (let i = 0; i < 3; i++) {
      const e = mesh.triEdges[3 * t + i];
      edgeLo[e] = Math.min(edgeLo[e], range[2 * f]);
      edgeHi[e] = Math.max(edgeHi[e], range[2 * f + 1]);
      const a = corner[i],
        b = corner[(i + 1) % 3];
      const texels = Math.hypot((b[0] - a[0]) * map.width, (b[1] - a[1]) * map.height);
      edgeTexels[e] = Math.max(edgeTexels[e], texels);
    }
  }
  const edgeWords = new Float32Array(3 * mesh.edgeCount);
  for (let e = 0; e < mesh.edgeCount; e++) {
    edgeWords[3 * e] = Math.min(edgeLo[e], edgeHi[e]);
    edgeWords[3 * e + 1] = edgeHi[e];
    edgeWords[3 * e + 2] = edgeTexels[e];
  }
  const heightTexels = packHeightTexels(map);
  const dispEdge = new Uint32Array(edgeWords.buffer);
  return {
    map,
    wrap,
    heightTexels,
    dispTri,
    dispEdge,
    cornerUvs,
    bytes: 4 * (heightTexels.length + dispTri.length + dispEdge.length + cornerUvs.length),
  };
}
