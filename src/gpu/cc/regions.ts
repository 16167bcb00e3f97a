/**
 * The regions of the Catmull-Clark preparation (part 3 of the header of src/gpu/cc/build.ts): how
 * deep each cage face is split, and what each piece (region) of it reads: a regular or
 * single-crease patch's 16 points (patchIdx) or an EV sector of a fan; then which region each
 * prepared triangle starts at (the tri words) and the regular n-gons' corners (poly).
 */
import { type Cage, type Classification, type Sharpness, type Topology, FaceKind, SHARPNESS_INFINITE } from '../../mesh/index.ts';
import { fannedRoundCentre, type PreparedMesh } from '../tess/prepare.ts';
import { CC_NONE } from '../contract/cc.ts';
import { CC_REGION_WORD, CC_TRI_WORD } from './words.ts';
import { U32, f32bits } from './word-list.ts';
import { type Level, type LevelStack, isRegular } from './levels.ts';
import { TOTAL_DEPTH, type FanTable } from './fans.ts';
import { singleCrease } from './single-crease.ts';

const INF = SHARPNESS_INFINITE;

/** Patch colours for the demo ("show irregular patches"). */
export const enum PatchKind {
  Regular = 0,
  /** A patch from the refinement of a quad at an irregular vertex (extraordinary, dart, corner...). */
  IrregularQuad = 1,
  /** A patch inside a triangle or n-gon, or a quad next to one. */
  Triangle = 2,
  /** A patch whose refinement was driven by a crease (semi-sharp or a sharp feature). */
  Crease = 3,
}

export const REGION_PATCH = 1;
export const REGION_SECTOR = 2;

// Sector coordinates of corner j of a quad in its own frame: (a, b) = rot_j(x, y).
const QUAD_OF_ROT: [number, number][] = [
  [0, 0],
  [1, 0],
  [1, 1],
  [0, 1],
];
const GRID_POS: [number, number][] = [
  [1, 1],
  [2, 1],
  [2, 2],
  [1, 2],
];
const AXES: [number, number, number, number][] = [
  [1, 0, 0, 1],
  [0, 1, -1, 0],
  [-1, 0, 0, -1],
  [0, -1, 1, 0],
];

/** The 16 slots of the patch being gathered (gatherPatch; -1 empty): one array, reused. */
const grid = new Int32Array(16);

function setGrid(c: number, r: number, v: number): void {
  if (c >= 0 && c < 4 && r >= 0 && r < 4) grid[4 * r + c] = v;
}

/**
 * The 16 point indices (global) of a regular level face g and its phantom mask, in the face's own
 * frame turned to start at corner `start` (its corner `start` at grid (1,1), the edge leaving it
 * along +x); null if a slot stays empty. (Indexed reads of the corner tables, no destructuring:
 * a cage's first preparation runs this cold, once per region.)
 */
function gatherPatch(L: Level, g: number, start = 0): { idx: number[]; mask: number } | null {
  const m = L.he;
  const a0 = m.faceOffsets[g];
  grid.fill(-1);
  let mask = 0;

  for (let j = 0; j < 4; j++) {
    const h = a0 + ((j + start) & 3);
    if (L.edgeSharp[m.heEdge[h]] >= INF) mask |= 1 << j;
    const gc = GRID_POS[j][0],
      gr = GRID_POS[j][1];
    const ax = AXES[j][0],
      ay = AXES[j][1],
      bx = AXES[j][2],
      by = AXES[j][3];
    setGrid(gc, gr, m.faceIndices[h]);
    const t1 = m.heTwin[m.hePrev[h]];
    if (t1 < 0) continue;
    setGrid(gc + bx - ax, gr + by - ay, m.faceIndices[m.heNext[m.heNext[t1]]]);
    setGrid(gc - ax, gr - ay, m.faceIndices[m.hePrev[t1]]);
    const t2 = m.heTwin[m.hePrev[t1]];
    if (t2 < 0) continue;
    setGrid(gc - ax - bx, gr - ay - by, m.faceIndices[m.heNext[m.heNext[t2]]]);
    setGrid(gc - bx, gr - by, m.faceIndices[m.hePrev[t2]]);
    const t3 = m.heTwin[m.hePrev[t2]];
    if (t3 < 0) continue;
    setGrid(gc + ax - bx, gr + ay - by, m.faceIndices[m.heNext[m.heNext[t3]]]);
  }
  const idx = new Array<number>(16);
  for (let r = 0; r < 4; r++) {
    for (let c = 0; c < 4; c++) {
      let v = grid[4 * r + c];
      if (v < 0) {
        const covered = (r === 0 && mask & 1) || (c === 3 && mask & 2) || (r === 3 && mask & 4) || (c === 0 && mask & 8);
        if (!covered) return null;
        v = m.faceIndices[a0]; // discarded by the phantom reflection
      }
      idx[4 * r + c] = L.base + v;
    }
  }
  return { idx, mask };
}

