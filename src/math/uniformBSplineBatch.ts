import { checkCoordinateArrays, nonFiniteError } from './checkCoordinateArrays';
import { uniformBSplineWeights } from './uniformBSpline';
import { checkInteger } from './validate';

// The uniform cubic B-spline for very many points (10^5): control points as
// one Float64Array per coordinate in, samples or Bézier control points out in
// typed arrays, no per-point objects; the weights and Bézier form are those
// of uniformBSpline.ts. The check for NaN or ±Infinity rides along in the
// arithmetic, so only a failing call scans the input to name the culprit.

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
