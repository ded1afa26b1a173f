import { checkPoints } from './checkPoints';
import { checkInteger, checkParameter } from './validate';
import type { Point } from './vec';

// Bézier curves by de Casteljau's construction (lecture notes: P_{r,i} =
// (1 − t) P_{r−1,i} + t P_{r−1,i+1}). Repeated convex combinations never
// subtract large nearby numbers, so the result is accurate for coordinates of
// 1e6 or 1e-6 alike, and exact at t = 0 and t = 1.

/** Scratch row for bezierPoint, grown on demand so evaluation does not allocate. */
let scratch = new Float64Array(16);

/**
 * Every level of de Casteljau's construction: `levels[0]` is a copy of the
 * control points, `levels[r][i] = (1 − t)·levels[r−1][i] + t·levels[r−1][i+1]`,
 * and `levels[n][0]` is the point on the curve (the lecture's `P_{r,i}`).
 */
export function deCasteljau(points: readonly Point[], t: number): Point[][] {
  const dimension = checkPoints('deCasteljau', 'points', points, 1);
  checkParameter('deCasteljau', 't', t, 0, 1);
  const s = 1 - t;
  const levels: Point[][] = [points.map((point) => point.slice())];
  for (let r = 1; r < points.length; r++) {
    const previous = levels[r - 1];
    const level: Point[] = new Array<Point>(previous.length - 1);
    for (let i = 0; i < level.length; i++) {
      const a = previous[i];
      const b = previous[i + 1];
      const point = new Array<number>(dimension);
      for (let d = 0; d < dimension; d++) point[d] = s * a[d] + t * b[d];
      level[i] = point;
    }
    levels.push(level);
  }
  return levels;
}

/** The point at parameter t ∈ [0, 1] on the Bézier curve with these control points. */
export function bezierPoint(points: readonly Point[], t: number): Point {
  // The lessons' everyday curves, 2D and 3D cubics, take straight-line code
  // small enough for V8 to inline into the caller's loop. Anything else, or
  // anything wrong, takes the general path, which words the error.
  if (points.length === 4 && typeof t === 'number' && t >= 0 && t <= 1) {
    const p0 = points[0];
    const p1 = points[1];
    const p2 = points[2];
    const p3 = points[3];
    if (Array.isArray(p0) && Array.isArray(p1) && Array.isArray(p2) && Array.isArray(p3)) {
      const dimension = p0.length;
      if (p1.length === dimension && p2.length === dimension && p3.length === dimension) {
        if (dimension === 2) return planarCubicPoint(points, p0, p1, p2, p3, t);
        if (dimension === 3) return spatialCubicPoint(points, p0, p1, p2, p3, t);
      }
    }
  }
  return checkedBezierPoint(points, t);
}

function checkedBezierPoint(points: readonly Point[], t: number): Point {
  const dimension = checkPoints('bezierPoint', 'points', points, 1);
  checkParameter('bezierPoint', 't', t, 0, 1);
  return evaluateBezier(points, dimension, t);
}

// The fast paths check their input by their output: cubicCoordinate gives NaN
// for a coordinate that is not a number, and a NaN or ±Infinity coordinate
// cannot give a finite result (every coordinate enters it through products
// with s and t and sums, and 0·∞ is NaN). So a finite result (v − v = 0) means
// the input was good; otherwise checkedBezierPoint finds what was wrong.

function planarCubicPoint(
  points: readonly Point[],
  p0: Point,
  p1: Point,
  p2: Point,
  p3: Point,
  t: number,
): Point {
  const x = cubicCoordinate(p0[0], p1[0], p2[0], p3[0], t);
  const y = cubicCoordinate(p0[1], p1[1], p2[1], p3[1], t);
  if (x - x + (y - y) === 0) return [x, y];
  return checkedBezierPoint(points, t);
}

function spatialCubicPoint(
  points: readonly Point[],
  p0: Point,
  p1: Point,
  p2: Point,
  p3: Point,
  t: number,
): Point {
  const x = cubicCoordinate(p0[0], p1[0], p2[0], p3[0], t);
  const y = cubicCoordinate(p0[1], p1[1], p2[1], p3[1], t);
  const z = cubicCoordinate(p0[2], p1[2], p2[2], p3[2], t);
  if (x - x + (y - y) + (z - z) === 0) return [x, y, z];
  return checkedBezierPoint(points, t);
}

/** One coordinate of a cubic by de Casteljau's six interpolations; NaN unless all four are numbers. */
function cubicCoordinate(v0: number, v1: number, v2: number, v3: number, t: number): number {
  if (
    typeof v0 !== 'number' ||
    typeof v1 !== 'number' ||
    typeof v2 !== 'number' ||
    typeof v3 !== 'number'
  ) {
    return NaN;
  }
  const s = 1 - t;
  const a = s * v0 + t * v1;
  const b = s * v1 + t * v2;
  const c = s * v2 + t * v3;
  return s * (s * a + t * b) + t * (s * b + t * c);
}

