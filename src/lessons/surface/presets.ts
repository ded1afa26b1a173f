import type { Point } from '../../app/lesson';
import { JOIN_NEXT_C1, heights } from './state';

// The nets worth seeing (flat, saddle, bump, wave, not planar), and the second
// net of two patches joined C⁰.

export const FLAT_NET = heights([
  [0, 0, 0, 0],
  [0, 0, 0, 0],
  [0, 0, 0, 0],
  [0, 0, 0, 0],
]);

/** z = (m − 3/2)(n − 3/2)/2, so the patch is z = 9(u − ½)(v − ½)/2: a hyperbolic paraboloid. */
export const SADDLE_NET = heights(
  [0, 1, 2, 3].map((m) => [0, 1, 2, 3].map((n) => ((m - 1.5) * (n - 1.5)) / 2)),
);

/** Height 2 at the four inner points: the top, P(½, ½), is at 2·(3/4)² = 9/8. */
export const BUMP_NET = heights([
  [0, 0, 0, 0],
  [0, 2, 2, 0],
  [0, 2, 2, 0],
  [0, 0, 0, 0],
]);

/** Up, then down along u; the wave flattens towards the edges v = 0 and v = 1. */
export const WAVE_NET = heights([0, 1.5, -1.5, 0].map((z) => [0.5 * z, z, z, 0.5 * z]));

/** No plane holds the net, not even its four corners (z = 0, 1.5, 1.2, −1), and the rows are not straight. */
export const TWISTED_NET: Point[][] = [
  [
    [0, 0, 0],
    [1, -0.3, 0.4],
    [2, 0.2, 0.8],
    [3, 0, 1.5],
  ],
  [
    [-0.2, 1, 0.6],
    [1.1, 1.2, 1.8],
    [2.2, 0.9, -0.4],
    [3.3, 1.1, 0.5],
  ],
  [
    [0.1, 2, -0.5],
    [0.9, 2.1, 0.3],
    [2, 1.8, 2.2],
    [2.8, 2.2, 1],
  ],
  [
    [0, 3, 1.2],
    [1.2, 3.2, -0.8],
    [2.1, 2.9, 0.2],
    [3, 3, -1],
  ],
];

/** The C¹ neighbour with its second row lifted: the legs across the edge bend, a crease (C⁰). */
export const JOIN_NEXT_C0: Point[][] = JOIN_NEXT_C1.map((row, m) =>
  m === 1
    ? row.map(([x, y, z], n) => [x, y, n === 1 || n === 2 ? 1.6 : z])
    : row.map((p) => p.slice()),
);
