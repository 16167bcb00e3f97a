// One level of a Catmull-Clark hierarchy (or a local neighbourhood of one) and the
// refinement step, with OpenSubdiv's semantics for creases, corners, boundaries
// and semi-sharp transitions. f64 positions; sharpness in f32 as OpenSubdiv stores it.
import {
  type Cage,
  type HalfEdges,
  type SubdivOptions,
  type Topology,
  DEFAULT_OPTIONS,
  buildHalfEdges,
  buildTopology,
  childEdgeSharpAtVertex,
  computeSharpness,
  decSharp,
} from '../mesh/index.ts';

export interface Level {
  he: HalfEdges;
  /** xyz per vertex. */
  pos: Float64Array;
  /** Sharpness per edge (0 smooth, >= 10 infinite). */
  edgeSharp: Float64Array;
  /** Sharpness per vertex. */
  vertSharp: Float64Array;
  /** 1 for faces without limit surface. */
  hole: Uint8Array;
  options: SubdivOptions;
  /** For refined levels: the parent face of each face and its corner index in it. */
  faceParent?: Int32Array;
  faceCorner?: Int32Array;
}

/** Level 0 of a validated cage, with boundary sharpening applied. */
export function levelFromCage(cage: Cage, topo?: Topology, options: SubdivOptions = DEFAULT_OPTIONS): Level {
  const t = topo ?? buildTopology(cage);
  const s = computeSharpness(cage, t, options);
  return { he: t, pos: cage.positions, edgeSharp: s.edge, vertSharp: s.vertex, hole: s.hole, options };
}

const F = Math.fround;

const enum Rule {
  Smooth = 1,
  Dart = 2,
  Crease = 4,
  Corner = 8,
}

function ruleOf(vs: number, sharp: number[]): Rule {
  if (vs > 0) return Rule.Corner;
  let n = 0;
  for (const s of sharp) if (s > 0) n++;
  return n > 2 ? Rule.Corner : n === 2 ? Rule.Crease : n === 1 ? Rule.Dart : Rule.Smooth;
}

