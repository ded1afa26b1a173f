import { checkCoordinateArrays, nonFiniteError } from './checkCoordinateArrays';
import { checkPoints } from './checkPoints';
import { checkInteger, checkParameter } from './validate';
import type { Point } from './vec';

// The uniform (unclamped) cubic B-spline of the lecture: segment i blends
// P(i) … P(i+3) with [1 t t² t³] · (1/6)[[1,4,1,0],[−3,0,3,0],[3,−6,3,0],[−1,3,−3,1]].
// The four blending functions are non-negative and sum to one, so each segment
// lies in the convex hull of its four control points; the curve is C² and in
// general passes through none of them.

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

/**
 * Samples the uniform cubic B-spline whose control points are given as parallel
 * coordinate arrays (`[xs, ys]` or `[xs, ys, zs]`, at least 4 points) at
 * `samplesPerSegment` steps per segment plus the end: returns one Float64Array
 * per coordinate with `(m−2)·samplesPerSegment + 1` samples. For 10^5 points;
 * pass `out` (one array per coordinate, long enough) to reuse buffers.
 */
export function sampleUniformBSpline(
  coordinates: readonly Float64Array[],
  samplesPerSegment: number,
  out?: Float64Array[],
): Float64Array[] {
  const caller = 'sampleUniformBSpline';
  const n = checkCoordinateArrays(caller, coordinates, 4);
  checkInteger(caller, 'samplesPerSegment', samplesPerSegment, 1);
  const k = samplesPerSegment;
  const length = (n - 3) * k + 1;
  const result = out ?? coordinates.map(() => new Float64Array(length));
  if (
    !Array.isArray(result) ||
    result.length !== coordinates.length ||
    result.some((array) => !(array instanceof Float64Array) || array.length < length)
  ) {
    throw new RangeError(
      `${caller}: out must hold ${coordinates.length} Float64Arrays of at least ${length} entries.`,
    );
  }
  // The four blending weights of each local step, computed once for all segments.
  const weights = new Float64Array(4 * (k + 1));
  for (let j = 0; j <= k; j++) weights.set(uniformBSplineWeights(j / k), 4 * j);
  for (let c = 0; c < coordinates.length; c++) {
    const check = sampleCoordinate(coordinates[c], weights, k, result[c]);
    if (check !== 0) throw nonFiniteError(caller, `coordinates[${c}]`, coordinates[c]);
  }
  return result;
}

/**
 * One coordinate of sampleUniformBSpline. Returns Σ value·0, which is 0 unless
 * some value is NaN or ±Infinity (then NaN): the check rides along.
 */
function sampleCoordinate(
  values: Float64Array,
  weights: Float64Array,
  k: number,
  samples: Float64Array,
): number {
  const segments = values.length - 3;
  let offset = 0;
  let check = 0;
  for (let i = 0; i < segments; i++) {
    const p0 = values[i];
    const p1 = values[i + 1];
    const p2 = values[i + 2];
    const p3 = values[i + 3];
    check += p0 * 0;
    for (let j = 0; j < k; j++) {
      const w = 4 * j;
      samples[offset++] =
        weights[w] * p0 + weights[w + 1] * p1 + weights[w + 2] * p2 + weights[w + 3] * p3;
    }
  }
  const last = 4 * k;
  const i = segments - 1;
  const [p1, p2, p3] = [values[i + 1], values[i + 2], values[i + 3]];
  samples[offset] =
    weights[last] * values[i] +
    weights[last + 1] * p1 +
    weights[last + 2] * p2 +
    weights[last + 3] * p3;
  return check + p1 * 0 + p2 * 0 + p3 * 0;
}

/** Bézier control points of every segment of a uniform cubic B-spline, per coordinate. */
export interface BSplineBezierControls {
  /** `joints[c][i]`: the segment ends `(P(i) + 4P(i+1) + P(i+2))/6`, i = 0 … m−2. */
  readonly joints: Float64Array[];
  /** `firstControl[c][i]`: `(2P(i+1) + P(i+2))/3` of segment i = 0 … m−3. */
  readonly firstControl: Float64Array[];
  /** `secondControl[c][i]`: `(P(i+1) + 2P(i+2))/3` of segment i. */
  readonly secondControl: Float64Array[];
}

/**
 * The uniform cubic B-spline with control points given as parallel coordinate
 * arrays (at least 4 points), as Bézier segments
 * `[joints[i], firstControl[i], secondControl[i], joints[i+1]]`, in typed
 * arrays. Pass `out` (arrays of at least m − 1, m − 2, m − 2 entries) to reuse
 * buffers from frame to frame.
 */
export function uniformBSplineBezierBatch(
  coordinates: readonly Float64Array[],
  out?: BSplineBezierControls,
): BSplineBezierControls {
  const caller = 'uniformBSplineBezierBatch';
  const n = checkCoordinateArrays(caller, coordinates, 4);
  const segments = n - 3;
  const result = out ?? {
    joints: coordinates.map(() => new Float64Array(segments + 1)),
    firstControl: coordinates.map(() => new Float64Array(segments)),
    secondControl: coordinates.map(() => new Float64Array(segments)),
  };
  checkBezierOutput(caller, result, coordinates.length, segments);
  for (let c = 0; c < coordinates.length; c++) {
    const values = coordinates[c];
    const check = coordinateControls(
      values,
      result.joints[c],
      result.firstControl[c],
      result.secondControl[c],
    );
    if (check !== 0) throw nonFiniteError(caller, `coordinates[${c}]`, values);
  }
  return result;
}

/**
 * One coordinate of uniformBSplineBezierBatch. Returns Σ value·0, which is 0
 * unless some value is NaN or ±Infinity (then NaN): the check rides along.
 */
function coordinateControls(
  values: Float64Array,
  joint: Float64Array,
  first: Float64Array,
  second: Float64Array,
): number {
  const segments = values.length - 3;
  const third = 1 / 3;
  const sixth = 1 / 6;
  let a = values[0];
  let b = values[1];
  let check = a * 0 + b * 0;
  for (let i = 0; i < segments; i++) {
    const next = values[i + 2];
    check += next * 0;
    joint[i] = (a + 4 * b + next) * sixth;
    first[i] = (2 * b + next) * third;
    second[i] = (b + 2 * next) * third;
    a = b;
    b = next;
  }
  const last = values[segments + 2];
  joint[segments] = (a + 4 * b + last) * sixth;
  return check + last * 0;
}

function checkBezierOutput(
  caller: string,
  out: BSplineBezierControls,
  dimension: number,
  segments: number,
): void {
  const lengths: [Float64Array[], number][] = [
    [out.joints, segments + 1],
    [out.firstControl, segments],
    [out.secondControl, segments],
  ];
  for (const [arrays, length] of lengths) {
    if (
      !Array.isArray(arrays) ||
      arrays.length !== dimension ||
      arrays.some((array) => !(array instanceof Float64Array) || array.length < length)
    ) {
      throw new RangeError(
        `${caller}: out must hold ${dimension} Float64Arrays per field, with at least ${segments + 1} joints and ${segments} of each control point.`,
      );
    }
  }
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
