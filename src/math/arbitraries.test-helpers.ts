import fc from 'fast-check';
import type { Point } from './vec';

// Shared fast-check generators for the maths tests.

/**
 * A finite coordinate of moderate size. −0 becomes +0 so that exact comparisons
 * (toEqual distinguishes them) test values, not signs of zero.
 */
export const coordinate = fc
  .double({ min: -1000, max: 1000, noNaN: true, noDefaultInfinity: true })
  .map((value) => (value === 0 ? 0 : value));

/** A point with the given dimension. */
export function point(dimension: number): fc.Arbitrary<Point> {
  return fc.array(coordinate, { minLength: dimension, maxLength: dimension });
}

/** Between `minimum` and `maximum` points, all 2D or all 3D. */
export function polygon(minimum: number, maximum: number): fc.Arbitrary<Point[]> {
  return fc
    .constantFrom(2, 3)
    .chain((dimension) => fc.array(point(dimension), { minLength: minimum, maxLength: maximum }));
}

/** Between `minimum` and `maximum` 2D points. */
export function polygon2D(minimum: number, maximum: number): fc.Arbitrary<Point[]> {
  return fc.array(point(2), { minLength: minimum, maxLength: maximum });
}

/** A parameter in [0, 1]. */
export const unitParameter = fc.double({ min: 0, max: 1, noNaN: true });

/** Asserts two points agree coordinate by coordinate within `tolerance`·max(1, |a|). */
export function expectClose(actual: Point, expected: Point, tolerance = 1e-9): void {
  if (actual.length !== expected.length) {
    throw new Error(`dimension ${actual.length} ≠ ${expected.length}`);
  }
  for (let d = 0; d < actual.length; d++) {
    const scale = Math.max(1, Math.abs(expected[d]));
    if (!(Math.abs(actual[d] - expected[d]) <= tolerance * scale)) {
      throw new Error(
        `coordinate ${d}: ${actual[d]} ≠ ${expected[d]} (±${tolerance * scale}) in [${actual.join(', ')}] vs [${expected.join(', ')}]`,
      );
    }
  }
}

/** The numbers with −0 turned into +0, for exact comparisons where the sign of zero is noise. */
export function plain(values: readonly number[]): number[] {
  return values.map((value) => value + 0);
}
