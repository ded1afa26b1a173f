import { bezierDerivative, bezierPoint } from './bezier';
import { checkPoints } from './checkPoints';
import { chordDeviation } from './chordDeviation';
import { checkInteger, checkNumber } from './validate';
import type { Point } from './vec';

// How many uniform pieces (parameters k / n) a Bézier curve needs for the
// chords drawn for them to stay within a tolerance of it: an estimate from
// the curvature, then a search from there that measures a few counts with
// chordDeviation.

/** The parameters k / count, k = 0 … count: uniform sampling. */
export function uniformParameters(count: number): number[] {
  checkInteger('uniformParameters', 'count', count, 1);
  return Array.from({ length: count + 1 }, (_, k) => k / count);
}

/**
 * The uniform count the curvature asks for: a piece of parameter length h
 * strays about h²/8 · ‖P″⊥‖ from its chord (the second-order Taylor term; P″⊥
 * is the part of P″ across the tangent, as speeding up along a straight line
 * strays nowhere), so n uniform segments stray about max‖P″⊥‖ / (8n²), and
 * n ≈ √(max‖P″⊥‖ / (8·tolerance)), rounded up and at least 1. P′ and P″ are
 * sampled at 65 parameters of the hodographs. An estimate to start a search
 * from, not a guarantee.
 */
export function uniformCountEstimate(points: readonly Point[], tolerance: number): number {
  const caller = 'uniformCountEstimate';
  checkPoints(caller, 'points', points, 1);
  checkPositive(caller, tolerance);
  if (points.length < 3) return 1;
  const first = bezierDerivative(points);
  const second = bezierDerivative(first);
  let largest = 0;
  for (let i = 0; i <= 64; i++) {
    const velocity = bezierPoint(first, i / 64);
    const acceleration = bezierPoint(second, i / 64);
    let speed = 0;
    let along = 0;
    let size = 0;
    for (let d = 0; d < velocity.length; d++) {
      speed += velocity[d] ** 2;
      along += velocity[d] * acceleration[d];
      size += acceleration[d] ** 2;
    }
    // ‖P″⊥‖² = ‖P″‖² − (P′·P″)²/‖P′‖²; where the curve stops, P″ is its tangent.
    if (speed === 0) continue;
    const across = size - (along * along) / speed;
    largest = Math.max(largest, Math.sqrt(Math.max(0, across)));
  }
  return Math.max(1, Math.ceil(Math.sqrt(largest / (8 * tolerance))));
}

/**
 * A uniform count n ≤ `maximum` (parameters k / n) whose chords stay within
 * `tolerance` of the curve while those of n − 1 do not (or n = 1), found from
 * uniformCountEstimate by steps doubling away from it, then bisection: a few
 * chordDeviation calls, not one per count. Where the deviation falls as n
 * grows (it need not everywhere) this is the fewest. `maximum` + 1 when
 * `maximum` segments do not reach the tolerance either: more than `maximum`.
 */
export function uniformCountWithin(
  points: readonly Point[],
  tolerance: number,
  maximum = 512,
): number {
  checkNumber('uniformCountWithin', 'tolerance', tolerance);
  checkInteger('uniformCountWithin', 'maximum', maximum, 1);
  const within = (n: number) => chordDeviation(points, uniformParameters(n)).distance <= tolerance;
  // A tolerance of 0 (a straight curve's own gap) is only met by a straight piece.
  const guess =
    tolerance > 0 ? Math.min(maximum, uniformCountEstimate(points, tolerance)) : maximum;
  // `pass` reaches the tolerance, `fail` does not (0 segments never do).
  let pass: number;
  let fail = 0;
  if (within(guess)) {
    pass = guess;
    for (let step = 1; pass - step >= 1; step *= 2) {
      if (!within(pass - step)) {
        fail = pass - step;
        break;
      }
      pass -= step;
    }
  } else {
    fail = guess;
    for (let step = 1; ; step *= 2) {
      if (fail === maximum) return maximum + 1;
      const n = Math.min(maximum, fail + step);
      if (within(n)) {
        pass = n;
        break;
      }
      fail = n;
    }
  }
  while (pass - fail > 1) {
    const middle = Math.floor((pass + fail) / 2);
    if (within(middle)) pass = middle;
    else fail = middle;
  }
  return pass;
}

function checkPositive(caller: string, tolerance: number): void {
  checkNumber(caller, 'tolerance', tolerance);
  if (!(tolerance > 0)) {
    throw new RangeError(`${caller}: tolerance = ${tolerance}; it must be a positive distance.`);
  }
}
