// Exact evaluation of the Catmull-Clark limit surface anywhere, by local
// feature-adaptive refinement: refine the face's 1-ring until the point lies in a
// regular, crease-free (or infinitely-sharp) bicubic B-spline patch; at irregular
// vertices use the exact limit (see limit.ts).
import { type Cage, type SubdivOptions, type Topology, DEFAULT_OPTIONS, buildTopology } from '../mesh/index.ts';
import { evalBSplinePatch, gatherPatch, isRegularFace } from './bspline.ts';
import { type Level, extractFaces, faceNeighbourhood, levelFromCage, refine } from './level.ts';
import { cross, vertexLimit } from './limit.ts';

export interface SurfacePoint {
  P: [number, number, number];
  /** Derivatives with respect to the face's (u,v) (quads) or the sub-face's (s,t). */
  dPdu: [number, number, number];
  dPdv: [number, number, number];
  /** Unit normal, normalize(dPdu x dPdv) (outward for counter-clockwise faces). */
  N: [number, number, number];
  /** The point is an irregular vertex (or within 2^-20 of one): P is the vertex's limit and dPdu/dPdv are limit tangents whose magnitudes are not parametric derivatives. */
  atVertex: boolean;
  /** false where no tangent plane exists (cone points, interior valence 2, collapsed crease spans). */
  normalDefined: boolean;
}

/** Points within this parametric distance of an irregular vertex use the vertex's limit. */
export const VERTEX_SNAP_LEVEL = 20;

interface Node {
  lvl: Level;
  regular: boolean;
  cp: Float64Array | null;
  refined: Level | null;
  children: (Node | undefined)[];
}

function makeNode(lvl: Level): Node {
  const regular = isRegularFace(lvl, 0) && !lvl.hole[0];
  const cp = regular ? gatherPatch(lvl, 0) : null;
  return { lvl, regular: regular && cp !== null, cp, refined: null, children: [] };
}

function childNode(node: Node, c: number): Node {
  let ch = node.children[c];
  if (!ch) {
    if (!node.refined) node.refined = refine(node.lvl);
    ch = makeNode(extractFaces(node.refined, faceNeighbourhood(node.refined.he, c)).level);
    node.children[c] = ch;
  }
  return ch;
}

function normalize(n: [number, number, number]): { N: [number, number, number]; ok: boolean } {
  const l = Math.hypot(n[0], n[1], n[2]);
  if (!(l > 0) || !Number.isFinite(l)) return { N: [NaN, NaN, NaN], ok: false };
  return { N: [n[0] / l, n[1] / l, n[2] / l], ok: true };
}

/** Sub-face trees an n-gon's evaluator keeps: all of them while n·kept stays under this many
 * (every n-gon of an ordinary model, so its evaluation order costs nothing), else a few: each tree
 * holds the whole fan round the centre, so keeping all n of a large n-gon's costs memory ~ n². */
const CACHED_ROOT_BUDGET = 4096;
const MIN_CACHED_ROOTS = 8;

/** Evaluation tree for one cage face (caches refined neighbourhoods). */
export class FaceEvaluator {
  readonly size: number;
  readonly hole: boolean;
  private readonly base: Level;
  private roots: (Node | undefined)[] = [];
  private cachedRoots = 0;
  private baseRefined: Level | null = null;

  constructor(L: Level, face: number) {
    this.base = extractFaces(L, faceNeighbourhood(L.he, face)).level;
    this.size = L.he.faceOffsets[face + 1] - L.he.faceOffsets[face];
    this.hole = !!L.hole[face];
  }

  /** Sub-face trees held now (an n-gon's memory stays linear in n: see CACHED_ROOT_BUDGET). */
  get cachedSubFaces(): number {
    return this.cachedRoots;
  }

  private root(k: number): Node {
    let r = this.roots[k];
    if (!r) {
      // Every sub-face's tree holds the n-gon's whole fan round its centre (valence n) at each
      // depth, so keeping all n of them costs memory ~ n² (3.7 GB for a 1,500-gon's samples).
      if (this.cachedRoots >= Math.max(MIN_CACHED_ROOTS, Math.floor(CACHED_ROOT_BUDGET / this.size))) {
        this.roots = [];
        this.cachedRoots = 0;
      }
      this.cachedRoots++;
      if (this.size === 4) r = makeNode(this.base);
      else {
        if (!this.baseRefined) this.baseRefined = refine(this.base);
        r = makeNode(extractFaces(this.baseRefined, faceNeighbourhood(this.baseRefined.he, k)).level);
      }
      this.roots[k] = r;
    }
    return r;
  }

