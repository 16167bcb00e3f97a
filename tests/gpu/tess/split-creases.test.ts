/**
 * Split normals at infinitely sharp creases (src/gpu/tess/prepare.ts splitCreases): which edges are
 * output once per side, and the sectors of each vertex (one output vertex per sector). On a
 * torus of quads (every vertex regular) with different tags, on the cube (every vertex
 * extraordinary) and on the project's models. The GPU side is
 * tests/gpu/cc/crease-normals.node.test.ts.
 */
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { prepareMesh, type PreparedMesh } from '../../../src/gpu/tess/prepare.ts';
import { OWNER_WORD } from '../../../src/gpu/contract/tess.ts';
import { loadCage, type Cage } from '../../../src/mesh/index.ts';
import { cube, cubeFaces, quadTorus } from '../../support/subdiv-fixtures.ts';

const INF = 10;
const NU = 8,
  NV = 6;
const at = (i: number, j: number) => (((j % NV) + NV) % NV) * NU + (((i % NU) + NU) % NU);

const torus = (tags: Parameters<typeof quadTorus>[2] = {}): Cage => quadTorus(NU, NV, tags);

/** The ring j = const (NU edges) or i = const (NV edges) as infinitely sharp crease tags. */
const ringU = (j: number): [number, number, number][] => Array.from({ length: NU }, (_, i) => [at(i, j), at(i + 1, j), INF]);
const ringV = (i: number): [number, number, number][] => Array.from({ length: NV }, (_, j) => [at(i, j), at(i, j + 1), INF]);

const splitEdges = (m: PreparedMesh) => m.edgeSplit.reduce((a, b) => a + b, 0);

/** The output vertices at cage vertex v (its own and its extra sectors'), by the corners. */
function slotsAt(m: PreparedMesh, v: number): Set<number> {
  const s = new Set<number>();
  for (let c = 0; c < 3 * m.triangleCount; c++) if (m.triVerts[c] === v) s.add(m.cornerSlot[c]);
  return s;
}

/** Every slot is at its corner's vertex: a cage vertex's own index, or an extra slot whose owner
 * corner is at that vertex. */
function slotsConsistent(m: PreparedMesh): boolean {
  for (let c = 0; c < 3 * m.triangleCount; c++) {
    const slot = m.cornerSlot[c];
    if (slot < m.vertexCount) {
      if (slot !== m.triVerts[c]) return false;
    } else {
      const o = OWNER_WORD.unpack(m.slotOwner[slot - m.vertexCount]);
      if (m.triVerts[3 * o.tri + o.corner] !== m.triVerts[c]) return false;
    }
  }
  return true;
}

describe('split normals at infinitely sharp creases', () => {
  it('no tags: nothing splits; every corner is its vertex', () => {
    const m = prepareMesh(torus());
    expect(splitEdges(m)).toBe(0);
    expect(m.slotOwner.length).toBe(0);
    expect([...m.cornerSlot]).toEqual([...m.triVerts]);
  });

  it('semi-sharp creases (sharpness below 10) do not split: the limit is smooth there', () => {
    const m = prepareMesh(torus({ creases: ringU(2).map(([a, b]) => [a, b, 3]) }));
    expect(splitEdges(m)).toBe(0);
    expect(m.slotOwner.length).toBe(0);
  });

  it('one sharp ring: its edges split, each of its vertices has 2 sectors', () => {
    const m = prepareMesh(torus({ creases: ringU(2) }));
    expect(splitEdges(m)).toBe(NU);
    expect(m.slotOwner.length).toBe(NU);
    for (let i = 0; i < NU; i++) expect(slotsAt(m, at(i, 2)).size).toBe(2);
    expect(slotsAt(m, at(0, 3)).size).toBe(1);
    expect(slotsConsistent(m)).toBe(true);
  });

  it('two crossing sharp rings: 4 sectors where they cross, 2 elsewhere on them', () => {
    const m = prepareMesh(torus({ creases: [...ringU(2), ...ringV(5)] }));
    expect(splitEdges(m)).toBe(NU + NV);
    expect(slotsAt(m, at(5, 2)).size).toBe(4);
    expect(slotsAt(m, at(1, 2)).size).toBe(2);
    expect(slotsAt(m, at(5, 4)).size).toBe(2);
    expect(m.slotOwner.length).toBe(3 + (NU - 1) + (NV - 1));
    // The two triangles of a quad meet a corner in one sector.
    for (let c = 0; c < 3 * m.triangleCount; c++)
      for (let d = c + 1; d < 3 * m.triangleCount; d++)
        if (m.triVerts[c] === m.triVerts[d] && m.triFace[Math.floor(c / 3)] === m.triFace[Math.floor(d / 3)])
          expect(m.cornerSlot[c]).toBe(m.cornerSlot[d]);
    expect(slotsConsistent(m)).toBe(true);
  });

  it('one sharp edge: it splits, its ends are darts (one sector each)', () => {
    const m = prepareMesh(torus({ creases: [[at(3, 3), at(4, 3), INF]] }));
    expect(splitEdges(m)).toBe(1);
    expect(m.slotOwner.length).toBe(0);
    expect(slotsConsistent(m)).toBe(true);
  });

  it('an infinitely sharp corner tag: one sector per face at that vertex, no edge splits', () => {
    const m = prepareMesh(torus({ corners: [[at(2, 2), INF]] }));
    expect(splitEdges(m)).toBe(0);
    expect(slotsAt(m, at(2, 2)).size).toBe(4);
    expect(m.slotOwner.length).toBe(3);
    expect(slotsConsistent(m)).toBe(true);
  });

  it('the cube (valence 3 everywhere, extraordinary vertices) with every edge sharp: one sector per face at each vertex', () => {
    // Each edge is walked low → high by one of its two faces.
    const every: [number, number, number][] = [];
    for (const f of cubeFaces) for (let k = 0; k < 4; k++) if (f[k] < f[(k + 1) % 4]) every.push([f[k], f[(k + 1) % 4], INF]);
    const m = prepareMesh(cube({ creases: every, corners: [[6, INF]] }));
    expect(splitEdges(m)).toBe(12);
    for (let v = 0; v < 8; v++) expect(slotsAt(m, v).size).toBe(3);
    expect(m.slotOwner.length).toBe(8 * 2);
    expect(slotsConsistent(m)).toBe(true);
  });

  it("the project's models: every infinitely sharp edge splits, extraordinary ends included", () => {
    const load = (f: string) => prepareMesh(loadCage(readFileSync(new URL(`../../../public/models/${f}`, import.meta.url), 'utf8')).cage);
    // The fold: 6 edges from boundary to boundary; its 5 interior vertices and 2 boundary ends
    // (2 faces each side of it) have 2 sectors each.
    const sheet = load('sheet.obj');
    expect([splitEdges(sheet), sheet.slotOwner.length]).toEqual([6, 7]);
    expect(slotsConsistent(sheet)).toBe(true);
    // Closed sharp loops (the box's bottom rim, the pawn's rims, the gear's teeth and axle hole,
    // whose vertices have valence 3 or touch n-gons): each edge splits and each vertex on a loop
    // has 2 sectors; the box's corner tag (3 faces) 2 more.
    const loops: [string, number, number][] = [
      ['creased-box.obj', 8, 8 + 2],
      ['pawn.obj', 16, 16],
      ['gear.obj', 50, 50],
    ];
    for (const [f, edges, extra] of loops) {
      const m = load(f);
      expect([splitEdges(m), m.slotOwner.length], f).toEqual([edges, extra]);
      expect(slotsConsistent(m)).toBe(true);
    }
  });
});
