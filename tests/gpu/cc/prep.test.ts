/**
 * The topology-only Catmull-Clark preparation (src/gpu/cc/build.ts), no GPU: face classes and
 * region counts of the talk's table on small cages, fans and their depths, and the region
 * lookup the checks use. (Positions play no part in it: the cages' positions are arbitrary.)
 */
import { describe, it, expect } from 'vitest';
import { buildCatmullClark, regionOf, type CatmullClarkData } from '../../../src/gpu/cc/build.ts';
import { REGION_PATCH, REGION_SECTOR } from '../../../src/gpu/cc/regions.ts';
import { TOTAL_DEPTH } from '../../../src/gpu/cc/fans.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { CC_FAN_WORD, CC_FAN_WORDS } from '../../../src/gpu/cc/words.ts';
import { type Cage, DEFAULT_OPTIONS, buildTopology, computeSharpness } from '../../../src/mesh/index.ts';
import { levelStack } from '../../../src/gpu/cc/levels.ts';
import { levelFromCage, refine } from '../../../src/subdiv/level.ts';
import { cube, tetra, triPrism, ringCrease, quadTorus } from '../../support/subdiv-fixtures.ts';

function prep(cage: Cage): CatmullClarkData {
  return buildCatmullClark(cage, prepareMesh(cage));
}

/** Region kinds of face f, in region order. */
function faceRegions(cc: CatmullClarkData, cage: Cage, f: number): number[] {
  const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
  const d = cc.faceDepth[f];
  const count = n === 4 ? 4 ** d : n * 4 ** (d - 1);
  const out: number[] = [];
  for (let r = 0; r < count; r++) out.push(cc.regions[2 * (cc.faceRegion[f] + r)] & 3);
  return out;
}

describe('Catmull-Clark preparation (topology only)', () => {
  it('regular torus: one regular patch per face, no refinement, no sliced fans', () => {
    const cage = quadTorus(8, 6);
    const cc = prep(cage);
    expect(cc.levels).toBe(0);
    expect(cc.regionCount).toBe(48);
    for (let f = 0; f < 48; f++) expect(faceRegions(cc, cage, f)).toEqual([REGION_PATCH]);
    expect(cc.sliceWorkgroups).toBe(0);
    // Every cage vertex still gets a fan for its limit (the factor rule), without slices.
    expect(cc.fanCount).toBe(48);
    expect(cc.maxDepth).toBe(0);
  });

  it('cube: every face is split once into 4 EV sectors; 8 valence-3 fans starting at level 1', () => {
    const cage = cube();
    const cc = prep(cage);
    expect(cc.levels).toBe(1);
    for (let f = 0; f < 6; f++) {
      expect(cc.faceDepth[f]).toBe(1);
      expect(faceRegions(cc, cage, f)).toEqual([REGION_SECTOR, REGION_SECTOR, REGION_SECTOR, REGION_SECTOR]);
    }
    expect(cc.fanCount).toBe(8);
    for (let F = 0; F < 8; F++) {
      const w0 = cc.fans[CC_FAN_WORDS * F];
      expect(CC_FAN_WORD.get(w0, 'sectors')).toBe(3); // threads: 3 sectors
      expect(CC_FAN_WORD.get(w0, 'depth')).toBe(TOTAL_DEPTH - 1); // start level 1
    }
  });

  it('tetrahedron (triangles only): 12 regions per face, two levels', () => {
    const cage = tetra();
    const cc = prep(cage);
    expect(cc.levels).toBe(2);
    for (let f = 0; f < 4; f++) {
      const r = faceRegions(cc, cage, f);
      expect(r.length).toBe(12);
      // In each sub-face's 2×2: the corner at the cage vertex and the one at the face centre
      // are EV sectors, the two at the edge midpoints regular patches.
      expect(r.filter((k) => k === REGION_SECTOR).length).toBe(6);
      expect(r.filter((k) => k === REGION_PATCH).length).toBe(6);
    }
    // 4 cage vertices (valence 3) + 4 face centres (valence 3), all starting at level 2.
    expect(cc.fanCount).toBe(8);
  });

  it('triangular prism: quads touching triangles go to 16 regions, triangles to 12', () => {
    const cage = triPrism();
    const cc = prep(cage);
    for (let f = 0; f < cage.faceOffsets.length - 1; f++) {
      const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
      expect(faceRegions(cc, cage, f).length).toBe(n === 4 ? 16 : 12);
    }
  });

  it("semi-sharp crease through extraordinary vertices: the fans decay it, no level past the EVs' one", () => {
    const cage = cube({ creases: ringCrease(2.5) });
    const cc = prep(cage);
    // Before the fans took semi-sharp axes: ceil σ = 3 uniform levels and depth 3 on the top face.
    expect(cc.levels).toBe(1);
    expect(cc.semiAxes).toBe(true);
    // The top face (its 4 edges creased) is 4 sectors of its corners' fans, ...
    expect(cc.faceDepth[0]).toBe(1);
    // ... each of which steps at least until its crease has decayed (ceil σ + 1: the limit's rule).
    expect(cc.maxDepth).toBeGreaterThanOrEqual(4);
  });

  it('region lookup: points within the last square of a fan are blended, others exact', () => {
    const cage = cube();
    const mesh = prepareMesh(cage);
    const cc = buildCatmullClark(cage, mesh);
    // Triangle 0 is (c0, c1, c2) of face 0: (u, v) = (w1 + w2, w2). Corner c0 is an EV.
    const eps = 2 ** -(TOTAL_DEPTH + 1);
    expect(regionOf(cc, 0, 0, eps, eps).blended).toBe(true);
    expect(regionOf(cc, 0, 0, 4 * eps, eps).blended).toBe(false);
    expect(regionOf(cc, 0, 0, 0.3, 0.2)).toEqual({ blended: false, sector: true });
  });
});

