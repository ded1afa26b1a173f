import { nonFiniteError } from './checkCoordinateArrays';
import { checkPoint, checkPoints } from './checkPoints';
import { cubicSplineCoefficients, sampleCubicSpline } from './cubicSpline';
import { fillNaturalDerivatives } from './naturalSolver';
import { thomas, type TridiagonalSystem } from './tridiagonal';
import { checkNumber, checkNumbers, copyCheckedNumbers } from './validate';
import type { Point } from './vec';

// The natural cubic spline through y0 … ym with uniform local parameter
// (lecture notes, "splines through the villages"): its gradients D0 … Dm solve
//   2D0 + D1 = 3(y1 − y0)
//   D(i−1) + 4Di + D(i+1) = 3(y(i+1) − y(i−1))      0 < i < m
//   D(m−1) + 2Dm = 3(ym − y(m−1))
// (second derivative zero at both ends). The clamped spline replaces the end
// rows by given D0 and Dm.

/**
 * The natural spline's tridiagonal system for scalar values ys (at least 2), so
 * a lesson can display the matrix: rows `[2 1]`, `[1 4 1]` …, `[1 2]`, right
 * side `3(y1−y0)`, `3(y(i+1)−y(i−1))`, `3(ym−y(m−1))`. `sub[0]` and `sup[m]` are 0.
 */
export function naturalCubicSystem(ys: readonly number[]): TridiagonalSystem {
  checkNumbers('naturalCubicSystem', 'ys', ys, 2);
  const n = ys.length;
  const m = n - 1;
  const sub = new Array<number>(n).fill(1);
  const diag = new Array<number>(n).fill(4);
  const sup = new Array<number>(n).fill(1);
  const rhs = new Array<number>(n);
  sub[0] = 0;
  sup[m] = 0;
  diag[0] = 2;
  diag[m] = 2;
  rhs[0] = 3 * (ys[1] - ys[0]);
  for (let i = 1; i < m; i++) rhs[i] = 3 * (ys[i + 1] - ys[i - 1]);
  rhs[m] = 3 * (ys[m] - ys[m - 1]);
  return { sub, diag, sup, rhs };
}

/**
 * The clamped spline's system: the natural system with its first and last rows
 * replaced by `[1 | d0]` and `[1 | dm]` (the given end gradients).
 */
export function clampedCubicSystem(
  ys: readonly number[],
  d0: number,
  dm: number,
): TridiagonalSystem {
  checkNumbers('clampedCubicSystem', 'ys', ys, 2);
  checkNumber('clampedCubicSystem', 'd0', d0);
  checkNumber('clampedCubicSystem', 'dm', dm);
  return clampedSystem(ys, d0, dm);
}

/**
 * The gradients `D0 … Dm` of the natural cubic spline through the scalar values
 * ys (one value gives `[0]`), by the Thomas algorithm in O(m).
 */
export function naturalCubicDerivatives(ys: readonly number[]): number[] {
  // The solver works on Float64Arrays only, so its loops stay monomorphic.
  const values = copyCheckedNumbers('naturalCubicDerivatives', 'ys', ys, 1);
  const n = values.length;
  const derivatives = new Float64Array(n);
  fillNaturalDerivatives(values, derivatives);
  // Finite values can still overflow; a non-finite gradient spreads to both ends.
  if (!Number.isFinite(derivatives[0]) || !Number.isFinite(derivatives[n - 1])) {
    throw nonFiniteError('naturalCubicDerivatives', 'ys', values);
  }
  // An index loop into a sized array, not Array.from, which iterates.
  const result = new Array<number>(n);
  for (let i = 0; i < n; i++) result[i] = derivatives[i];
  return result;
}

/**
 * The gradients `D0 … Dm` of the clamped cubic spline through ys (at least 2
 * values) with the given end gradients `D0 = d0`, `Dm = dm`.
 */
