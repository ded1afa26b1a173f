// The checks of the batch functions, whose points come as one Float64Array
// per coordinate ([xs, ys]): the arrays' shape is checked before the batch
// runs, and finiteness rides along in the batch's own pass, named in words
// only when its result came out non-finite.

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
