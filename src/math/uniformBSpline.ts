import { checkPoints } from './checkPoints';
import { checkParameter } from './validate';
import type { Point } from './vec';

// The uniform (unclamped) cubic B-spline of the lecture: segment i blends
// P(i) … P(i+3) with [1 t t² t³] · (1/6)[[1,4,1,0],[−3,0,3,0],[3,−6,3,0],[−1,3,−3,1]].
// The four blending functions are non-negative and sum to one, so each segment
// lies in the convex hull of its four control points; the curve is C² and in
// general passes through none of them.
// For very many points, uniformBSplineBatch.ts samples it and gives its
// Bézier segments in typed arrays.

/** The lecture's uniform cubic B-spline matrix `(1/6)[[1,4,1,0],[−3,0,3,0],[3,−6,3,0],[−1,3,−3,1]]`. */
export function uniformBSplineMatrix(): number[][] {
  return [
    [1 / 6, 4 / 6, 1 / 6, 0],
    [-3 / 6, 0, 3 / 6, 0],
    [3 / 6, -6 / 6, 3 / 6, 0],
    [-1 / 6, 3 / 6, -3 / 6, 1 / 6],
  ];
}

/**
 * The four blending functions of a uniform cubic B-spline segment at local
 * t ∈ [0, 1], weighting P(i) … P(i+3): `(1−t)³/6`, `(3t³ − 6t² + 4)/6`,
 * `(−3t³ + 3t² + 3t + 1)/6`, `t³/6`. For plotting.
 */
export function uniformBSplineBasis(t: number): [number, number, number, number] {
  checkParameter('uniformBSplineBasis', 't', t, 0, 1);
  return uniformBSplineWeights(t);
}

/** uniformBSplineBasis without checks. Internal. */
export function uniformBSplineWeights(t: number): [number, number, number, number] {
  const s = 1 - t;
  const t2 = t * t;
  const t3 = t2 * t;
  return [(s * s * s) / 6, (3 * t3 - 6 * t2 + 4) / 6, (-3 * t3 + 3 * t2 + 3 * t + 1) / 6, t3 / 6];
}

/**
 * The point at global `s ∈ [0, m−2]` on the uniform cubic B-spline with control
 * points P0 … Pm (at least 4): segment `min(floor(s), m−3)` at local `t = s − i`.
 */
export function uniformBSplinePoint(points: readonly Point[], s: number): Point {
  const dimension = checkPoints('uniformBSplinePoint', 'points', points, 4);
  const segments = points.length - 3;
  checkParameter('uniformBSplinePoint', 's', s, 0, segments);
  const i = Math.min(Math.floor(s), segments - 1);
  const [w0, w1, w2, w3] = uniformBSplineWeights(s - i);
  const result = new Array<number>(dimension);
  for (let d = 0; d < dimension; d++) {
    result[d] =
      w0 * points[i][d] + w1 * points[i + 1][d] + w2 * points[i + 2][d] + w3 * points[i + 3][d];
  }
  return result;
}

/**
 * The Bézier control points of one uniform cubic B-spline segment with control
 * points P0 … P3: `(P0 + 4P1 + P2)/6`, `(2P1 + P2)/3`, `(P1 + 2P2)/3`, `(P1 + 4P2 + P3)/6`.
 */
export function uniformBSplineToBezier(points: readonly Point[]): Point[] {
  const dimension = checkFour('uniformBSplineToBezier', points);
  const [p0, p1, p2, p3] = points;
  const result: number[][] = [[], [], [], []];
  for (let d = 0; d < dimension; d++) {
    result[0][d] = (p0[d] + 4 * p1[d] + p2[d]) / 6;
    result[1][d] = (2 * p1[d] + p2[d]) / 3;
    result[2][d] = (p1[d] + 2 * p2[d]) / 3;
    result[3][d] = (p1[d] + 4 * p2[d] + p3[d]) / 6;
  }
  return result;
}

/**
 * The uniform cubic B-spline control points of a cubic Bézier segment B0 … B3
 * (the inverse of `uniformBSplineToBezier`): `6B0 − 7B1 + 2B2`, `2B1 − B2`,
 * `2B2 − B1`, `2B1 − 7B2 + 6B3`.
 */
export function bezierToUniformBSpline(points: readonly Point[]): Point[] {
  const dimension = checkFour('bezierToUniformBSpline', points);
  const [b0, b1, b2, b3] = points;
  const result: number[][] = [[], [], [], []];
  for (let d = 0; d < dimension; d++) {
    result[0][d] = 6 * b0[d] - 7 * b1[d] + 2 * b2[d];
    result[1][d] = 2 * b1[d] - b2[d];
    result[2][d] = 2 * b2[d] - b1[d];
    result[3][d] = 2 * b1[d] - 7 * b2[d] + 6 * b3[d];
  }
  return result;
}

/** The whole uniform cubic B-spline (at least 4 control points) as m − 2 Bézier segments. */
export function uniformBSplineSegments(points: readonly Point[]): Point[][] {
  checkPoints('uniformBSplineSegments', 'points', points, 4);
  const segments: Point[][] = [];
  for (let i = 0; i + 3 < points.length; i++) {
    segments.push(uniformBSplineToBezier(points.slice(i, i + 4)));
  }
  return segments;
}

function checkFour(caller: string, points: readonly Point[]): number {
  const dimension = checkPoints(caller, 'points', points, 4);
  if (points.length !== 4) {
    throw new RangeError(
      `${caller}: points must hold exactly 4 control points, but got ${points.length}.`,
    );
  }
  return dimension;
}