  /** Evaluate sub-face k (k = 0 for quads) at (s,t) in [0,1]^2. */
  evaluate(k: number, s: number, t: number): SurfacePoint {
    if (!(s >= 0 && s <= 1 && t >= 0 && t <= 1)) throw new RangeError(`parameter (${s}, ${t}) outside [0,1]^2`);
    if (!(Number.isInteger(k) && k >= 0 && k < (this.size === 4 ? 1 : this.size)))
      throw new RangeError(`sub-face ${k} does not exist on a face with ${this.size} corners`);
    let node = this.root(this.size === 4 ? 0 : k);
    let x = s,
      y = t;
    // J = d(s,t)/d(x,y), row-major [ds/dx, ds/dy, dt/dx, dt/dy].
    let j00 = 1,
      j01 = 0,
      j10 = 0,
      j11 = 1;
    const out = [0, 0, 0, 0, 0, 0, 0, 0, 0];
    for (let depth = 0; ; depth++) {
      if (node.regular && node.cp) {
        evalBSplinePatch(node.cp, x, y, out);
        const det = j00 * j11 - j01 * j10;
        const Pu: [number, number, number] = [0, 0, 0],
          Pv: [number, number, number] = [0, 0, 0];
        for (let c = 0; c < 3; c++) {
          const px = out[3 + c],
            py = out[6 + c];
          Pu[c] = (px * j11 - py * j10) / det;
          Pv[c] = (py * j00 - px * j01) / det;
        }
        const n = normalize(cross(Pu, Pv));
        return { P: [out[0], out[1], out[2]], dPdu: Pu, dPdv: Pv, N: n.N, atVertex: false, normalDefined: n.ok };
      }
      const atCorner = (x === 0 || x === 1) && (y === 0 || y === 1);
      if (atCorner || depth >= VERTEX_SNAP_LEVEL + 1) {
        // Nearest corner (for the depth cap: the irregular one nearest the point).
        let corner = atCorner ? (x === 0 ? (y === 0 ? 0 : 3) : y === 0 ? 1 : 2) : -1;
        if (corner < 0) {
          const cx = [0, 1, 1, 0],
            cy = [0, 0, 1, 1];
          let best = Infinity;
          for (let c = 0; c < 4; c++) {
            const d = Math.max(Math.abs(x - cx[c]), Math.abs(y - cy[c]));
            if (d < best) {
              best = d;
              corner = c;
            }
          }
        }
        return this.cornerLimit(node.lvl, corner, j00, j01, j10, j11);
      }
      const i = x >= 0.5 ? 1 : 0,
        jj = y >= 0.5 ? 1 : 0;
      const c = i === 0 ? (jj === 0 ? 0 : 3) : jj === 0 ? 1 : 2;
      let nx: number, ny: number, d00: number, d01: number, d10: number, d11: number;
      switch (c) {
        case 0:
          nx = 2 * x;
          ny = 2 * y;
          d00 = 0.5;
          d01 = 0;
          d10 = 0;
          d11 = 0.5;
          break;
        case 1:
          nx = 2 * y;
          ny = 2 * (1 - x);
          d00 = 0;
          d01 = -0.5;
          d10 = 0.5;
          d11 = 0;
          break;
        case 2:
          nx = 2 * (1 - x);
          ny = 2 * (1 - y);
          d00 = -0.5;
          d01 = 0;
          d10 = 0;
          d11 = -0.5;
          break;
        default:
          nx = 2 * (1 - y);
          ny = 2 * x;
          d00 = 0;
          d01 = 0.5;
          d10 = -0.5;
          d11 = 0;
          break;
      }
      // (x,y) = f(nx,ny): d(x,y)/d(nx,ny) = D; J <- J D.
      const a00 = j00 * d00 + j01 * d10,
        a01 = j00 * d01 + j01 * d11;
      const a10 = j10 * d00 + j11 * d10,
        a11 = j10 * d01 + j11 * d11;
      j00 = a00;
      j01 = a01;
      j10 = a10;
      j11 = a11;
      x = nx;
      y = ny;
      node = childNode(node, c);
    }
  }

