import { evaluateBezier } from './bezier';
import { cubicSplineSegments } from './cubicSpline';
import { naturalCubicTangents } from './naturalCubic';
import { checkParameter, checkPoint, checkPoints } from './validate';
import type { Point } from './vec';

// Splines built from Bézier segments (lecture notes): a quadratic spline is C¹
// when each joint is the midpoint of its neighbouring control points; the
// natural cubic spline is C² and, written per segment, is a cubic Bézier.

/**
 * The C¹ quadratic Bézier spline through `points`: m segments (none for one
 * point) `[Pi, Bi, P(i+1)]` with `B0 = firstControl` and `B(i+1) = 2·P(i+1) − Bi`
 * (the joint is the midpoint of Bi and B(i+1), so the gradients match).
 */
export function quadraticSplineC1(points: readonly Point[], firstControl: Point): Point[][] {
  const dimension = checkPoints('quadraticSplineC1', 'points', points, 1);
  checkPoint('quadraticSplineC1', 'firstControl', firstControl, dimension);
  const segments: Point[][] = [];
  let control: Point = firstControl.slice();
  for (let i = 0; i + 1 < points.length; i++) {
    segments.push([points[i].slice(), control, points[i + 1].slice()]);
    const next = new Array<number>(dimension);
    for (let d = 0; d < dimension; d++) next[d] = 2 * points[i + 1][d] - control[d];
    control = next;
  }
  return segments;
}

/**
 * The natural C² cubic Bézier spline through `points`: m segments (none for one
 * point) `[Pi, Bi, Ci, P(i+1)]` with `Bi = Pi + Di/3`, `Ci = P(i+1) − D(i+1)/3`
 * from the natural spline's gradients, second derivative zero at both ends.
 */
export function cubicSplineC2(points: readonly Point[]): Point[][] {
  checkPoints('cubicSplineC2', 'points', points, 1);
  return cubicSplineSegments(points, naturalCubicTangents(points));
}

/**
 * The point at global `s ∈ [0, k]` on a chain of k Bézier segments (any
 * degrees, e.g. from quadraticSplineC1 or cubicSplineC2): segment
 * `min(floor(s), k−1)` at local `t = s − i`. Only that segment is read, so
 * only that segment is checked.
 */
export function bezierSplinePoint(segments: readonly (readonly Point[])[], s: number): Point {
  if (!Array.isArray(segments) || segments.length < 1) {
    throw new RangeError('bezierSplinePoint: segments needs at least 1 segment, but got none.');
  }
  const k = segments.length;
  checkParameter('bezierSplinePoint', 's', s, 0, k);
  const i = Math.min(Math.floor(s), k - 1);
  const dimension = checkPoints('bezierSplinePoint', `segments[${i}]`, segments[i], 1);
  return evaluateBezier(segments[i], dimension, s - i);
}
