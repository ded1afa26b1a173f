import { fillBernstein } from './bernstein';
import { deCasteljau } from './bezier';
import { checkPoints } from './checkPoints';
import { checkInteger, checkParameter } from './validate';
import type { Point } from './vec';

// The construction of a tensor-product patch in the lecture notes (surfaces):
// choose v, and each row m of the net, Σn fn(v) x(m,n), is a curve in v that
// gives one point r_m(v); those points are the control points of a curve in u,
// and x(u, v) = Σm fm(u) r_m(v). Choosing u first works the same way with the
// columns: c_n(u) = Σm fm(u) x(m,n), x(u, v) = Σn fn(v) c_n(u).

/** Which direction a construction evaluates first. */
export type SurfaceOrder = 'u-then-v' | 'v-then-u';

/** Every point of the patch construction by de Casteljau in one direction, then the other. */
export interface SurfaceConstruction {
  readonly order: SurfaceOrder;
  /**
   * The first pass: one de Casteljau construction per curve of the net (per
   * column n for `u-then-v`, per row m for `v-then-u`); `first[k][r][i]` is
   * level r of curve k.
   */
  readonly first: Point[][][];
  /** The curves' end points: the control points of the iso-curve the second pass evaluates. */
  readonly intermediate: Point[];
  /** The second pass's de Casteljau levels on `intermediate`. */
  readonly second: Point[][];
  /** x(u, v). */
  readonly point: Point;
}

/**
 * The points r_m(v) = Σn fn(v) x(m,n), one per row m of the net: the control
 * points of the iso-curve v = const, a Bézier curve in u.
 */
export function surfaceRowPoints(grid: readonly (readonly Point[])[], v: number): Point[] {
  const dimension = checkNet('surfaceRowPoints', grid);
  checkParameter('surfaceRowPoints', 'v', v, 0, 1);
  const weights = bernsteinValues(grid[0].length - 1, v);
  return grid.map((row) => combine(row, weights, dimension));
}

/**
 * The points c_n(u) = Σm fm(u) x(m,n), one per column n of the net: the
 * control points of the iso-curve u = const, a Bézier curve in v.
 */
export function surfaceColumnPoints(grid: readonly (readonly Point[])[], u: number): Point[] {
  const dimension = checkNet('surfaceColumnPoints', grid);
  checkParameter('surfaceColumnPoints', 'u', u, 0, 1);
  const weights = bernsteinValues(grid.length - 1, u);
  return grid[0].map((_, n) =>
    combine(
      grid.map((row) => row[n]),
      weights,
      dimension,
    ),
  );
}

/**
 * x(u, v) by de Casteljau's construction on every column in u and then on
 * the results in v (`u-then-v`), or on every row in v and then in u
 * (`v-then-u`); both orders give the same point.
 */
export function surfaceDeCasteljau(
  grid: readonly (readonly Point[])[],
  u: number,
  v: number,
  order: SurfaceOrder,
): SurfaceConstruction {
  checkNet('surfaceDeCasteljau', grid);
  checkParameter('surfaceDeCasteljau', 'u', u, 0, 1);
  checkParameter('surfaceDeCasteljau', 'v', v, 0, 1);
  const curves = order === 'u-then-v' ? grid[0].map((_, n) => grid.map((row) => row[n])) : grid;
  const [firstParameter, secondParameter] = order === 'u-then-v' ? [u, v] : [v, u];
  const first = curves.map((curve) => deCasteljau(curve, firstParameter));
  const intermediate = first.map((levels) => levels[levels.length - 1][0]);
  const second = deCasteljau(intermediate, secondParameter);
  return { order, first, intermediate, second, point: second[second.length - 1][0].slice() };
}

/**
 * The weights fm(u)·fn(v) of every control point of a patch of `rows` × `columns`
 * points at (u, v): `weights[m][n]`. They are never negative and sum to 1.
 */
export function surfaceWeights(rows: number, columns: number, u: number, v: number): number[][] {
  checkInteger('surfaceWeights', 'rows', rows, 1);
  checkInteger('surfaceWeights', 'columns', columns, 1);
  checkParameter('surfaceWeights', 'u', u, 0, 1);
  checkParameter('surfaceWeights', 'v', v, 0, 1);
  const fu = bernsteinValues(rows - 1, u);
  const fv = bernsteinValues(columns - 1, v);
  return Array.from(fu, (a) => Array.from(fv, (b) => a * b));
}

function combine(points: readonly Point[], weights: Float64Array, dimension: number): Point {
  const result = new Array<number>(dimension).fill(0);
  points.forEach((point, i) => {
    for (let d = 0; d < dimension; d++) result[d] += weights[i] * point[d];
  });
  return result;
}

function bernsteinValues(n: number, t: number): Float64Array {
  const values = new Float64Array(n + 1);
  fillBernstein(n, t, values);
  return values;
}

function checkNet(caller: string, grid: readonly (readonly Point[])[]): number {
  if (!Array.isArray(grid) || grid.length < 1) {
    throw new RangeError(`${caller}: grid needs at least one row of control points.`);
  }
  const dimension = checkPoints(caller, 'grid[0]', grid[0], 1);
  for (let m = 1; m < grid.length; m++) {
    checkPoints(caller, `grid[${m}]`, grid[m], 1, dimension);
    if (grid[m].length !== grid[0].length) {
      throw new RangeError(
        `${caller}: grid[${m}] has ${grid[m].length} points but grid[0] has ${grid[0].length}; the control net must be rectangular.`,
      );
    }
  }
  return dimension;
}