describe("the levels' sharpness under Chaikin's rule", () => {
  // Creases of four sharpnesses meeting at cube corners: each child edge's sharpness depends on
  // its neighbours at its end (src/mesh/topology.ts childEdgeSharpAtVertex), so the two halves
  // of an edge differ. The GPU build's levels must carry what the CPU reference refines (which
  // the CI's OpenSubdiv check holds to OpenSubdiv), edge for edge by its two end points.
  const tags = {
    creases: [
      [0, 1, 3],
      [1, 2, 1.5],
      [2, 3, 4.2],
      [4, 5, 2.5],
      [1, 5, 0.7],
    ] as [number, number, number][],
  };
  const byEnds = (he: { nEdges: number; edgeVerts: Int32Array }, sharp: Float64Array) => {
    const out = new Map<string, number>();
    for (let e = 0; e < he.nEdges; e++) {
      const a = he.edgeVerts[2 * e],
        b = he.edgeVerts[2 * e + 1];
      out.set(`${Math.min(a, b)} ${Math.max(a, b)}`, sharp[e]);
    }
    return out;
  };
  for (const creasing of ['chaikin', 'uniform'] as const) {
    it(`${creasing}: levels 1-3 have the CPU reference's edge and vertex sharpness`, () => {
      const cage = cube(tags);
      const options = { ...DEFAULT_OPTIONS, creasing };
      const topo = buildTopology(cage);
      const stack = levelStack(topo, computeSharpness(cage, topo, options), creasing === 'chaikin');
      let ref = levelFromCage(cage, topo, options);
      for (let l = 1; l <= 3; l++) {
        ref = refine(ref);
        const L = stack.level(l);
        expect(byEnds(L.he, L.edgeSharp), `level ${l}`).toEqual(byEnds(ref.he, ref.edgeSharp));
        expect(Array.from(L.vertSharp)).toEqual(Array.from(ref.vertSharp));
      }
    });
  }
  it('and the two rules differ on this cage (so the comparison above can fail)', () => {
    const cage = cube(tags);
    const topo = buildTopology(cage);
    const level1 = (chaikin: boolean) => {
      const sharp = computeSharpness(cage, topo, { ...DEFAULT_OPTIONS, creasing: chaikin ? 'chaikin' : 'uniform' });
      const L = levelStack(topo, sharp, chaikin).level(1);
      return byEnds(L.he, L.edgeSharp);
    };
    expect(level1(true)).not.toEqual(level1(false));
  });
});