/** Refine a level (or a neighbourhood) once. Child of face corner h is face h. */
export function refine(L: Level): Level {
  const m = L.he;
  const nv = m.nVerts,
    ne = m.nEdges,
    nf = m.nFaces;
  const P = L.pos;
  const chaikin = L.options.creasing === 'chaikin';
  const cnv = nv + ne + nf;
  const cpos = new Float64Array(3 * cnv);
  // Face points.
  for (let f = 0; f < nf; f++) {
    const a = m.faceOffsets[f],
      b = m.faceOffsets[f + 1],
      n = b - a;
    let x = 0,
      y = 0,
      z = 0;
    for (let h = a; h < b; h++) {
      const v = 3 * m.faceIndices[h];
      x += P[v];
      y += P[v + 1];
      z += P[v + 2];
    }
    const o = 3 * (nv + ne + f);
    cpos[o] = x / n;
    cpos[o + 1] = y / n;
    cpos[o + 2] = z / n;
  }
  // Edge points.
  for (let e = 0; e < ne; e++) {
    const va = 3 * m.edgeVerts[2 * e],
      vb = 3 * m.edgeVerts[2 * e + 1];
    const s = L.edgeSharp[e];
    const o = 3 * (nv + e);
    const mx = 0.5 * (P[va] + P[vb]),
      my = 0.5 * (P[va + 1] + P[vb + 1]),
      mz = 0.5 * (P[va + 2] + P[vb + 2]);
    if (s >= 1) {
      cpos[o] = mx;
      cpos[o + 1] = my;
      cpos[o + 2] = mz;
      continue;
    }
    // Smooth rule: 1/4 (a+b) + (1/2k) sum of the k adjacent face points.
    const h0 = m.edgeHe[e];
    const t = m.heTwin[h0];
    const fo0 = 3 * (nv + ne + m.heFace[h0]);
    let fx = cpos[fo0],
      fy = cpos[fo0 + 1],
      fz = cpos[fo0 + 2],
      k = 1;
    if (t >= 0) {
      const fo1 = 3 * (nv + ne + m.heFace[t]);
      fx += cpos[fo1];
      fy += cpos[fo1 + 1];
      fz += cpos[fo1 + 2];
      k = 2;
    }
    const w = 0.5 / k;
    let sx = 0.5 * mx + w * fx,
      sy = 0.5 * my + w * fy,
      sz = 0.5 * mz + w * fz;
    if (s > 0) {
      // fractional: blend sharp and smooth by s
      sx = s * mx + (1 - s) * sx;
      sy = s * my + (1 - s) * sy;
      sz = s * mz + (1 - s) * sz;
    }
    cpos[o] = sx;
    cpos[o + 1] = sy;
    cpos[o + 2] = sz;
  }
  // Vertex points.
  const ps: number[] = [],
    cs: number[] = [],
    far: number[] = [];
  const cvs = new Float64Array(cnv);
  for (let v = 0; v < nv; v++) {
    const ea = m.vertEdgeOffsets[v],
      eb = m.vertEdgeOffsets[v + 1];
    const ha = m.vertHeOffsets[v],
      hb = m.vertHeOffsets[v + 1];
    const o = 3 * v;
    const vx = P[o],
      vy = P[o + 1],
      vz = P[o + 2];
    const vs = L.vertSharp[v];
    const cvsv = decSharp(vs);
    cvs[v] = cvsv;
    if (hb === ha) {
      cpos[o] = vx;
      cpos[o + 1] = vy;
      cpos[o + 2] = vz;
      continue;
    }
    ps.length = 0;
    far.length = 0;
    for (let k = ea; k < eb; k++) {
      const e = m.vertEdges[k];
      ps.push(L.edgeSharp[e]);
      far.push(m.edgeVerts[2 * e] + m.edgeVerts[2 * e + 1] - v);
    }
    childEdgeSharpAtVertex(ps, chaikin, cs);
    const pRule = ruleOf(vs, ps);
    const smooth = (out: number[]): void => {
      const n = eb - ea,
        nfv = hb - ha;
      if (n !== nfv || n < 2) {
        out[0] = vx;
        out[1] = vy;
        out[2] = vz;
        return;
      }
      let ex = 0,
        ey = 0,
        ez = 0,
        fx = 0,
        fy = 0,
        fz = 0;
      for (const w of far) {
        ex += P[3 * w];
        ey += P[3 * w + 1];
        ez += P[3 * w + 2];
      }
      for (let k = ha; k < hb; k++) {
        const fo = 3 * (nv + ne + m.heFace[m.vertHe[k]]);
        fx += cpos[fo];
        fy += cpos[fo + 1];
        fz += cpos[fo + 2];
      }
      const a = (n - 2) / n,
        b = 1 / (n * n);
      out[0] = a * vx + b * (ex + fx);
      out[1] = a * vy + b * (ey + fy);
      out[2] = a * vz + b * (ez + fz);
    };
    const crease = (sharp: number[], out: number[]): void => {
      let x = 0.75 * vx,
        y = 0.75 * vy,
        z = 0.75 * vz;
      for (let i = 0; i < sharp.length; i++)
        if (sharp[i] > 0) {
          const w = 3 * far[i];
          x += 0.125 * P[w];
          y += 0.125 * P[w + 1];
          z += 0.125 * P[w + 2];
        }
      out[0] = x;
      out[1] = y;
      out[2] = z;
    };
    const mask = (rule: Rule, sharp: number[], out: number[]): void => {
      if (rule === Rule.Corner) {
        out[0] = vx;
        out[1] = vy;
        out[2] = vz;
      } else if (rule === Rule.Crease) crease(sharp, out);
      else smooth(out);
    };
    const r0: number[] = [0, 0, 0];
    if (pRule === Rule.Smooth || pRule === Rule.Dart) {
      smooth(r0);
    } else {
      const cRule = ruleOf(cvsv, cs);
      mask(pRule, ps, r0);
      if (cRule !== pRule) {
        // OpenSubdiv's fractional weight (f32).
        let sum = 0,
          count = 0;
        if (vs > 0 && !(cvsv > 0)) {
          sum = vs;
          count = 1;
        }
        for (let i = 0; i < ps.length; i++) {
          const hit = chaikin ? ps[i] > 0 && !(cs[i] > 0) : ps[i] > 0 && ps[i] <= 1;
          if (hit) {
            sum = F(sum + ps[i]);
            count++;
          }
        }
        let w = count ? F(sum / count) : 0;
        if (w > 1) w = 1;
        const r1: number[] = [0, 0, 0];
        mask(cRule, cs, r1);
        for (let c = 0; c < 3; c++) r0[c] = w * r0[c] + (1 - w) * r1[c];
      }
    }
    cpos[o] = r0[0];
    cpos[o + 1] = r0[1];
    cpos[o + 2] = r0[2];
  }
  // Child topology: child face h = [V(v_j), E(e_j), F(f), E(e_{j-1})].
  const nHe = m.faceIndices.length;
  const cOff = new Int32Array(nHe + 1);
  const cIdx = new Int32Array(4 * nHe);
  const faceParent = new Int32Array(nHe);
  const faceCorner = new Int32Array(nHe);
  const chole = new Uint8Array(nHe);
  for (let h = 0; h < nHe; h++) {
    const f = m.heFace[h];
    cOff[h + 1] = 4 * (h + 1);
    cIdx[4 * h] = m.faceIndices[h];
    cIdx[4 * h + 1] = nv + m.heEdge[h];
    cIdx[4 * h + 2] = nv + ne + f;
    cIdx[4 * h + 3] = nv + m.heEdge[m.hePrev[h]];
    faceParent[h] = f;
    faceCorner[h] = h - m.faceOffsets[f];
    chole[h] = L.hole[f];
  }
  const { he: ch } = buildHalfEdges(cnv, cOff, cIdx);
  const cEdgeSharp = new Float64Array(ch.nEdges);
  // Child edge sharpness, computed at the parent vertex end.
  for (let v = 0; v < nv; v++) {
    const ea = m.vertEdgeOffsets[v],
      eb = m.vertEdgeOffsets[v + 1];
    if (eb === ea) continue;
    let any = false;
    ps.length = 0;
    for (let k = ea; k < eb; k++) {
      const s = L.edgeSharp[m.vertEdges[k]];
      ps.push(s);
      if (s > 0) any = true;
    }
    if (!any) continue;
    childEdgeSharpAtVertex(ps, chaikin, cs);
    for (let k = ea; k < eb; k++) {
      const s = cs[k - ea];
      if (!(s > 0)) continue;
      // child edge V(v)-E(e): find it among V(v)'s child edges
      const target = nv + m.vertEdges[k];
      for (let q = ch.vertEdgeOffsets[v]; q < ch.vertEdgeOffsets[v + 1]; q++) {
        const ce = ch.vertEdges[q];
        if (ch.edgeVerts[2 * ce] + ch.edgeVerts[2 * ce + 1] - v === target) {
          cEdgeSharp[ce] = s;
          break;
        }
      }
    }
  }
  return { he: ch, pos: cpos, edgeSharp: cEdgeSharp, vertSharp: cvs, hole: chole, options: L.options, faceParent, faceCorner };
}

