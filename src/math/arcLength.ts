import { bezierDerivative } from './bezier';
import { checkParameter, checkPoints } from './validate';
import type { Point } from './vec';

// Arc length ∫ |P′(t)| dt by adaptive Gauss–Legendre quadrature: five-point
// rules on an interval and on its two halves; where they disagree by more than
// the interval's share of the tolerance, bisect (Gander & Gautschi, "Adaptive
// quadrature — revisited", 2000). |P′| is smooth except near cusps, where the
// bisection concentrates.

const nodes = [-0.906179845938664, -0.5384693101056831, 0, 0.5384693101056831, 0.906179845938664];
const weights = [
  0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
  0.2369268850561891,
];
const maximumDepth = 40;

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
  const adapt = (a: number, b: number, whole: number, allowed: number, depth: number): number => {
    const middle = (a + b) / 2;
    const left = rule(a, middle);
    const right = rule(middle, b);
    if (Math.abs(left + right - whole) <= allowed || depth >= maximumDepth) return left + right;
    return (
      adapt(a, middle, left, allowed / 2, depth + 1) +
      adapt(middle, b, right, allowed / 2, depth + 1)
    );
  };
  return adapt(0, upTo, rule(0, upTo), tolerance * Math.max(polygon, Number.MIN_VALUE), 0);
}
