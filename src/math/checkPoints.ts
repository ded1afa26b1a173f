import { describe } from './validate';
import type { Point } from './vec';

// The checks that points are points: arrays of finite coordinates, all of one
// dimension. As in validate.ts, bad input throws a RangeError that says what
// was wrong, and good input costs one pass with no strings built.

/**
 * Throws unless `point` is an array of finite numbers with at least one
 * coordinate, and exactly `dimension` of them when `dimension` is given.
 * Returns the dimension.
 */
export function checkPoint(caller: string, name: string, point: Point, dimension?: number): number {
  if (!Array.isArray(point)) {
    throw new RangeError(
      `${caller}: ${name} is ${describe(point)}; a point must be an array of coordinates such as [x, y].`,
    );
  }
  const length = point.length;
  if (dimension === undefined) {
    if (length === 0) {
      throw new RangeError(`${caller}: ${name} has no coordinates; a point needs at least one.`);
    }
  } else if (length !== dimension) {
    throw new RangeError(
      `${caller}: ${name} has ${length} coordinates but ${dimension} are expected; every point must have the same dimension.`,
    );
  }
  for (let d = 0; d < length; d++) {
    const coordinate = point[d];
    if (typeof coordinate !== 'number' || !Number.isFinite(coordinate)) {
      throw new RangeError(
        `${caller}: ${name}[${d}] is ${describe(coordinate)}; every coordinate must be a finite number.`,
      );
    }
  }
  return length;
}

/**
 * Throws unless `points` is an array of at least `minimum` points, all with the
 * same dimension (that of `dimension` when given) and finite coordinates.
 * Returns the dimension (0 for an empty array when `minimum` is 0).
 */
export function checkPoints(
  caller: string,
  name: string,
  points: readonly Point[],
  minimum: number,
  dimension?: number,
): number {
  // The common case is one tight loop with no strings built; only a failure
  // goes through the slow path that words the message.
  if (!Array.isArray(points) || points.length < minimum) {
    return explainPoints(caller, name, points, minimum, dimension);
  }
  if (points.length === 0) return dimension ?? 0;
  const first = points[0];
  const size = Array.isArray(first) ? first.length : 0;
  if (size === 0 || (dimension !== undefined && size !== dimension)) {
    return explainPoints(caller, name, points, minimum, dimension);
  }
  for (let i = 0; i < points.length; i++) {
    const point = points[i];
    if (!Array.isArray(point) || point.length !== size) {
      return explainPoints(caller, name, points, minimum, dimension);
    }
    for (let d = 0; d < size; d++) {
      const coordinate = point[d];
      if (typeof coordinate !== 'number' || !Number.isFinite(coordinate)) {
        return explainPoints(caller, name, points, minimum, dimension);
      }
    }
  }
  return size;
}

/** The slow path of checkPoints: finds the first problem and throws it in words. */
function explainPoints(
  caller: string,
  name: string,
  points: readonly Point[],
  minimum: number,
  dimension?: number,
): number {
  if (!Array.isArray(points)) {
    throw new RangeError(
      `${caller}: ${name} is ${describe(points)}; it must be an array of points.`,
    );
  }
  if (points.length < minimum) {
    throw new RangeError(
      `${caller}: ${name} needs at least ${minimum} point${minimum === 1 ? '' : 's'}, but got ${points.length}.`,
    );
  }
  const first = checkPoint(caller, `${name}[0]`, points[0], dimension);
  for (let i = 1; i < points.length; i++) {
    const point = points[i];
    if (Array.isArray(point) && point.length !== first) {
      throw new RangeError(
        `${caller}: ${name}[${i}] has ${point.length} coordinates but ${name}[0] has ${first}; every point must have the same dimension.`,
      );
    }
    checkPoint(caller, `${name}[${i}]`, point, first);
  }
  return first;
}
