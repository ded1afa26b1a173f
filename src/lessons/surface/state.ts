import { choice, stepField, linkKey, number, pointGrid } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

/** What the scene teaches; each has its own steps (`s=rows` in the link). */
export type SurfaceMode = 'patch' | 'rows' | 'casteljau' | 'matrix' | 'weights' | 'normal' | 'join';

/** The patch shaded, or drawn as iso-parameter lines. */
export type SurfaceLook = 'shaded' | 'lines';

/** The coordinate the matrix form is written for. */
export type Coordinate = 'x' | 'y' | 'z';

/** Everything the surface lesson shows, and all of it goes in the link. */
export interface SurfaceState {
  /** The control net Pₘ,ₙ, `net[m][n]`: m runs along u, n along v (`x=` in the link). */
  net: Point[][];
  /** The second patch's net Qₘ,ₙ of the joined pair: its row m = 0 meets the first patch's row m = 3 (`y=`). */
  secondNet: Point[][];
  u: number;
  v: number;
  /** The step of the scene's construction (`k=`). */
  step: number;
  /** What the scene teaches (`s=`). */
  mode: SurfaceMode;
  look: SurfaceLook;
  /** The coordinate of the matrix form (`c=`). */
  coordinate: Coordinate;
}

export const MODES: readonly SurfaceMode[] = [
  'patch',
  'rows',
  'casteljau',
  'matrix',
  'weights',
  'normal',
  'join',
];

/** A net over the square [0, 3]² (x = m, y = n) with the heights `z[m][n]`. */
export const heights = (z: readonly (readonly number[])[]): Point[][] =>
  z.map((row, m) => row.map((height, n) => [m, n, height]));

/**
 * A hill that leans towards one corner, so no two rows are alike: the net the
 * construction scenes start from (the notes draw a patch but give no numbers).
 */
export const LEANING_HILL_NET = heights([
  [0, 0.5, 0.5, 0],
  [0.5, 2, 1.5, 0.5],
  [0.5, 1.5, 1, 0],
  [0, 0.5, 0, -0.5],
]);

/** The first patch of the joined pair: a ridge along x that ends at x = 3, where the second patch goes on. */
export const JOIN_NET = heights([
  [0, 0, 0, 0],
  [0, 1, 1, 0],
  [0, 1.5, 1.5, 0],
  [0, 1, 1, 0],
]);

/**
 * `JOIN_NET`'s neighbour over [3, 6] × [0, 3]: its row 0 is `JOIN_NET`'s row 3,
 * its row 1 that row's mirror of `JOIN_NET`'s row 2 (z = 2·1 − 1.5 = 0.5), so
 * the two patches join C¹.
 */
export const JOIN_NEXT_C1: Point[][] = [
  [
    [3, 0, 0],
    [3, 1, 1],
    [3, 2, 1],
    [3, 3, 0],
  ],
  [
    [4, 0, 0],
    [4, 1, 0.5],
    [4, 2, 0.5],
    [4, 3, 0],
  ],
  [
    [5, 0, 0],
    [5, 1, -0.25],
    [5, 2, -0.25],
    [5, 3, 0],
  ],
  [
    [6, 0, 0],
    [6, 1, 0],
    [6, 2, 0],
    [6, 3, 0],
  ],
];

/** Whole words in code, short keys in the link (in this order). */
export const schema: Schema<SurfaceState> = {
  net: linkKey(pointGrid({ default: LEANING_HILL_NET, rows: 4, columns: 4, dimension: 3 }), 'x'),
  secondNet: linkKey(pointGrid({ default: JOIN_NEXT_C1, rows: 4, columns: 4, dimension: 3 }), 'y'),
  u: number({ default: 0.3, min: 0, max: 1 }),
  v: number({ default: 0.6, min: 0, max: 1 }),
  step: linkKey(stepField(), 'k'),
  mode: linkKey(choice<SurfaceMode>({ default: 'patch', values: MODES }), 's'),
  look: choice<SurfaceLook>({ default: 'shaded', values: ['shaded', 'lines'] }),
  coordinate: linkKey(choice<Coordinate>({ default: 'z', values: ['x', 'y', 'z'] }), 'c'),
};

/** Index of a coordinate in a point. */
export const coordinateIndex = (c: Coordinate) => (c === 'x' ? 0 : c === 'y' ? 1 : 2);