/** A patch region's first word (its frame's turn, phantom mask, single crease, colour). */
function patchWord(rot: number, mask: number, crease: boolean, patchKind: number): number {
  return CC_REGION_WORD.pack({ kind: REGION_PATCH, rot, mask, offset: 0, sector: 0, crease, patchKind });
}

/** The region words and patch indices of every cage face, with its depth and first region. */
export interface Regions {
  regionWords: U32;
  /** Patches' 16 indices (and σ of single-crease ones); vertexLimits appends the crease records. */
  patchIdx: U32;
  faceRegion: Int32Array;
  faceDepth: Int8Array;
  /** Per cage face: its patch kind (the colour of its triangles). */
  faceKindOf: Uint8Array;
  patchCount: number;
  singleCreaseCount: number;
  sectorRegionCount: number;
}

/**
 * Split every face to the smallest depth at which each piece is a regular patch, a single-crease
 * patch or an EV sector (refining levels and making fans as that asks), and write its regions in
 * the evaluator's order. Faces are done in order, so the levels and fans are made in the same
 * order every time.
 */
export function buildRegions(topo: Topology, sharp: Sharpness, cls: Classification, lv: LevelStack, ft: FanTable): Regions {
  const { levels, level } = lv;
  const { fans, fanStart, getFan } = ft;
  const regionWords = new U32();
  const patchIdx = new U32();
  const faceRegion = new Int32Array(topo.nFaces).fill(-1);
  const faceDepth = new Int8Array(topo.nFaces).fill(-1);
  const faceKindOf = new Uint8Array(topo.nFaces);
  let patchCount = 0,
    singleCreaseCount = 0,
    sectorRegionCount = 0;
  type Desc = { g: number; k: number; i: number; j: number; r: number };
  for (let f = 0; f < topo.nFaces; f++) {
    if (sharp.hole[f]) continue;
    const N = topo.faceOffsets[f + 1] - topo.faceOffsets[f];
    const fk = cls.faceKind[f];
    const kind =
      fk === FaceKind.Regular
        ? PatchKind.Regular
        : fk === FaceKind.QuadIrregular
          ? (cls.faceFlags[f] & 3) !== 0
            ? PatchKind.Crease
            : PatchKind.IrregularQuad
          : PatchKind.Triangle;
    faceKindOf[f] = kind;
    // First depth worth trying: 0 for a quad (regular, or a sector of a fan eligible on the
    // cage); an n-gon's sub-faces are regions at level 1 only when its corners are smooth
    // interior valence-4 vertices (else the face point's fan is not eligible at level 1: its
    // diagonals are those corners).
    let d0 = N === 4 ? 0 : 1;
    if (N !== 4) {
      for (let h = topo.faceOffsets[f]; h < topo.faceOffsets[f + 1]; h++) {
        const v = topo.faceIndices[h];
        if (topo.valence[v] !== 4 || topo.vertBoundary[v]) d0 = 2;
      }
    }
    for (let d = d0; ; d++) {
      // Descendants at level d with their place in the root square (or sub-face k).
      let desc: Desc[] = N === 4 ? [{ g: f, k: 0, i: 0, j: 0, r: 0 }] : [];
      if (N !== 4) for (let k = 0; k < N; k++) desc.push({ g: topo.faceOffsets[f] + k, k, i: 0, j: 0, r: 0 });
      for (let l = N === 4 ? 0 : 1; l < d; l++) {
        const L = level(l);
        const next: Desc[] = [];
        for (let n = 0; n < desc.length; n++) {
          const q = desc[n];
          for (let c = 0; c < 4; c++) {
            const r = (q.r + c) & 3;
            next.push({ g: L.he.faceOffsets[q.g] + c, k: q.k, i: 2 * q.i + QUAD_OF_ROT[r][0], j: 2 * q.j + QUAD_OF_ROT[r][1], r });
          }
        }
        desc = next;
      }
      const L = level(d);
      const m = L.he;
      type Reg = { w0: number; w1: number; patch?: number[]; sigma?: number };
      const regs: Reg[] = [];
      let ok = true;
      for (let n = 0; n < desc.length; n++) {
        const q = desc[n];
        const a0 = m.faceOffsets[q.g];
        let irregular = -1,
          nIrr = 0;
        for (let c = 0; c < 4; c++)
          if (!isRegular(L, m.faceIndices[a0 + c])) {
            irregular = c;
            nIrr++;
          }
        if (nIrr === 0) {
          const p = gatherPatch(L, q.g);
          if (p) {
            regs.push({ w0: patchWord(q.r, p.mask, false, kind), w1: 0, patch: p.idx });
            continue;
          }
        } else {
          // One semi-sharp crease along a side: a single-crease patch, turned so the crease is
          // its x = 0 side.
          const sc = singleCrease(L, q.g);
          const p = sc && gatherPatch(L, q.g, sc.start);
          if (sc && p && p.mask === 0) {
            regs.push({ w0: patchWord((q.r + sc.start) & 3, 0, true, kind), w1: 0, patch: p.idx, sigma: sc.sigma });
            singleCreaseCount++;
            continue;
          }
        }
        // An EV sector: a corner that is (or descends from) an eligible fan centre. A fan's
        // eligibility covers the face's other three corners (its axis neighbours and diagonal),
        // so with one irregular corner only that one can be the centre; with several (a centre
        // whose semi-sharp axes run through its axis neighbours) any eligible one is.
        let found = false;
        for (let c = 0; c < 4 && !found; c++) {
          if (nIrr === 1 && c !== irregular) continue;
          const x = m.faceIndices[a0 + c];
          const s = fanStart(x, d);
          if (s < 0) continue;
          // Sector index: this face's ancestor at level s in x's ring. The face at level d
          // descends from the level-s face whose corner x it shares: walk up by child index.
          let g = q.g;
          for (let l = d; l > s; l--) g = levels[l - 1].he.heFace[g];
          const fan = getFan(s, x, Math.max(1, TOTAL_DEPTH - s));
          const sector = fans[fan].ringFaces.indexOf(g);
          if (sector < 0) throw new Error(`Catmull-Clark: face ${f} is not in the fan of its corner`);
          regs.push({
            w0: CC_REGION_WORD.pack({
              kind: REGION_SECTOR,
              rot: (q.r + c) & 3,
              mask: 0,
              offset: d - s,
              sector,
              crease: 0,
              patchKind: kind,
            }),
            w1: fan,
          });
          found = true;
        }
        if (!found) {
          ok = false;
          break;
        }
      }
      if (!ok) continue;
      const dd = N === 4 ? d : d - 1;
      const side = 1 << dd;
      const base = regionWords.n / 2;
      const order = new Array<Reg>(regs.length);
      for (let n = 0; n < desc.length; n++) {
        const q = desc[n];
        order[q.k * side * side + q.j * side + q.i] = regs[n];
      }
      for (let n = 0; n < order.length; n++) {
        const rg = order[n];
        if (rg.patch) {
          regionWords.push(rg.w0);
          regionWords.push(patchIdx.n);
          for (let k = 0; k < rg.patch.length; k++) patchIdx.push(rg.patch[k]);
          if (rg.sigma !== undefined) patchIdx.push(f32bits(rg.sigma));
          patchCount++;
        } else {
          regionWords.push(rg.w0);
          regionWords.push(rg.w1);
          sectorRegionCount++;
        }
      }
      faceRegion[f] = base;
      faceDepth[f] = d;
      break;
    }
  }
  return { regionWords, patchIdx, faceRegion, faceDepth, faceKindOf, patchCount, singleCreaseCount, sectorRegionCount };
}