  private cornerLimit(lvl: Level, corner: number, j00: number, j01: number, j10: number, j11: number): SurfacePoint {
    const v = lvl.he.faceIndices[lvl.he.faceOffsets[0] + corner];
    const r = vertexLimit(lvl, v, 0);
    // Local (x,y) directions of the lead / trail edges at this corner.
    const ax = [
      [1, 0],
      [0, 1],
      [-1, 0],
      [0, -1],
    ][corner];
    const bx = [
      [0, 1],
      [-1, 0],
      [0, -1],
      [1, 0],
    ][corner];
    // d/dx and d/dy in local coordinates: lead = a.(Px,Py), trail = b.(Px,Py)
    // Solve [a; b] [Px; Py] = [lead; trail].
    const det = ax[0] * bx[1] - ax[1] * bx[0];
    const Px: number[] = [0, 0, 0],
      Py: number[] = [0, 0, 0];
    for (let c = 0; c < 3; c++) {
      Px[c] = (r.lead[c] * bx[1] - r.trail[c] * ax[1]) / det;
      Py[c] = (r.trail[c] * ax[0] - r.lead[c] * bx[0]) / det;
    }
    const dj = j00 * j11 - j01 * j10;
    const Pu: [number, number, number] = [0, 0, 0],
      Pv: [number, number, number] = [0, 0, 0];
    for (let c = 0; c < 3; c++) {
      Pu[c] = (Px[c] * j11 - Py[c] * j10) / dj;
      Pv[c] = (Py[c] * j00 - Px[c] * j01) / dj;
    }
    const n = normalize(cross(r.lead, r.trail));
    return { P: r.P, dPdu: Pu, dPdv: Pv, N: n.N, atVertex: true, normalDefined: n.ok && r.normalDefined };
  }
}

/** The exact limit surface of a cage. */
export class Surface {
  readonly cage: Cage;
  readonly topology: Topology;
  readonly level0: Level;
  readonly options: SubdivOptions;
  private cache = new Map<number, FaceEvaluator>();

  constructor(cage: Cage, topology?: Topology, options: SubdivOptions = DEFAULT_OPTIONS) {
    this.cage = cage;
    this.topology = topology ?? buildTopology(cage);
    this.options = options;
    this.level0 = levelFromCage(cage, this.topology, options);
  }

  get faceCount(): number {
    return this.topology.nFaces;
  }
  faceSize(f: number): number {
    return this.topology.faceOffsets[f + 1] - this.topology.faceOffsets[f];
  }
  /** false for hole faces (tagged, or made holes by boundary mode 'none'). */
  hasLimitSurface(f: number): boolean {
    return !this.level0.hole[f];
  }

  faceEvaluator(f: number): FaceEvaluator {
    if (!(Number.isInteger(f) && f >= 0 && f < this.topology.nFaces)) throw new RangeError(`face ${f} does not exist`);
    let e = this.cache.get(f);
    if (!e) {
      if (this.cache.size >= 64) this.cache.clear();
      e = new FaceEvaluator(this.level0, f);
      this.cache.set(f, e);
    }
    return e;
  }

  /** Evaluate quad `face` at (u,v): corners 0,1,2,3 at (0,0),(1,0),(1,1),(0,1). */
  evaluate(face: number, u: number, v: number): SurfacePoint {
    const n = this.faceSize(face);
    if (n !== 4) throw new RangeError(`face ${face} has ${n} corners: use evaluateSubFace(face, k, s, t)`);
    return this.faceEvaluator(face).evaluate(0, u, v);
  }

  /** Evaluate sub-face k of any face at normalised (s,t) (for quads k = 0 and (s,t) = (u,v)). */
  evaluateSubFace(face: number, k: number, s: number, t: number): SurfacePoint {
    return this.faceEvaluator(face).evaluate(k, s, t);
  }
}
