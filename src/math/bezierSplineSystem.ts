import { checkPoints } from './checkPoints';
import type { Point } from './vec';

// The C² cubic Bézier spline as the practical writes it: n pieces through
// p0 … pn have 3n + 1 control points c0 … c3n, the unknowns. The equations:
//   c3i = pi                                   (interpolation, n + 1 rows; C⁰ by sharing)
//   c(3i−1) − 2c3i + c(3i+1) = 0               (C¹ at inner joint i: c3i midway)
//   c(3i−2) − 2c(3i−1) + 2c(3i+1) − c(3i+2) = 0 (C²: P″ of both pieces equal)
//   c0 − 2c1 + c2 = 0,  c(3n−2) − 2c(3n−1) + c3n = 0   (natural ends: P″ = 0)
// For four points the control points are A … J and the rows are the
// practical's 8 equations plus the 2 end conditions.

/** What one row of the system says. */
export type SplineEquationKind = 'point' | 'C1' | 'C2' | 'natural';

export interface SplineEquation {
  kind: SplineEquationKind;
  /** The point index (for 'point'), the inner joint (for C1/C2), 0 or n (for 'natural'). */
  at: number;
  /** The row's coefficients: `coefficients[j]` multiplies control point cj. */
  coefficients: number[];
  /** Right side per coordinate. */
  right: number[];
}

/** The (3n+1) × (3n+1) system of the C² cubic Bézier spline through `points` (at least 2). */
export function cubicSplineC2System(points: readonly Point[]): SplineEquation[] {
  const dimension = checkPoints('cubicSplineC2System', 'points', points, 2);
  const n = points.length - 1;
  const size = 3 * n + 1;
  const zero = () => new Array<number>(dimension).fill(0);
  const row = (
    kind: SplineEquationKind,
    at: number,
    terms: [number, number][],
    right: number[],
  ) => {
    const coefficients = new Array<number>(size).fill(0);
    for (const [j, value] of terms) coefficients[j] = value;
    return { kind, at, coefficients, right };
  };
  // Grouped as the practical lists them: the points, C¹, C², then the two ends.
  const rows: SplineEquation[] = [];
  for (let i = 0; i <= n; i++) rows.push(row('point', i, [[3 * i, 1]], points[i].slice()));
  for (let i = 1; i < n; i++)
    rows.push(
      row(
        'C1',
        i,
        [
          [3 * i - 1, 1],
          [3 * i, -2],
          [3 * i + 1, 1],
        ],
        zero(),
      ),
    );
  for (let i = 1; i < n; i++) {
    const k = 3 * i;
    rows.push(
      row(
        'C2',
        i,
        [
          [k - 2, 1],
          [k - 1, -2],
          [k + 1, 2],
          [k + 2, -1],
        ],
        zero(),
      ),
    );
  }
  rows.push(
    row(
      'natural',
      0,
      [
        [0, 1],
        [1, -2],
        [2, 1],
      ],
      zero(),
    ),
  );
  rows.push(
    row(
      'natural',
      n,
      [
        [3 * n - 2, 1],
        [3 * n - 1, -2],
        [3 * n, 1],
      ],
      zero(),
    ),
  );
  return rows;
}

/**
 * Solves the square system A x = B (B has one column per coordinate) by
 * Gaussian elimination with partial pivoting. RangeError if A is singular.
 */
export function solveDense(
  matrix: readonly (readonly number[])[],
  right: readonly (readonly number[])[],
): number[][] {
  const size = matrix.length;
  const a = matrix.map((r) => r.slice());
  const b = right.map((r) => r.slice());
  for (let col = 0; col < size; col++) {
    let pivot = col;
    for (let r = col + 1; r < size; r++)
      if (Math.abs(a[r][col]) > Math.abs(a[pivot][col])) pivot = r;
    if (!(Math.abs(a[pivot][col]) > 1e-14))
      throw new RangeError('solveDense: the matrix is singular.');
    [a[col], a[pivot]] = [a[pivot], a[col]];
    [b[col], b[pivot]] = [b[pivot], b[col]];
    for (let r = col + 1; r < size; r++) {
      const factor = a[r][col] / a[col][col];
      if (factor === 0) continue;
      for (let c = col; c < size; c++) a[r][c] -= factor * a[col][c];
      for (let d = 0; d < b[r].length; d++) b[r][d] -= factor * b[col][d];
    }
  }
  const x = b.map((r) => r.map(() => 0));
  for (let r = size - 1; r >= 0; r--) {
    for (let d = 0; d < x[r].length; d++) {
      let sum = b[r][d];
      for (let c = r + 1; c < size; c++) sum -= a[r][c] * x[c][d];
      x[r][d] = sum / a[r][r];
    }
  }
  return x;
}

/** The solved system: the control points c0 … c3n and the largest |A c − b| of any row. */
export interface SplineSystemSolution {
  equations: SplineEquation[];
  controls: Point[];
  residual: number;
}

/** Builds and solves the C² system through `points`, and measures how well the solution satisfies it. */
export function solveCubicSplineC2System(points: readonly Point[]): SplineSystemSolution {
  const equations = cubicSplineC2System(points);
  const controls = solveDense(
    equations.map((e) => e.coefficients),
    equations.map((e) => e.right),
  );
  let residual = 0;
  for (const { coefficients, right } of equations) {
    for (let d = 0; d < right.length; d++) {
      let sum = -right[d];
      coefficients.forEach((value, j) => (sum += value * controls[j][d]));
      residual = Math.max(residual, Math.abs(sum));
    }
  }
  return { equations, controls, residual };
}

/** The practical's names of the control points for four points: A … J; else c0 … c3n. */
export function controlPointName(j: number, count: number): string {
  return count === 10 ? 'ABCDEFGHIJ'[j] : `c_{${j}}`;
}
