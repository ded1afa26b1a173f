/**
 * A point or vector of any dimension: `[x, y]` or `[x, y, z]`.
 * Functions never mutate one and always return fresh arrays.
 */
export type Point = readonly number[];

/** `a + b`, coordinate by coordinate. */
export function add(a: Point, b: Point): Point {
  const result = new Array<number>(a.length);
  for (let d = 0; d < a.length; d++) result[d] = a[d] + b[d];
  return result;
}

/** `a − b`, coordinate by coordinate. */
export function subtract(a: Point, b: Point): Point {
  const result = new Array<number>(a.length);
  for (let d = 0; d < a.length; d++) result[d] = a[d] - b[d];
  return result;
}

/** `factor · a`. */
export function scale(a: Point, factor: number): Point {
  const result = new Array<number>(a.length);
  for (let d = 0; d < a.length; d++) result[d] = factor * a[d];
  return result;
}

/**
 * `(1 − t)·a + t·b`, the point a fraction t of the way from a to b.
 * Written as a convex combination rather than `a + t(b − a)` so that it is exact
 * at t = 0 and t = 1 and never subtracts two large nearby coordinates.
 */
export function pointBetween(a: Point, b: Point, t: number): Point {
  const result = new Array<number>(a.length);
  const s = 1 - t;
  for (let d = 0; d < a.length; d++) result[d] = s * a[d] + t * b[d];
  return result;
}

/** The dot product `a · b`. */
export function dot(a: Point, b: Point): number {
  let sum = 0;
  for (let d = 0; d < a.length; d++) sum += a[d] * b[d];
  return sum;
}

/** The Euclidean length `|a|`. */
export function norm(a: Point): number {
  return Math.sqrt(dot(a, a));
}

/** The Euclidean distance `|a − b|`. */
export function distance(a: Point, b: Point): number {
  let sum = 0;
  for (let d = 0; d < a.length; d++) {
    const difference = a[d] - b[d];
    sum += difference * difference;
  }
  return Math.sqrt(sum);
}

/** The cross product `a × b` of two 3D vectors. */
export function cross(a: Point, b: Point): Point {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

/** The zero vector with `dimension` coordinates. */
export function zeroVector(dimension: number): Point {
  return new Array<number>(dimension).fill(0);
}
