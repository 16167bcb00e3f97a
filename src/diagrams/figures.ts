/**
 * Every figure of the talk's "Part 1: The Triangle", as a preset: a page (line or triangle), a
 * query string of parameters, a title and a caption in plain words. `?fig=ID` loads a preset;
 * any other parameter in the URL overrides it.
 */

export interface Figure {
  id: string;
  kind: 'line' | 'triangle';
  title: string;
  caption: string;
  /** Parameters, as a query string (see params.ts). */
  query: string;
  /** The talk's slide this figure stands for. */
  slide: string;
}

export const FIGURES: readonly Figure[] = [
  // ---------------------------------------------------------------------------------------- line
  {
    id: 'pow2-pop',
    kind: 'line',
    slide: 'Tessellating a line: Powers of Two',
    title: 'Powers of two: the pop',
    caption:
      'The simplest answer subdivides only at powers of two: 1, 2, 4, 8, 16, 32, 64. Nothing changes in between, then half the points appear at once (red): a strong pop at every power of two.',
    query: 'mode=pow2-snap&from=1&to=64&ease=log&duration=9&start=5.2',
  },
  {
    id: 'one-at-a-time',
    kind: 'line',
    slide: 'Tessellating a line: One at a time',
    title: 'One point at a time',
    caption:
      'Going from 4 to 8, add the points 5, 6, 7 and 8 one at a time (the factor steps through whole numbers here). At 8 the pattern is exactly the uniform one again, as at every power of two.',
    query: 'mode=one-at-a-time&from=4&to=8&snap=1&duration=5&hold=1&start=2.6',
  },
  {
    id: 'sliding-pivot',
    kind: 'line',
    slide: 'Tessellating a line: Distribution (sliding pivot)',
    title: 'The sliding pivot',
    caption:
      'Each new point (red) slides in from the point before it; all the others stay locked and only the pivot moves, ending where the uniform pattern puts it. The result is lopsided: at factor 3 there are two small segments (green) and one big one (red).',
    query: 'mode=one-at-a-time&from=2&to=8&duration=6&segments=1&start=1',
  },
  {
    id: 'even-10.3',
    kind: 'line',
    slide: 'Tessellating a line: One at a time (10.3)',
    title: 'Even redistribution: factor 10.3',
    caption:
      'Spread the points by weight instead: at factor 10.3 there are 11 segments, ten of weight 1 and one sliding segment of weight 0.3 (the numbers), all divided by 10.3. Every point moves a little, but the spacing stays even, and every whole factor is exactly uniform.',
    query: 'mode=even&from=8&to=16&duration=8&labels=1&start=2.3',
  },
  {
    id: 'fractional-even',
    kind: 'line',
    slide: 'DX11 fractional even',
    title: 'D3D11 fractional even',
    caption:
      "Mirror the even pattern about the midpoint and you have D3D11's fractional_even partitioning: symmetric, the midpoint always present, so its smallest factor is 2 (1 is clamped up to 2). Each new pair (red) is born on an existing point and pushed apart while every other point glides.",
    query: 'mode=fractional_even&from=2&to=16&duration=8&start=2.5',
  },
  {
    id: 'fractional-odd',
    kind: 'line',
    slide: 'DX11 line segments',
    title: 'D3D11 fractional odd',
    caption:
      'fractional_odd keeps a middle segment instead of a middle point, so it can start from a single segment at factor 1: the first pair (red) grows out of the two corners. Like fractional_even, every point keeps gliding as the factor grows.',
    query: 'mode=fractional_odd&from=1&to=9&duration=8&start=2.2',
  },
  {
    id: 'even-vs-stable',
    kind: 'line',
    slide: 'DX11 line segments',
    title: 'Even but unstable, or stable but lopsided',
    caption:
      "Every point's track as the factor grows (upwards). D3D11's fractional_even (left) is very evenly spread, at the cost of points that never stop moving; adding one point at a time (right) is lopsided, but once a point has arrived it stays put: less swimming under displacement.",
    query: 'mode=fractional_even,one-at-a-time&from=2&to=16&ease=log&view=trace&duration=8&start=3',
  },
  {
    id: 'd3d11-does-not-converge',
    kind: 'line',
    slide: 'Why DX11 does not converge',
    title: 'Why D3D11 does not converge',
    caption:
      'Each new point pushes the points above it up and those below it down. Follow the point that sits in the middle of the half-edge at every power of two (red): born at the middle of the edge in the first octave (2 → 4), it then goes 0.5 → 2/3 → 0.5 in every octave, 4 → 8 → 16 → 32. The points never settle, however high the factor.',
    query: 'mode=fractional_even&from=2&to=32&ease=log&view=trace&half=1&track=0.5&marks=0.5,0.6667&duration=12&start=4.5',
  },
  {
    id: 'odd-first',
    kind: 'line',
    slide: 'Fixing the line first: odd before even',
    title: 'Odd points before even',
    caption:
      'Back to the stable one-at-a-time line, but insert the odd points of each octave before the even ones. Same segments, less lopsided: half-way from 4 to 8, left to right gives small, small, small, small, big, big (top); odd first gives big, small, small, big, small, small (bottom).',
    query: 'mode=one-at-a-time,odd-first&from=4&to=8&duration=6&segments=1&start=3',
  },
  {
    id: 'slow-slide',
    kind: 'line',
    slide: 'Fixing the line first: slowly slide in multiple points',
    title: 'Slowly slide in several points',
    caption:
      'One point at a time, each sliding in quickly, looks as if it pops in, although it is continuous (top). Instead, slide several points in together, each more slowly: up to four red points move at once (bottom).',
    query: 'mode=odd-first,slow-slide&from=4&to=16&ease=log&duration=8&start=2.2',
  },
  {
    id: 'clean-1-2',
    kind: 'line',
    slide: 'Fixing the line first: clean 1 → 2 transition',
    title: 'A clean 1 → 2 transition',
    caption:
      'D3D11 fractional_even cannot go below 2: a factor of 1 is clamped to 2, so its midpoint is always there (top). One point sliding in from one end is lopsided (middle). Hable brings two points in from both ends; they meet in the middle and merge at exactly 2 (bottom).',
    query: 'mode=fractional_even,slow-slide,hable&from=1&to=2&duration=4&start=2',
  },
  {
    id: 'hable',
    kind: 'line',
    slide: 'Fixing the line first (the final line)',
    title: "Hable's line",
    caption:
      'The final line pattern. Points never move once placed; within each octave the new points slide in from their left neighbours, odd ones first, up to four at once and slowly, and 1 → 2 comes in from both ends. Every power of two is exactly uniform.',
    query: 'mode=hable&from=1&to=64&ease=log&duration=12&start=4.4',
  },
  {
    id: 'hable-trace',
    kind: 'line',
    slide: 'Fixing the line first (the final line)',
    title: "Hable's line, traced",
    caption:
      "The same line as tracks: the factor grows upwards. A point slides to its place and then its track goes straight up: it never moves again. Compare with D3D11's tracks, which bend in every octave.",
    query: 'mode=hable&from=1&to=16&ease=log&view=trace&duration=8&start=3',
  },
  {
    id: 'all-lines',
    kind: 'line',
    slide: 'Tessellating a line (every step)',
    title: 'Every line pattern at one factor',
    caption:
      "All the line patterns stacked at the same factor: the talk's steps from powers of two to Hable's line, and D3D11's four partitionings. Red points are the sliding or newest ones.",
    query:
      'mode=pow2-snap,one-at-a-time,even,odd-first,slow-slide,hable,integer,pow2,fractional_odd,fractional_even&from=1&to=16&duration=10&start=3.5',
  },
  // ------------------------------------------------------------------------------------ triangle
  {
    id: 'd3d11-vs-clamped',
    kind: 'triangle',
    slide: 'How does DX11 tessellation create a triangle?',
    title: 'D3D11 next to the clamped parallelogram',
    caption:
      "D3D11's four partitionings (integer and pow2 jump; fractional odd and even slide) next to Hable's clamped parallelogram, all three edge factors and D3D11's inside factor at the same value. Red vertices are the ones moving at this moment.",
    query: 'mode=integer,pow2,fractional_odd,fractional_even,clamped&from=1&to=12&duration=10&start=3.2',
  },
  {
    id: 'd3d11-inside',
    kind: 'triangle',
    slide: 'DX11 interior: the internal tess factor',
    title: "D3D11's inside factor",
    caption:
      'D3D11 has a fourth factor for the interior. Here the three edges stay at 4 and only the inside factor grows: new rings fill in, and the outer strip (the picture frame) stitches them to the fixed edges.',
    query: 'mode=fractional_even,fractional_odd&f0=4&f1=4&f2=4&inside=2..12&duration=7&start=2.5',
  },
  {
    id: 'parallelogram',
    kind: 'triangle',
    slide: 'The clamped parallelogram (start with a parallelogram)',
    title: 'Start with a parallelogram',
    caption:
      "Put Hable's line on the bottom edge (u) and on the left edge (v) and join the points into a grid: a parallelogram, twice the triangle. The rows and columns are straight, but it is not a triangle.",
    query: 'stage=parallelogram&shape=right&f0=2..8&f1=5&f2=3..6&duration=6&start=2',
  },
  {
    id: 'clamp',
    kind: 'triangle',
    slide: 'The clamped parallelogram (clamp it into a triangle)',
    title: 'Clamp it into a triangle',
    caption:
      'Clamp every row at the diagonal, u = min(u, 1 − v). Grid points past the diagonal collapse onto it (hollow) and make zero-area triangles, a solvable problem. The real flaw: the third edge gets whatever points the other two dictate, not its own line (blue ticks), so it cannot have its own factor. This step is drawn for illustration; the pattern itself never uses it.',
    query: 'stage=clamp&shape=right&f0=3..7&f1=9&f2=4..6&duration=6&start=2',
  },
  {
    id: 'gap',
    kind: 'triangle',
    slide: 'The clamped parallelogram (mind the gap)',
    title: 'Mind the gap',
    caption:
      "Each line has a gap at its far end; take the larger of the two and clamp at u = min(u, (1 − gap) − v), the dashed line. Here a line's gap is the larger of its last two segments (the talk takes 1 minus the last interior point): the two agree at powers of two, but only this one moves continuously while points slide. An open strip (shaded) is left along the third edge.",
    query: 'stage=gap&shape=right&f0=5..7&f1=12..4&f2=6..8&duration=7&start=2.5',
  },
  {
    id: 'gap-matching',
    kind: 'triangle',
    slide: 'Matching the gap',
    title: 'Matching the gap',
    caption:
      "Fill the strip (shaded) between its two sides, the ends of the clamped rows and the third edge's points, without caps: triangles whose three points lie nearly on one line, which fold on a curved surface. A small strip gets the triangulation whose largest angle is least; a larger one is zipped from B by a greedy walk that looks one step ahead. The points move continuously; the strip's diagonals flip where two cuts tie.",
    query: 'stage=match&shape=right&f0=5..7&f1=12..4&f2=6..8&duration=7&start=2.5',
  },
  {
    id: 'low-factors',
    kind: 'triangle',
    slide: 'The full tess pattern (the centre point at low factors)',
    title: 'Low factors, without a centre point',
    caption:
      "While the left edge's factor is between 1 and 2, its two points slide in from both ends. Hable's parallelogram breaks there, so he adds a centre point. This construction does not need one: each sliding left point simply gets its own row, wherever it is. At (1, 1, 1) the pattern is a single triangle and it grows continuously from there.",
    query: 'from=1&to=2&duration=5&start=2',
  },
  {
    id: 'full-pattern',
    kind: 'triangle',
    slide: 'Full pattern',
    title: 'The full pattern: three independent edges',
    caption:
      'Three edge factors and no inside factor. The grid comes from the bottom and left edges, the strip matches the right edge, and every edge carries exactly its own line, so two triangles that share an edge always agree: no cracks.',
    query: 'f0=2..7..11&f1=3..12..5&f2=6..4..14&duration=10&start=3',
  },
  {
    id: 'edges-independent',
    kind: 'triangle',
    slide: 'Each edge moves on its own',
    title: 'Each edge moves on its own',
    caption:
      'Drop one edge at a time to 1 and bring it back. In D3D11 (left) the outer strip absorbs the change and the interior, driven by the inside factor, stays as it is. In the clamped pattern (right) each edge keeps its own line too: the grid follows the bottom and left edges, and the strip absorbs the right one.',
    query:
      'mode=fractional_even,clamped&f0=8..1..8..8..8..8..8&f1=8..8..8..1..8..8..8&f2=8..8..8..8..8..1..8&inside=8&loop=repeat&duration=12&start=1.2',
  },
  {
    id: 'inefficient-16',
    kind: 'triangle',
    slide: 'DX11 vs. clamped: inefficient patterns',
    title: 'Inefficient patterns: 384 against 256',
    caption:
      "Every factor at 16. D3D11's six regular regions need 384 triangles; the clamped parallelogram's regular grid needs 16² = 256, one third fewer for the same edges.",
    query: 'mode=fractional_even,clamped&from=16&to=16&inside=16',
  },
  {
    id: 'thin-triangle',
    kind: 'triangle',
    slide: 'DX11 vs. clamped: varied factors',
    title: 'Long, thin triangles',
    caption:
      'A long thin triangle wants few points across and many along. D3D11 has a single inside factor: low, and the interior is too coarse along the triangle; high, and it is far too fine across it (it sweeps 2 → 16 here). The clamped pattern takes its columns from the short edge and its rows from a long one.',
    query: 'mode=fractional_even,clamped&shape=thin&f0=2&f1=16&f2=16&inside=2..16&duration=7&start=3',
  },
  {
    id: 'edge-loops',
    kind: 'triangle',
    slide: 'DX11 vs. clamped: bending & edge loops',
    title: 'Edge loops',
    caption:
      "Edges coloured by direction (blue rows, orange columns, green parallel to the third edge). Deformation wants straight edge loops: D3D11's loops are rings that bend at every corner, joined by stitching; the clamped pattern's rows and columns run straight across and degrade gracefully where factors differ.",
    query: 'mode=fractional_even,clamped&loops=1&f0=4..8&f1=6..10&f2=5..9&duration=7&start=2',
  },
  {
    id: 'minimum-triangles',
    kind: 'triangle',
    slide: 'DX11 vs. clamped: minimum triangles',
    title: 'The minimum triangle count: 6 against 1',
    caption:
      'At factor 1, D3D11 fractional_even still draws 6 triangles (it clamps to 2), so merely switching tessellation on is costly. fractional_odd starts from one triangle but jumps to 13 as soon as the factors pass 1. The clamped parallelogram grows continuously from a single triangle.',
    query: 'mode=fractional_even,fractional_odd,clamped&from=1&to=2.5&duration=5',
  },
];

export function figuresOf(kind: 'line' | 'triangle'): Figure[] {
  return FIGURES.filter((f) => f.kind === kind);
}

/** The page URL (relative to the diagrams folder) of a figure, with extra parameters. */
export function figureUrl(f: Figure, extra = ''): string {
  return `${f.kind}.html?fig=${f.id}${extra ? `&${extra}` : ''}`;
}
