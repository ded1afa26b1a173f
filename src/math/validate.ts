import type { Point } from './vec';

// Input checks shared by every maths function. Each throws a RangeError whose
// message names the function, the argument, what was wrong and what is allowed,
// so a student who drags a point somewhere odd reads a sentence, not NaN.
// They are single passes over the input with no allocation: they run on every
// call, inside animation frames.

function describe(value: unknown): string {
  if (typeof value === 'number') return String(value);
  if (value === null) return 'null';
  if (value === undefined) return 'undefined';
  if (Array.isArray(value)) return 'an array';
  return `a ${typeof value}`;
}

/** Throws unless `value` is a finite number; returns it. */
export function checkNumber(caller: string, name: string, value: number): number {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new RangeError(`${caller}: ${name} is ${describe(value)}; it must be a finite number.`);
  }
  return value;
}

/** Throws unless `value` is an integer ≥ `minimum`; returns it. */
export function checkInteger(caller: string, name: string, value: number, minimum: number): number {
  if (!Number.isSafeInteger(value) || value < minimum) {
    throw new RangeError(
      `${caller}: ${name} is ${describe(value)}; it must be a whole number ≥ ${minimum}.`,
    );
  }
  return value;
}

/** Throws unless `low ≤ value ≤ high` (a closed range); returns `value`. */
export function checkParameter(
  caller: string,
  name: string,
  value: number,
  low: number,
  high: number,
): number {
  if (typeof value !== 'number' || !(value >= low && value <= high)) {
    throw new RangeError(
      `${caller}: ${name} = ${describe(value)} is outside the allowed range [${low}, ${high}].`,
    );
  }
  return value;
}

/** Throws unless `low < value < high` (an open range); returns `value`. */
export function checkOpenParameter(
  caller: string,
  name: string,
  value: number,
  low: number,
  high: number,
): number {
  if (typeof value !== 'number' || !(value > low && value < high)) {
    throw new RangeError(
      `${caller}: ${name} = ${describe(value)} is outside the allowed range (${low}, ${high}), ends excluded.`,
    );
  }
  return value;
}

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

/** Throws unless `values` is an array of at least `minimum` finite numbers. */
export function checkNumbers(
  caller: string,
  name: string,
  values: ArrayLike<number>,
  minimum: number,
): void {
  if (values === null || typeof values !== 'object' || typeof values.length !== 'number') {
    throw new RangeError(
      `${caller}: ${name} is ${describe(values)}; it must be an array of numbers.`,
    );
  }
  if (values.length < minimum) {
    throw new RangeError(
      `${caller}: ${name} needs at least ${minimum} value${minimum === 1 ? '' : 's'}, but got ${values.length}.`,
    );
  }
  for (let i = 0; i < values.length; i++) {
    const value = values[i];
    if (typeof value !== 'number' || !Number.isFinite(value)) {
      throw new RangeError(
        `${caller}: ${name}[${i}] is ${describe(value)}; every value must be a finite number.`,
      );
    }
  }
}

/**
 * checkNumbers and a copy into a new Float64Array in the same pass, for the
 * solvers that work on typed arrays. Only a failing call goes on to
 * checkNumbers, which finds the first bad value and throws it in words.
 */
export function copyCheckedNumbers(
  caller: string,
  name: string,
  values: ArrayLike<number>,
  minimum: number,
): Float64Array {
  if (values === null || typeof values !== 'object' || !(values.length >= minimum)) {
    checkNumbers(caller, name, values, minimum);
  }
  const n = values.length;
  const copy = new Float64Array(n);
  // v − v is 0 exactly when v is finite, so one sum tests every value.
  let finite = 0;
  let i = 0;
  for (; i < n; i++) {
    const value = values[i];
    if (typeof value !== 'number') break;
    copy[i] = value;
    finite += value - value;
  }
  if (i < n || finite !== 0) checkNumbers(caller, name, values, minimum);
  return copy;
}

/** Throws unless the two arrays have the same length. */
export function checkSameLength(
  caller: string,
  name: string,
  values: ArrayLike<unknown>,
  otherName: string,
  other: ArrayLike<unknown>,
): void {
  if (values.length !== other.length) {
    throw new RangeError(
      `${caller}: ${name} has ${values.length} entries but ${otherName} has ${other.length}; they must match one for one.`,
    );
  }
}

/**
 * Throws unless `coordinates` is a non-empty array of equally long typed
 * arrays (`[xs, ys]`, `[xs, ys, zs]`) with at least `minimum` points; returns
 * the point count. Finiteness is left to the caller, which can fold it into
 * its own pass (see `nonFiniteError`).
 */
export function checkCoordinateArrays(
  caller: string,
  coordinates: readonly Float64Array[],
  minimum: number,
): number {
  if (!Array.isArray(coordinates) || coordinates.length < 1) {
    throw new RangeError(
      `${caller}: coordinates must be an array of Float64Arrays, one per coordinate ([xs, ys]).`,
    );
  }
  const n = coordinates[0].length;
  for (let c = 0; c < coordinates.length; c++) {
    if (!(coordinates[c] instanceof Float64Array)) {
      throw new RangeError(`${caller}: coordinates[${c}] is not a Float64Array.`);
    }
    if (coordinates[c].length !== n) {
      throw new RangeError(
        `${caller}: coordinates[${c}] has ${coordinates[c].length} values but coordinates[0] has ${n}; each point needs every coordinate.`,
      );
    }
  }
  if (n < minimum) {
    throw new RangeError(
      `${caller}: needs at least ${minimum} point${minimum === 1 ? '' : 's'}, but got ${n}.`,
    );
  }
  return n;
}

/**
 * The RangeError for a batch whose result came out non-finite: names the first
 * NaN or ±Infinity in `values`, or says the values overflowed. Only called on
 * the failing path, so batch functions need no separate checking pass.
 */
export function nonFiniteError(
  caller: string,
  name: string,
  values: ArrayLike<number>,
): RangeError {
  for (let i = 0; i < values.length; i++) {
    if (!Number.isFinite(values[i])) {
      return new RangeError(
        `${caller}: ${name}[${i}] is ${values[i]}; every value must be a finite number.`,
      );
    }
  }
  return new RangeError(
    `${caller}: ${name} holds values so large that the result overflows; scale them down.`,
  );
}
