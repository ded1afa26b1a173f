import { checkPoints } from './checkPoints';
import { hermiteWeights } from './hermite';
import { checkInteger, checkNumbers, checkParameter, checkSameLength } from './validate';
import type { Point } from './vec';

// A piecewise cubic Hermite curve (lecture notes): segment i joins Pi to
// P(i+1) for local t ∈ [0, 1] with end gradients Di and D(i+1). Natural,
// clamped, closed and Catmull-Rom splines differ only in how they choose D.

/**
 * The piecewise cubic Hermite curve through `points` with gradients `tangents`,
 * at global `s ∈ [0, m]` (segment `min(floor(s), m−1)`, local `t = s − i`).
 */
export function cubicSplinePoint(
  points: readonly Point[],
  tangents: readonly Point[],
  s: number,
): Point {
  const dimension = checkSpline('cubicSplinePoint', points, tangents, 1);
  const m = points.length - 1;
  checkParameter('cubicSplinePoint', 's', s, 0, m);
  if (m === 0) return points[0].slice();
  const i = Math.min(Math.floor(s), m - 1);
  return segmentPoint(points[i], tangents[i], points[i + 1], tangents[i + 1], s - i, dimension);
}

/**
 * The closed piecewise cubic through `points` and back to P0 (at least 2
 * points): m + 1 segments, the last joining Pm to P0, at global `s ∈ [0, m+1]`.
 * Use with `closedCubicTangents`.
 */
export function closedCubicSplinePoint(
  points: readonly Point[],
  tangents: readonly Point[],
  s: number,
): Point {
  const dimension = checkSpline('closedCubicSplinePoint', points, tangents, 2);
  const n = points.length;
  checkParameter('closedCubicSplinePoint', 's', s, 0, n);
  const i = Math.min(Math.floor(s), n - 1);
  const j = i + 1 === n ? 0 : i + 1;
  return segmentPoint(points[i], tangents[i], points[j], tangents[j], s - i, dimension);
}

/**
 * The same curve as cubic Bézier segments `[Pi, Pi + Di/3, P(i+1) − D(i+1)/3,
 * P(i+1)]` for drawing; with `closed`, one more segment from Pm back to P0.
 */
export function cubicSplineSegments(
  points: readonly Point[],
  tangents: readonly Point[],
  closed = false,
): Point[][] {
  const dimension = checkSpline('cubicSplineSegments', points, tangents, closed ? 2 : 1);
  const n = points.length;
  const count = closed ? n : n - 1;
  const segments: Point[][] = new Array<Point[]>(count);
  for (let i = 0; i < count; i++) {
    const j = i + 1 === n ? 0 : i + 1;
    const first = new Array<number>(dimension);
    const second = new Array<number>(dimension);
    for (let d = 0; d < dimension; d++) {
      first[d] = points[i][d] + tangents[i][d] / 3;
      second[d] = points[j][d] - tangents[j][d] / 3;
    }
    segments[i] = [points[i].slice(), first, second, points[j].slice()];
  }
  return segments;
}

/**
 * The power-form coefficients `[a, b, c, d]` of each segment of the scalar
 * cubic spline with values ys and gradients ds, `y(t) = a + b·t + c·t² + d·t³`
 * on segment i: `a = yi`, `b = Di`, `c = 3(y(i+1) − yi) − 2Di − D(i+1)`,
 * `d = 2(yi − y(i+1)) + Di + D(i+1)` (lecture equation 7). For display.
 */
export function cubicSplineCoefficients(
  ys: readonly number[],
  ds: readonly number[],
): [number, number, number, number][] {
  checkNumbers('cubicSplineCoefficients', 'ys', ys, 1);
  checkNumbers('cubicSplineCoefficients', 'ds', ds, 1);
  checkSameLength('cubicSplineCoefficients', 'ys', ys, 'ds', ds);
  const coefficients: [number, number, number, number][] = [];
  for (let i = 0; i + 1 < ys.length; i++) {
    const [y0, y1, d0, d1] = [ys[i], ys[i + 1], ds[i], ds[i + 1]];
    coefficients.push([y0, d0, 3 * (y1 - y0) - 2 * d0 - d1, 2 * (y0 - y1) + d0 + d1]);
  }
  return coefficients;
}

/**
 * Samples the spline at `samplesPerSegment` uniform steps per segment (plus the
 * final point) into an interleaved Float64Array `[x0, y0, x1, y1, …]`:
 * `m·samplesPerSegment + 1` samples, exactly Pi at each joint. Pass `out` to
 * reuse a buffer.
 */
export function sampleCubicSpline(
  points: readonly Point[],
  tangents: readonly Point[],
  samplesPerSegment: number,
  out?: Float64Array,
): Float64Array {
  const dimension = checkSpline('sampleCubicSpline', points, tangents, 1);
  checkInteger('sampleCubicSpline', 'samplesPerSegment', samplesPerSegment, 1);
  const m = points.length - 1;
  const k = samplesPerSegment;
  const length = (m * k + 1) * dimension;
  const result = out && out.length >= length ? out : new Float64Array(length);
  // The Hermite weights of each local step, computed once for all segments.
  const weights = new Float64Array(4 * k);
  for (let j = 0; j < k; j++) weights.set(hermiteWeights(j / k), 4 * j);
  let offset = 0;
  for (let i = 0; i < m; i++) {
    const [p0, d0, p1, d1] = [points[i], tangents[i], points[i + 1], tangents[i + 1]];
    for (let j = 0; j < k; j++) {
      const w = 4 * j;
      for (let d = 0; d < dimension; d++) {
        result[offset++] =
          weights[w] * p0[d] +
          weights[w + 1] * p1[d] +
          weights[w + 2] * d0[d] +
          weights[w + 3] * d1[d];
      }
    }
  }
  for (let d = 0; d < dimension; d++) result[offset++] = points[m][d];
  return result;
}

function segmentPoint(
  p0: Point,
  d0: Point,
  p1: Point,
  d1: Point,
  t: number,
  dimension: number,
): Point {
  const [h0, h1, h2, h3] = hermiteWeights(t);
  const result = new Array<number>(dimension);
  for (let d = 0; d < dimension; d++) {
    result[d] = h0 * p0[d] + h1 * p1[d] + h2 * d0[d] + h3 * d1[d];
  }
  return result;
}

function checkSpline(
  caller: string,
  points: readonly Point[],
  tangents: readonly Point[],
  minimum: number,
): number {
  const dimension = checkPoints(caller, 'points', points, minimum);
  checkPoints(caller, 'tangents', tangents, minimum, dimension);
  checkSameLength(caller, 'points', points, 'tangents', tangents);
  return dimension;
}
