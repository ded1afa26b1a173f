import { bezierDerivative } from './bezier';
import { checkPoints } from './checkPoints';
import { checkParameter } from './validate';
import type { Point } from './vec';

// Arc length ∫ |P′(t)| dt by adaptive Gauss–Legendre quadrature: five-point
// rules on an interval and on its two halves; where they disagree by more than
// the interval's share of the tolerance, bisect (Gander & Gautschi, "Adaptive
// quadrature — revisited", 2000).
//
// Adaptive rules can be fooled by a feature too small for the first samples to
// see (a curve that doubles back a little, where |P′| has a kink). So the
// interval is first cut where any coordinate turns (a root of that component of
// the hodograph, isolated by Bézier subdivision: no sign change in the control
// values means no root). Between cuts every coordinate is monotone and |P′| is
// smooth, vanishing at most at the ends.

const nodes = [-0.906179845938664, -0.5384693101056831, 0, 0.5384693101056831, 0.906179845938664];
const weights = [
  0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
  0.2369268850561891,
];
const maximumDepth = 40;
/** Bisections allowed in one call: far more than any smooth curve needs. */
const maximumIntervals = 20_000;

/**
 * The length of the Bézier curve from t = 0 to t = `upTo` ∈ [0, 1], to within
 * about `tolerance` times the length of the control polygon.
 */
export function bezierArcLength(points: readonly Point[], upTo = 1, tolerance = 1e-10): number {
  const caller = 'bezierArcLength';
  const dimension = checkPoints(caller, 'points', points, 1);
  checkParameter(caller, 'upTo', upTo, 0, 1);
  if (!(tolerance > 0) || !Number.isFinite(tolerance)) {
    throw new RangeError(
      `${caller}: tolerance = ${tolerance}; it must be a positive finite number.`,
    );
  }
  if (points.length === 1 || upTo === 0) return 0;
  // Length scales with the curve, L(kP) = k·L(P): integrate the curve scaled to
  // unit size, so neither 1e-300 (tolerances underflow and can never be met)
  // nor 1e300 (squares overflow) reaches the quadrature.
  let size = 0;
  for (const p of points) for (const value of p) size = Math.max(size, Math.abs(value));
  if (size === 0) return 0;
  const unit = points.map((p) => p.map((value) => value / size));
  return size * unitArcLength(unit, dimension, upTo, tolerance);
}

function unitArcLength(
  points: readonly Point[],
  dimension: number,
  upTo: number,
  tolerance: number,
): number {
  const hodograph = bezierDerivative(points);
  const count = hodograph.length;
  const flat = new Float64Array(count * dimension);
  for (let i = 0; i < count; i++) {
    for (let d = 0; d < dimension; d++) flat[d * count + i] = hodograph[i][d];
  }
  const row = new Float64Array(count);
  const speed = (t: number): number => {
    const s = 1 - t;
    let sum = 0;
    for (let d = 0; d < dimension; d++) {
      row.set(flat.subarray(d * count, (d + 1) * count));
      for (let r = count - 1; r > 0; r--) {
        for (let i = 0; i < r; i++) row[i] = s * row[i] + t * row[i + 1];
      }
      sum += row[0] * row[0];
    }
    return Math.sqrt(sum);
  };
  const rule = (a: number, b: number): number => {
    const half = (b - a) / 2;
    const middle = (a + b) / 2;
    let sum = 0;
    for (let k = 0; k < 5; k++) sum += weights[k] * speed(middle + half * nodes[k]);
    return sum * half;
  };
  let polygon = 0;
  for (let i = 1; i < points.length; i++) {
    let squared = 0;
    for (let d = 0; d < dimension; d++) squared += (points[i][d] - points[i - 1][d]) ** 2;
    polygon += Math.sqrt(squared);
  }
  // Each interval's share of the tolerance halves with its width, so without a
  // floor rounding noise alone could force bisection to full depth in every
  // branch (2^40 calls); and a budget bounds the work on any input.
  let budget = maximumIntervals;
  const adapt = (a: number, b: number, whole: number, allowed: number, depth: number): number => {
    const middle = (a + b) / 2;
    const left = rule(a, middle);
    const right = rule(middle, b);
    const estimate = left + right;
    const noise = 64 * Number.EPSILON * Math.abs(estimate);
    budget -= 1;
    if (
      Math.abs(estimate - whole) <= Math.max(allowed, noise) ||
      depth >= maximumDepth ||
      budget <= 0
    ) {
      return estimate;
    }
    return (
      adapt(a, middle, left, allowed / 2, depth + 1) +
      adapt(middle, b, right, allowed / 2, depth + 1)
    );
  };
  const allowed = tolerance * Math.max(polygon, Number.MIN_VALUE);
  const cuts = [0];
  for (const t of turningParameters(flat, count, dimension)) if (t > 0 && t < upTo) cuts.push(t);
  cuts.push(upTo);
  let length = 0;
  for (let k = 1; k < cuts.length; k++) {
    const [a, b] = [cuts[k - 1], cuts[k]];
    length += adapt(a, b, rule(a, b), (allowed * (b - a)) / upTo, 0);
  }
  return length;
}

/**
 * Sorted parameters in (0, 1) where some coordinate of the curve turns: roots
 * of the hodograph's components, whose control values are `flat[d·count + i]`.
 */
function turningParameters(flat: Float64Array, count: number, dimension: number): number[] {
  const roots: number[] = [];
  for (let d = 0; d < dimension; d++) {
    const values = Array.from(flat.subarray(d * count, (d + 1) * count));
    if (values.every((value) => value === 0)) continue; // this coordinate never moves
    // Rounding noise in a nearly constant coordinate could show sign changes
    // everywhere; the cuts only help accuracy, so cap the work instead.
    isolateRoots(values, 0, 1, 0, roots, { calls: 0, limit: 200 * count });
  }
  roots.sort((a, b) => a - b);
  return roots.filter((t, k) => k === 0 || t - roots[k - 1] > 1e-12);
}

/** Roots in [a, b] of the scalar Bézier polynomial with these control values. */
function isolateRoots(
  values: number[],
  a: number,
  b: number,
  depth: number,
  roots: number[],
  budget: { calls: number; limit: number },
): void {
  if (++budget.calls > budget.limit) return;
  let low = Infinity;
  let high = -Infinity;
  for (const value of values) {
    low = Math.min(low, value);
    high = Math.max(high, value);
  }
  // Variation diminishing: one sign throughout the control values, no root.
  if (low > 0 || high < 0) return;
  if (depth >= 40 || b - a < 1e-12) {
    roots.push((a + b) / 2);
    return;
  }
  // de Casteljau at 1/2 on the scalar values.
  const left: number[] = [];
  const right: number[] = [];
  let row = values.slice();
  while (row.length > 0) {
    left.push(row[0]);
    right.unshift(row[row.length - 1]);
    row = row.slice(1).map((value, i) => (row[i] + value) / 2);
  }
  const middle = (a + b) / 2;
  isolateRoots(left, a, middle, depth + 1, roots, budget);
  isolateRoots(right, middle, b, depth + 1, roots, budget);
}