/** de Casteljau without checks, for callers that have already validated. */
export function evaluateBezier(points: readonly Point[], dimension: number, t: number): Point {
  const count = points.length;
  const s = 1 - t;
  const result = new Array<number>(dimension);
  if (count === 4) {
    // The cubic, the lessons' everyday curve, unrolled: the same six
    // interpolations as the general loop, without the scratch row.
    const p0 = points[0];
    const p1 = points[1];
    const p2 = points[2];
    const p3 = points[3];
    for (let d = 0; d < dimension; d++) result[d] = cubicCoordinate(p0[d], p1[d], p2[d], p3[d], t);
    return result;
  }
  if (scratch.length < count) scratch = new Float64Array(2 * count);
  const row = scratch;
  // One coordinate at a time keeps the scratch row one-dimensional.
  for (let d = 0; d < dimension; d++) {
    for (let i = 0; i < count; i++) row[i] = points[i][d];
    for (let r = count - 1; r > 0; r--) {
      for (let i = 0; i < r; i++) row[i] = s * row[i] + t * row[i + 1];
    }
    result[d] = row[0];
  }
  return result;
}

/**
 * Subdivision at t: the left polygon is `levels[r][0]` for r = 0…n, the right
 * polygon `levels[n−r][r]` for r = 0…n. Together they draw the same curve.
 */
export function splitBezier(points: readonly Point[], t: number): [Point[], Point[]] {
  checkPoints('splitBezier', 'points', points, 1);
  checkParameter('splitBezier', 't', t, 0, 1);
  const levels = deCasteljau(points, t);
  const n = points.length - 1;
  const left: Point[] = new Array<Point>(n + 1);
  const right: Point[] = new Array<Point>(n + 1);
  for (let r = 0; r <= n; r++) {
    left[r] = levels[r][0];
    right[r] = levels[n - r][r];
  }
  return [left, right];
}

/**
 * Control points of the hodograph (the derivative curve), `n·(P(i+1) − Pi)`, a
 * Bézier curve of degree n − 1. A single point (degree 0) gives one zero vector.
 */
export function bezierDerivative(points: readonly Point[]): Point[] {
  const dimension = checkPoints('bezierDerivative', 'points', points, 1);
  const n = points.length - 1;
  if (n === 0) return [new Array<number>(dimension).fill(0)];
  const result: Point[] = new Array<Point>(n);
  for (let i = 0; i < n; i++) {
    const a = points[i];
    const b = points[i + 1];
    const vector = new Array<number>(dimension);
    for (let d = 0; d < dimension; d++) vector[d] = n * (b[d] - a[d]);
    result[i] = vector;
  }
  return result;
}

/**
 * Degree elevation: the n + 2 control points of the same curve at degree n + 1,
 * `Q0 = P0`, `Qi = i/(n+1)·P(i−1) + (1 − i/(n+1))·Pi`, `Q(n+1) = Pn`.
 */
export function elevateDegree(points: readonly Point[]): Point[] {
  const dimension = checkPoints('elevateDegree', 'points', points, 1);
  const n = points.length - 1;
  const result: Point[] = new Array<Point>(n + 2);
  result[0] = points[0].slice();
  for (let i = 1; i <= n; i++) {
    const weight = i / (n + 1);
    const a = points[i - 1];
    const b = points[i];
    const point = new Array<number>(dimension);
    for (let d = 0; d < dimension; d++) point[d] = weight * a[d] + (1 - weight) * b[d];
    result[i] = point;
  }
  result[n + 1] = points[n].slice();
  return result;
}

/**
 * Samples the curve at the `segments + 1` parameters t = 0, 1/segments, …, 1
 * into one interleaved Float64Array `[x0, y0, x1, y1, …]` (dimension values per
 * sample), for drawing many points fast. Pass `out` to reuse a buffer. The
 * first and last samples are exactly P0 and Pn.
 */
export function sampleBezier(
  points: readonly Point[],
  segments: number,
  out?: Float64Array,
): Float64Array {
  const dimension = checkPoints('sampleBezier', 'points', points, 1);
  checkInteger('sampleBezier', 'segments', segments, 1);
  const length = (segments + 1) * dimension;
  const result = out && out.length >= length ? out : new Float64Array(length);
  const count = points.length;
  // Control points flattened coordinate by coordinate, so the loops read a typed array.
  const flat = new Float64Array(count * dimension);
  for (let i = 0; i < count; i++) {
    for (let d = 0; d < dimension; d++) flat[d * count + i] = points[i][d];
  }
  if (count === 4) {
    // The cubic unrolled: de Casteljau's six interpolations per coordinate.
    for (let d = 0; d < dimension; d++) {
      const p0 = flat[4 * d];
      const p1 = flat[4 * d + 1];
      const p2 = flat[4 * d + 2];
      const p3 = flat[4 * d + 3];
      for (let sample = 0, offset = d; sample <= segments; sample++, offset += dimension) {
        const t = sample / segments;
        const s = 1 - t;
        const a = s * p0 + t * p1;
        const b = s * p1 + t * p2;
        const c = s * p2 + t * p3;
        result[offset] = s * (s * a + t * b) + t * (s * b + t * c);
      }
    }
    return result;
  }
  const row = new Float64Array(count);
  for (let sample = 0; sample <= segments; sample++) {
    const t = sample / segments;
    const s = 1 - t;
    for (let d = 0; d < dimension; d++) {
      row.set(flat.subarray(d * count, (d + 1) * count));
      for (let r = count - 1; r > 0; r--) {
        for (let i = 0; i < r; i++) row[i] = s * row[i] + t * row[i + 1];
      }
      result[sample * dimension + d] = row[0];
    }
  }
  return result;
}
