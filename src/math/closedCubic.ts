import { checkPoints } from './checkPoints';
import { cyclicThomas } from './cyclicTridiagonal';
import type { TridiagonalSystem } from './tridiagonal';
import { checkNumbers } from './validate';
import type { Point } from './vec';

// The closed cubic spline through y0 … ym and back to y0 (lecture notes): with
// indices mod n = m + 1 every row is D(i−1) + 4Di + D(i+1) = 3(y(i+1) − y(i−1)).
// The matrix is cyclic tridiagonal, solved in O(n) by Sherman–Morrison.

/**
 * The closed spline's cyclic system for scalar values ys (at least 3), for
 * display: every row `[1 4 1]`, with `sub[0]` the corner entry of row 0 (the
 * coefficient of D(n−1)) and `sup[n−1]` the corner of the last row (of D0).
 */
export function closedCubicSystem(ys: readonly number[]): TridiagonalSystem {
  checkNumbers('closedCubicSystem', 'ys', ys, 3);
  return cyclicSystem(ys);
}

/**
 * The gradients `D0 … Dm` of the closed cubic spline through ys and back to
 * y0 (at least 3 values), solved in O(m).
 */
export function naturalCubicDerivativesClosed(ys: readonly number[]): number[] {
  checkNumbers('naturalCubicDerivativesClosed', 'ys', ys, 3);
  const { sub, diag, sup, rhs } = cyclicSystem(ys);
  const derivatives = new Array<number>(ys.length);
  cyclicThomas('naturalCubicDerivativesClosed', sub, diag, sup, rhs, derivatives);
  return derivatives;
}

/**
 * The closed spline's gradient vectors at each point (per coordinate), at least
 * 3 points, for `closedCubicSplinePoint(points, tangents, s)`.
 */
export function closedCubicTangents(points: readonly Point[]): Point[] {
  const caller = 'closedCubicTangents';
  const dimension = checkPoints(caller, 'points', points, 3);
  const n = points.length;
  const values = new Array<number>(n);
  const derivatives = new Float64Array(n);
  const tangents: number[][] = points.map(() => new Array<number>(dimension));
  for (let d = 0; d < dimension; d++) {
    for (let i = 0; i < n; i++) values[i] = points[i][d];
    const { sub, diag, sup, rhs } = cyclicSystem(values);
    cyclicThomas(caller, sub, diag, sup, rhs, derivatives);
    for (let i = 0; i < n; i++) tangents[i][d] = derivatives[i];
  }
  return tangents;
}

function cyclicSystem(ys: readonly number[]): TridiagonalSystem {
  const n = ys.length;
  const rhs = new Array<number>(n);
  for (let i = 0; i < n; i++) rhs[i] = 3 * (ys[(i + 1) % n] - ys[(i + n - 1) % n]);
  return {
    sub: new Array<number>(n).fill(1),
    diag: new Array<number>(n).fill(4),
    sup: new Array<number>(n).fill(1),
    rhs,
  };
}
