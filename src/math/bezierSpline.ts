import { evaluateBezier } from './bezier';
import { nonFiniteError } from './checkCoordinateArrays';
import { checkPoint, checkPoints } from './checkPoints';
import { fillNaturalBezierControls, type CubicBezierControls } from './naturalCubicBatch';
import { checkParameter } from './validate';
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
  const caller = 'cubicSplineC2';
  const dimension = checkPoints(caller, 'points', points, 1);
  const m = points.length - 1;
  if (m === 0) return [];
  // One pass to validate; then the typed-array solver of naturalCubicBezierBatch,
  // and the output arrays built once from its results.
  const coordinates = coordinateArrays(points, dimension);
  const controls: CubicBezierControls = {
    firstControl: coordinates.map(() => new Float64Array(m)),
    secondControl: coordinates.map(() => new Float64Array(m)),
  };
  const failed = fillNaturalBezierControls(coordinates, controls);
  if (failed >= 0) throw nonFiniteError(caller, 'points', coordinates[failed]);
  return cubicSegments(coordinates, controls);
}

/** Coordinate d of every point as one Float64Array per d (`[xs, ys]`). */
function coordinateArrays(points: readonly Point[], dimension: number): Float64Array[] {
  const n = points.length;
  const coordinates = new Array<Float64Array>(dimension);
  for (let d = 0; d < dimension; d++) {
    const values = new Float64Array(n);
    for (let i = 0; i < n; i++) values[i] = points[i][d];
    coordinates[d] = values;
  }
  return coordinates;
}

/**
 * The segments `[Pi, Bi, Ci, P(i+1)]` as fresh arrays. 2D and 3D are written
 * out as array literals, which V8 allocates inline; other dimensions loop.
 */
function cubicSegments(
  coordinates: readonly Float64Array[],
  { firstControl, secondControl }: CubicBezierControls,
): Point[][] {
  const m = coordinates[0].length - 1;
  const segments = new Array<Point[]>(m);
  if (coordinates.length === 2) {
    const [xs, ys] = [coordinates[0], coordinates[1]];
    const [bx, by] = [firstControl[0], firstControl[1]];
    const [cx, cy] = [secondControl[0], secondControl[1]];
    for (let i = 0; i < m; i++) {
      segments[i] = [
        [xs[i], ys[i]],
        [bx[i], by[i]],
        [cx[i], cy[i]],
        [xs[i + 1], ys[i + 1]],
      ];
    }
  } else if (coordinates.length === 3) {
    const [xs, ys, zs] = [coordinates[0], coordinates[1], coordinates[2]];
    const [bx, by, bz] = [firstControl[0], firstControl[1], firstControl[2]];
    const [cx, cy, cz] = [secondControl[0], secondControl[1], secondControl[2]];
    for (let i = 0; i < m; i++) {
      segments[i] = [
        [xs[i], ys[i], zs[i]],
        [bx[i], by[i], bz[i]],
        [cx[i], cy[i], cz[i]],
        [xs[i + 1], ys[i + 1], zs[i + 1]],
      ];
    }
  } else {
    for (let i = 0; i < m; i++) {
      segments[i] = [
        pointAt(coordinates, i),
        pointAt(firstControl, i),
        pointAt(secondControl, i),
        pointAt(coordinates, i + 1),
      ];
    }
  }
  return segments;
}

/** The point whose coordinate d is `arrays[d][i]`. */
function pointAt(arrays: readonly Float64Array[], i: number): number[] {
  const point = new Array<number>(arrays.length);
  for (let d = 0; d < arrays.length; d++) point[d] = arrays[d][i];
  return point;
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
