import { bezierArcLength } from './arcLength';
import { checkPoints } from './checkPoints';
import { bezierTangent } from './curvature';
import { checkNumber } from './validate';
import type { Point } from './vec';

// Reparametrising by arc length: s(t) = ∫₀ᵗ |P′(u)| du never decreases, so
// t(s) is found by Newton's method on s(t) − s (its derivative is the speed
// |P′(t)|), kept inside a bracket that bisection shrinks whenever a Newton
// step would leave it (Press et al., Numerical Recipes, §9.4, rtsafe).

/** One row of an arc length table: the parameter and the length up to it. */
export interface ArcLengthRow {
  readonly t: number;
  readonly s: number;
}

/**
 * The arc length table of a Bézier curve: `count + 1` rows at t = i/count,
 * each with s(t), the length of the curve from t = 0.
 */
export function bezierArcLengthTable(points: readonly Point[], count: number): ArcLengthRow[] {
  checkPoints('bezierArcLengthTable', 'points', points, 1);
  if (!Number.isInteger(count) || count < 1) {
    throw new RangeError(`bezierArcLengthTable: count = ${count}; it must be a whole number ≥ 1.`);
  }
  const rows: ArcLengthRow[] = [];
  for (let i = 0; i <= count; i++) {
    const t = i / count;
    rows.push({ t, s: bezierArcLength(points, t) });
  }
  return rows;
}

/**
 * The parameter t at which the curve has length `s` from its start (0 ≤ s ≤
 * the whole length), to within `tolerance` times the whole length. Where the
 * curve stands still (zero speed on an interval) the smallest such t is not
 * sought: any t with s(t) = s is returned.
 */
export function bezierParameterAtLength(
  points: readonly Point[],
  s: number,
  tolerance = 1e-12,
): number {
  const caller = 'bezierParameterAtLength';
  checkPoints(caller, 'points', points, 1);
  checkNumber(caller, 's', s);
  const total = bezierArcLength(points, 1);
  if (s < 0 || s > total * (1 + 1e-12)) {
    throw new RangeError(
      `${caller}: s = ${s}; it must lie between 0 and the curve's length ${total}.`,
    );
  }
  if (total === 0 || s === 0) return 0;
  if (s >= total) return 1;
  let [low, high] = [0, 1];
  let t = s / total;
  for (let iteration = 0; iteration < 100; iteration++) {
    const error = bezierArcLength(points, t) - s;
    if (Math.abs(error) <= tolerance * total) return t;
    if (error < 0) low = t;
    else high = t;
    const speed = Math.hypot(...bezierTangent(points, t));
    const newton = t - error / speed;
    t = speed > 0 && newton > low && newton < high ? newton : (low + high) / 2;
    if (high - low <= Number.EPSILON) return t;
  }
  return t;
}
