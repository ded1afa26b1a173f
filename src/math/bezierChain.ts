import { bezierDerivative, evaluateBezier } from './bezier';
import { checkPoints } from './checkPoints';
import { cubicInflections } from './cubicInflections';
import { checkInteger } from './validate';
import type { Point } from './vec';

// A piecewise Bézier curve written as one list of control points: piece i is
// points[i·n … (i+1)·n], so neighbouring pieces share their joint (the lecture's
// hand-built cubic spline, "joints at every third point").

/**
 * Splits `k·degree + 1` control points into the k Bézier pieces of the given
 * degree that share their end points. RangeError unless the count fits.
 */
export function bezierChainSegments(points: readonly Point[], degree: number): Point[][] {
  const caller = 'bezierChainSegments';
  checkInteger(caller, 'degree', degree, 1);
  checkPoints(caller, 'points', points, degree + 1);
  if ((points.length - 1) % degree !== 0) {
    throw new RangeError(
      `${caller}: ${points.length} points do not make pieces of degree ${degree}; a chain needs k·${degree} + 1 of them (${degree + 1}, ${2 * degree + 1}, …).`,
    );
  }
  const segments: Point[][] = [];
  for (let i = 0; i + degree < points.length; i += degree)
    segments.push(points.slice(i, i + degree + 1).map((p) => p.slice()));
  return segments;
}

/** Samples per degree when the sign changes of P′ × P″ are looked for (degree ≥ 4). */
const SCAN = 8;

/**
 * The parameters t in [0, 1] where a 2D Bézier curve of any degree inflects:
 * `P′(t) × P″(t)` changes sign. Cubics use the closed form of
 * `cubicInflections`; a line or a parabola never inflects; higher degrees scan
 * the numerator (a polynomial of degree 2n − 4) at 8·n steps and bisect each
 * change of sign to 1e-13, so two inflections closer than 1/(8n) can be missed.
 */
export function bezierInflections(points: readonly Point[]): number[] {
  checkPoints('bezierInflections', 'points', points, 1, 2);
  const n = points.length - 1;
  if (n < 3) return [];
  if (n === 3) return cubicInflections(points);
  const first = bezierDerivative(points);
  const second = bezierDerivative(first);
  const numerator = (t: number) => {
    const v = evaluateBezier(first, 2, t);
    const a = evaluateBezier(second, 2, t);
    return v[0] * a[1] - v[1] * a[0];
  };
  const steps = SCAN * n;
  const roots: number[] = [];
  // The last sample where the numerator was not zero: a straight stretch (all
  // zeros) has no change of sign, and a sign change across zeros is bisected whole.
  let [t0, f0] = [0, numerator(0)];
  for (let k = 1; k <= steps; k++) {
    const t1 = k / steps;
    const f1 = numerator(t1);
    if (f1 === 0) continue;
    if (f0 * f1 < 0) roots.push(bisect(numerator, t0, t1, f0));
    [t0, f0] = [t1, f1];
  }
  return roots;
}

function bisect(f: (t: number) => number, low: number, high: number, fLow: number): number {
  while (high - low > 1e-13) {
    const middle = (low + high) / 2;
    const value = f(middle);
    if (value === 0) return middle;
    if (Math.sign(value) === Math.sign(fLow)) [low, fLow] = [middle, value];
    else high = middle;
  }
  return (low + high) / 2;
}