/**
 * Extract the sub-level made of the given faces (first face becomes face 0), with
 * sharpness carried over (no boundary re-sharpening). Returns the map from new to
 * old vertex ids.
 */
export function extractFaces(L: Level, faces: number[]): { level: Level; vmap: Int32Array } {
  const m = L.he;
  const local = new Map<number, number>();
  const vmapA: number[] = [];
  let total = 0;
  for (const f of faces) total += m.faceOffsets[f + 1] - m.faceOffsets[f];
  const off = new Int32Array(faces.length + 1);
  const idx = new Int32Array(total);
  const srcHe = new Int32Array(total);
  const hole = new Uint8Array(faces.length);
  let k = 0;
  faces.forEach((f, i) => {
    for (let h = m.faceOffsets[f]; h < m.faceOffsets[f + 1]; h++) {
      const v = m.faceIndices[h];
      let lv = local.get(v);
      if (lv === undefined) {
        lv = vmapA.length;
        local.set(v, lv);
        vmapA.push(v);
      }
      srcHe[k] = h;
      idx[k++] = lv;
    }
    off[i + 1] = k;
    hole[i] = L.hole[f];
  });
  const nv = vmapA.length;
  const { he } = buildHalfEdges(nv, off, idx);
  const edgeSharp = new Float64Array(he.nEdges);
  for (let h = 0; h < total; h++) edgeSharp[he.heEdge[h]] = L.edgeSharp[m.heEdge[srcHe[h]]];
  const pos = new Float64Array(3 * nv);
  const vertSharp = new Float64Array(nv);
  for (let i = 0; i < nv; i++) {
    const v = vmapA[i];
    pos[3 * i] = L.pos[3 * v];
    pos[3 * i + 1] = L.pos[3 * v + 1];
    pos[3 * i + 2] = L.pos[3 * v + 2];
    vertSharp[i] = L.vertSharp[v];
  }
  return { level: { he, pos, edgeSharp, vertSharp, hole, options: L.options }, vmap: Int32Array.from(vmapA) };
}

/** Faces incident to any corner of face f, f first. */
export function faceNeighbourhood(m: HalfEdges, f: number): number[] {
  const out = [f];
  const seen = new Set<number>([f]);
  for (let h = m.faceOffsets[f]; h < m.faceOffsets[f + 1]; h++) {
    const v = m.faceIndices[h];
    for (let k = m.vertHeOffsets[v]; k < m.vertHeOffsets[v + 1]; k++) {
      const g = m.heFace[m.vertHe[k]];
      if (!seen.has(g)) {
        seen.add(g);
        out.push(g);
      }
    }
  }
  return out;
}

/** Faces incident to vertex v, `first` (if given) first. */
export function vertexFaces(m: HalfEdges, v: number, first = -1): number[] {
  const out: number[] = first >= 0 ? [first] : [];
  for (let k = m.vertHeOffsets[v]; k < m.vertHeOffsets[v + 1]; k++) {
    const g = m.heFace[m.vertHe[k]];
    if (g !== first) out.push(g);
  }
  return out;
}

/** Refine a whole level `n` times. */
export function refineUniform(L: Level, n: number): Level {
  let cur = L;
  for (let i = 0; i < n; i++) cur = refine(cur);
  return cur;
}
