import { sampleBezier } from './bezier';
import { checkPoints } from './checkPoints';
import { checkInteger } from './validate';
import type { Point } from './vec';

/** Where two curves are farthest apart at equal parameters, and how far. */
export interface Deviation {
  /** The parameter (or, for samples, the sample index) of the largest distance. */
  at: number;
  distance: number;
}

/**
 * The largest distance `|A(t) − B(t)|` between two Bézier curves (of any
 * degrees, same dimension) over the `samples + 1` parameters t = k / samples:
 * how far a change moved the curve, or how well two forms of a curve agree.
 */
export function bezierDeviation(
  a: readonly Point[],
  b: readonly Point[],
  samples = 1000,
): Deviation {
  const dimension = checkPoints('bezierDeviation', 'a', a, 1);
  checkPoints('bezierDeviation', 'b', b, 1, dimension);
  checkInteger('bezierDeviation', 'samples', samples, 1);
  const largest = sampledDeviation(sampleBezier(a, samples), sampleBezier(b, samples), dimension);
  return { at: largest.at / samples, distance: largest.distance };
}

/**
 * The largest distance between corresponding samples of two interleaved
 * sample arrays (`[x0, y0, x1, y1, …]` for dimension 2) of equal length;
 * `at` is the index of the sample.
 */
export function sampledDeviation(
  a: ArrayLike<number>,
  b: ArrayLike<number>,
  dimension = 2,
): Deviation {
  checkInteger('sampledDeviation', 'dimension', dimension, 1);
  if (a.length !== b.length || a.length % dimension !== 0) {
    throw new RangeError(
      `sampledDeviation: a has ${a.length} values and b has ${b.length}; both must hold the same number of ${dimension}D samples.`,
    );
  }
  let best = { at: 0, distance: 0 };
  for (let k = 0; k < a.length; k += dimension) {
    let sum = 0;
    for (let d = 0; d < dimension; d++) sum += (a[k + d] - b[k + d]) ** 2;
    const distance = Math.sqrt(sum);
    if (!Number.isFinite(distance)) {
      throw new RangeError(`sampledDeviation: sample ${k / dimension} is not finite.`);
    }
    if (distance > best.distance) best = { at: k / dimension, distance };
  }
  return best;
}
