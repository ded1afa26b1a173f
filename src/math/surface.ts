import { fillBernstein } from './bernstein';
import { checkPoints } from './checkPoints';
import { checkParameter } from './validate';
import type { Point } from './vec';

// Tensor-product Bézier patches (lecture notes, surfaces):
// x(u, v) = Σm Σn fm(u) fn(v) x(m,n), with f the Bernstein functions of each
// direction's degree. Partial derivatives differentiate one direction's
// Bernstein functions: ∂x/∂u = M Σm Σn W(M−1, m, u) fn(v) (x(m+1,n) − x(m,n)).

/** The point and both partial derivatives of a patch at (u, v). */
export interface SurfaceJet {
  readonly point: Point;
  /** ∂x/∂u, along the first index of the grid. */
  readonly du: Point;
  /** ∂x/∂v, along the second index of the grid. */
  readonly dv: Point;
}

/**
 * The tensor-product Bézier patch `Σm Σn fm(u) fn(v) x(m,n)` at (u, v) ∈ [0, 1]²,
 * `grid[m][n]` of any degree in each direction (4×4 is the bicubic patch).
 */
export function bezierSurfacePoint(
  grid: readonly (readonly Point[])[],
  u: number,
  v: number,
): Point {
  const dimension = checkGrid('bezierSurfacePoint', grid, u, v);
  const fu = bernsteinValues(grid.length - 1, u);
  const fv = bernsteinValues(grid[0].length - 1, v);
  return weightedSum(grid, dimension, fu, fv, 0, 0);
}

/** The point and the partial derivatives ∂x/∂u, ∂x/∂v of the patch at (u, v). */
export function bezierSurfaceDerivatives(
  grid: readonly (readonly Point[])[],
  u: number,
  v: number,
): SurfaceJet {
  const dimension = checkGrid('bezierSurfaceDerivatives', grid, u, v);
  return surfaceJet(grid, dimension, u, v);
}

/**
 * The unit normal `(∂x/∂u × ∂x/∂v) / |…|` of a 3D patch at (u, v). RangeError
 * where the partial derivatives are parallel or zero (e.g. a collapsed edge).
 */
export function bezierSurfaceNormal(
  grid: readonly (readonly Point[])[],
  u: number,
  v: number,
): Point {
  const caller = 'bezierSurfaceNormal';
  const dimension = checkGrid(caller, grid, u, v);
  if (dimension !== 3) {
    throw new RangeError(
      `${caller}: the grid points are ${dimension}D; a surface normal needs 3D points.`,
    );
  }
  const { du, dv } = surfaceJet(grid, dimension, u, v);
  const normal = [
    du[1] * dv[2] - du[2] * dv[1],
    du[2] * dv[0] - du[0] * dv[2],
    du[0] * dv[1] - du[1] * dv[0],
  ];
  const length = Math.hypot(normal[0], normal[1], normal[2]);
  if (!(length > 1e-12 * Math.hypot(...du) * Math.hypot(...dv)) || length === 0) {
    throw new RangeError(
      `${caller}: the partial derivatives at (u, v) = (${u}, ${v}) are parallel or zero, so the surface has no tangent plane there; try another (u, v).`,
    );
  }
  return normal.map((value) => value / length);
}

function surfaceJet(
  grid: readonly (readonly Point[])[],
  dimension: number,
  u: number,
  v: number,
): SurfaceJet {
  const rows = grid.length - 1;
  const columns = grid[0].length - 1;
  const fu = bernsteinValues(rows, u);
  const fv = bernsteinValues(columns, v);
  const point = weightedSum(grid, dimension, fu, fv, 0, 0);
  const du =
    rows === 0
      ? new Array<number>(dimension).fill(0)
      : weightedSum(grid, dimension, bernsteinValues(rows - 1, u), fv, 1, 0).map(
          (value) => rows * value,
        );
  const dv =
    columns === 0
      ? new Array<number>(dimension).fill(0)
      : weightedSum(grid, dimension, fu, bernsteinValues(columns - 1, v), 0, 1).map(
          (value) => columns * value,
        );
  return { point, du, dv };
}

/**
 * Σm Σn wu[m] wv[n] Δx(m,n), where Δ is the forward difference along u when
 * `stepU` is 1, along v when `stepV` is 1, and the point itself when both are 0.
 */
function weightedSum(
  grid: readonly (readonly Point[])[],
  dimension: number,
  wu: Float64Array,
  wv: Float64Array,
  stepU: number,
  stepV: number,
): number[] {
  const result = new Array<number>(dimension).fill(0);
  for (let m = 0; m < wu.length; m++) {
    for (let n = 0; n < wv.length; n++) {
      const weight = wu[m] * wv[n];
      if (weight === 0) continue;
      const here = grid[m][n];
      const there = grid[m + stepU][n + stepV];
      for (let d = 0; d < dimension; d++) {
        result[d] += weight * (stepU + stepV === 0 ? here[d] : there[d] - here[d]);
      }
    }
  }
  return result;
}

function bernsteinValues(n: number, t: number): Float64Array {
  const values = new Float64Array(n + 1);
  fillBernstein(n, t, values);
  return values;
}

function checkGrid(
  caller: string,
  grid: readonly (readonly Point[])[],
  u: number,
  v: number,
): number {
  if (!Array.isArray(grid) || grid.length < 1) {
    throw new RangeError(`${caller}: grid needs at least one row of control points.`);
  }
  const dimension = checkPoints(caller, 'grid[0]', grid[0], 1);
  const columns = grid[0].length;
  for (let m = 1; m < grid.length; m++) {
    checkPoints(caller, `grid[${m}]`, grid[m], 1, dimension);
    if (grid[m].length !== columns) {
      throw new RangeError(
        `${caller}: grid[${m}] has ${grid[m].length} points but grid[0] has ${columns}; the control net must be rectangular.`,
      );
    }
  }
  checkParameter(caller, 'u', u, 0, 1);
  checkParameter(caller, 'v', v, 0, 1);
  return dimension;
}