export function clampedCubicDerivatives(ys: readonly number[], d0: number, dm: number): number[] {
  checkNumbers('clampedCubicDerivatives', 'ys', ys, 2);
  checkNumber('clampedCubicDerivatives', 'd0', d0);
  checkNumber('clampedCubicDerivatives', 'dm', dm);
  const { sub, diag, sup, rhs } = clampedSystem(ys, d0, dm);
  const derivatives = new Array<number>(ys.length);
  thomas('clampedCubicDerivatives', sub, diag, sup, rhs, new Float64Array(ys.length), derivatives);
  return derivatives;
}

/**
 * The natural spline's gradient vectors at each of the points (per coordinate),
 * ready for `cubicSplinePoint(points, tangents, s)`.
 */
export function naturalCubicTangents(points: readonly Point[]): Point[] {
  const dimension = checkPoints('naturalCubicTangents', 'points', points, 1);
  const n = points.length;
  const values = new Float64Array(n);
  const derivatives = new Float64Array(n);
  const tangents = emptyPoints(n, dimension);
  for (let d = 0; d < dimension; d++) {
    for (let i = 0; i < n; i++) values[i] = points[i][d];
    fillNaturalDerivatives(values, derivatives);
    for (let i = 0; i < n; i++) tangents[i][d] = derivatives[i];
  }
  return tangents;
}

/**
 * The clamped spline's gradient vectors (per coordinate) with the given
 * gradients at the first and last point; at least 2 points.
 */
export function clampedCubicTangents(
  points: readonly Point[],
  startTangent: Point,
  endTangent: Point,
): Point[] {
  const caller = 'clampedCubicTangents';
  const dimension = checkPoints(caller, 'points', points, 2);
  checkPoint(caller, 'startTangent', startTangent, dimension);
  checkPoint(caller, 'endTangent', endTangent, dimension);
  const n = points.length;
  const values = new Array<number>(n);
  const gamma = new Float64Array(n);
  const derivatives = new Float64Array(n);
  const tangents = emptyPoints(n, dimension);
  for (let d = 0; d < dimension; d++) {
    for (let i = 0; i < n; i++) values[i] = points[i][d];
    const { sub, diag, sup, rhs } = clampedSystem(values, startTangent[d], endTangent[d]);
    thomas(caller, sub, diag, sup, rhs, gamma, derivatives);
    for (let i = 0; i < n; i++) tangents[i][d] = derivatives[i];
  }
  return tangents;
}

function clampedSystem(ys: ArrayLike<number>, d0: number, dm: number): TridiagonalSystem {
  const n = ys.length;
  const m = n - 1;
  const sub = new Array<number>(n).fill(1);
  const diag = new Array<number>(n).fill(4);
  const sup = new Array<number>(n).fill(1);
  const rhs = new Array<number>(n);
  sub[0] = 0;
  sup[0] = 0;
  diag[0] = 1;
  rhs[0] = d0;
  for (let i = 1; i < m; i++) rhs[i] = 3 * (ys[i + 1] - ys[i - 1]);
  sub[m] = 0;
  sup[m] = 0;
  diag[m] = 1;
  rhs[m] = dm;
  return { sub, diag, sup, rhs };
}

function emptyPoints(count: number, dimension: number): number[][] {
  const points = new Array<number[]>(count);
  for (let i = 0; i < count; i++) points[i] = new Array<number>(dimension);
  return points;
}

/**
 * The power-form coefficients `[a, b, c, d]` of each segment of the natural
 * cubic spline through ys, `y(t) = a + b·t + c·t² + d·t³` (for display).
 */
export function naturalCubicCoefficients(
  ys: readonly number[],
): [number, number, number, number][] {
  return cubicSplineCoefficients(ys, naturalCubicDerivatives(ys));
}

/**
 * Samples the natural cubic spline through points at `samplesPerSegment` steps
 * per segment into an interleaved Float64Array (see `sampleCubicSpline`).
 */
export function sampleNaturalCubicSpline(
  points: readonly Point[],
  samplesPerSegment: number,
  out?: Float64Array,
): Float64Array {
  return sampleCubicSpline(points, naturalCubicTangents(points), samplesPerSegment, out);
}
