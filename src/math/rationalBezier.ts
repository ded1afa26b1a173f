import { fillBernstein } from './bernstein';
import { checkPoints } from './checkPoints';
import { checkInteger, checkNumbers, checkParameter, checkSameLength } from './validate';
import type { Point } from './vec';

// A rational Bézier curve (Farin, Curves and Surfaces for CAGD, ch. 13):
// P(t) = Σ wᵢ W(n, i, t) Pᵢ / Σ wᵢ W(n, i, t), the simplest NURBS. With all
// weights equal it is the Bézier curve of the same points.

function checkWeights(
  caller: string,
  points: readonly Point[],
  weights: readonly number[],
): number {
  const dimension = checkPoints(caller, 'points', points, 1);
  checkNumbers(caller, 'weights', weights, 1);
  checkSameLength(caller, 'weights', weights, 'points', points);
  for (let i = 0; i < weights.length; i++) {
    if (!(weights[i] > 0)) {
      throw new RangeError(
        `${caller}: weights[${i}] = ${weights[i]} is not positive; a rational Bézier curve needs weights > 0.`,
      );
    }
  }
  return dimension;
}

/** Σ wᵢ W(n, i, t) Pᵢ / Σ wᵢ W(n, i, t) into `out` at `offset`, with the basis already in `basis`. */
function weightedAverage(
  points: readonly Point[],
  weights: readonly number[],
  basis: Float64Array,
  dimension: number,
  out: { [d: number]: number },
  offset: number,
): void {
  let denominator = 0;
  for (let i = 0; i < points.length; i++) denominator += weights[i] * basis[i];
  for (let d = 0; d < dimension; d++) {
    let sum = 0;
    for (let i = 0; i < points.length; i++) sum += weights[i] * basis[i] * points[i][d];
    out[offset + d] = sum / denominator;
  }
}

/**
 * The point at t ∈ [0, 1] of the rational Bézier curve with control points
 * `points` and positive `weights` (one per point).
 */
export function rationalBezierPoint(
  points: readonly Point[],
  weights: readonly number[],
  t: number,
): Point {
  const dimension = checkWeights('rationalBezierPoint', points, weights);
  checkParameter('rationalBezierPoint', 't', t, 0, 1);
  const basis = new Float64Array(points.length);
  fillBernstein(points.length - 1, t, basis);
  const point = new Array<number>(dimension);
  weightedAverage(points, weights, basis, dimension, point, 0);
  return point;
}

/**
 * The rational Bézier curve sampled at t = 0, 1/segments, …, 1, into one
 * interleaved Float64Array `[x0, y0, x1, y1, …]` (as sampleBezier does).
 */
export function sampleRationalBezier(
  points: readonly Point[],
  weights: readonly number[],
  segments: number,
): Float64Array {
  const dimension = checkWeights('sampleRationalBezier', points, weights);
  checkInteger('sampleRationalBezier', 'segments', segments, 1);
  const result = new Float64Array((segments + 1) * dimension);
  const basis = new Float64Array(points.length);
  for (let k = 0; k <= segments; k++) {
    fillBernstein(points.length - 1, k / segments, basis);
    weightedAverage(points, weights, basis, dimension, result, k * dimension);
  }
  return result;
}