/**
 * The tri words (each prepared triangle's face's first region, its fan place in the face, its
 * depth) and the corners of each regular n-gon used: what the evaluator starts its region lookup
 * from (wgsl/cc/surface.wgsl); with each triangle's patch kind for the colours.
 */
export interface TriangleRegions {
  triRegion: Uint32Array;
  poly: number[];
  triKind: Uint8Array;
}

export function triangleRegions(cage: Cage, prepared: PreparedMesh, nV0: number, regions: Regions): TriangleRegions {
  const { faceRegion, faceDepth, faceKindOf } = regions;
  // Triangles → regions.
  const nT = prepared.triangleCount;
  const triRegion = new Uint32Array(3 * nT);
  const polyAt = new Map<number, number>();
  const poly: number[] = [];
  const triKind = new Uint8Array(nT);
  for (let t = 0; t < nT; t++) {
    const f = prepared.triFace[t];
    const start = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - start;
    const k = prepared.triFan[t];
    const centred = fannedRoundCentre(n);
    const corner = (j: number) => cage.faceIndices[start + (j % n)];
    if ((centred ? prepared.triVerts[3 * t] < nV0 : prepared.triVerts[3 * t] !== corner(0)) || prepared.triVerts[3 * t + 1] !== corner(k))
      throw new Error(`triangle ${t} is not a fan triangle of face ${f}`);
    const dd = n === 4 ? faceDepth[f] : faceDepth[f] - 1;
    triRegion[3 * t] = faceRegion[f] >= 0 ? faceRegion[f] : CC_NONE;
    triRegion[3 * t + 1] = CC_TRI_WORD.pack({ corners: n, fan: k, centred: centred ? 1 : 0, depth: Math.max(0, dd) });
    if (n !== 4) {
      let at = polyAt.get(n);
      if (at === undefined) {
        polyAt.set(n, (at = poly.length / 2));
        for (let j = 0; j < n; j++) poly.push(Math.cos((2 * Math.PI * j) / n), Math.sin((2 * Math.PI * j) / n));
      }
      triRegion[3 * t + 2] = at;
    }
    triKind[t] = faceKindOf[f];
  }
  return { triRegion, poly, triKind };
}
