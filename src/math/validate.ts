// Input checks shared by every maths function. Each throws a RangeError whose
// message names the function, the argument, what was wrong and what is allowed,
// so a student who drags a point somewhere odd reads a sentence, not NaN.
// They are single passes over the input with no allocation: they run on every
// call, inside animation frames. Here are the checks of numbers, one or many;
// points are checked in checkPoints.ts, a batch's typed arrays in
// checkCoordinateArrays.ts.

/** A value as a message names it: a number as itself, anything else by its kind. */
export function describe(value: unknown): string {
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
