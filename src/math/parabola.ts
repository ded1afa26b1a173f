import { checkPoint } from './checkPoints';
import { checkOpenParameter, checkParameter } from './validate';
import type { Point } from './vec';

// Interpolating parabolas (lecture notes, "villages" example): the explicit
// y = a2 x² + a1 x + a0 through three points, and the parametric quadratic
// P(μ) = a2 μ² + a1 μ + a0 passing P0 at μ = 0, P1 at μ = mu and P2 at μ = 1.

/**
 * The parabola `y = a2·x² + a1·x + a0` through three 2D points, as `[a0, a1, a2]`.
 * RangeError when two x coincide (no function y(x) passes through both).
 */
export function parabolaThrough(p0: Point, p1: Point, p2: Point): [number, number, number] {
  checkPoint('parabolaThrough', 'p0', p0, 2);
  checkPoint('parabolaThrough', 'p1', p1, 2);
  checkPoint('parabolaThrough', 'p2', p2, 2);
  const [x0, y0] = p0;
  const [x1, y1] = p1;
  const [x2, y2] = p2;
  const pairs: [string, number, string, number][] = [
    ['p0', x0, 'p1', x1],
    ['p0', x0, 'p2', x2],
    ['p1', x1, 'p2', x2],
  ];
  for (const [name, x, otherName, other] of pairs) {
    if (x === other) {
      throw new RangeError(
        `parabolaThrough: ${name} and ${otherName} have the same x = ${x}; a parabola y(x) cannot pass through two points above one another, so the three x must differ.`,
      );
    }
  }
  // Newton's divided differences, then expanded: better conditioned than
  // solving the 3×3 Vandermonde system.
  const slope01 = (y1 - y0) / (x1 - x0);
  const slope12 = (y2 - y1) / (x2 - x1);
  const a2 = (slope12 - slope01) / (x2 - x0);
  const a1 = slope01 - a2 * (x0 + x1);
  const a0 = y0 - x0 * slope01 + a2 * x0 * x1;
  return [a0, a1, a2];
}

/**
 * The coefficient vectors `[a0, a1, a2]` of `P(μ) = a2·μ² + a1·μ + a0` with
 * `P(0) = p0`, `P(mu) = p1`, `P(1) = p2`. RangeError unless `0 < mu < 1`.
 */
export function parametricQuadratic(
  p0: Point,
  p1: Point,
  p2: Point,
  mu: number,
): [Point, Point, Point] {
  const dimension = checkQuadratic('parametricQuadratic', p0, p1, p2, mu);
  // From a1 + a2 = p2 − p0 and a1 mu + a2 mu² = p1 − p0.
  const a1 = new Array<number>(dimension);
  const a2 = new Array<number>(dimension);
  for (let d = 0; d < dimension; d++) {
    a2[d] = (p1[d] - p0[d] - mu * (p2[d] - p0[d])) / (mu * (mu - 1));
    a1[d] = p2[d] - p0[d] - a2[d];
  }
  return [p0.slice(), a1, a2];
}

/**
 * The parametric quadratic through p0 (μ = 0), p1 (μ = mu), p2 (μ = 1),
 * evaluated at μ = t ∈ [0, 1]. Uses the Lagrange form, so it is exact at the
 * three points whatever their size.
 */
export function parametricQuadraticPoint(
  p0: Point,
  p1: Point,
  p2: Point,
  mu: number,
  t: number,
): Point {
  const dimension = checkQuadratic('parametricQuadraticPoint', p0, p1, p2, mu);
  checkParameter('parametricQuadraticPoint', 't', t, 0, 1);
  const w0 = ((t - mu) * (t - 1)) / mu;
  const w1 = (t * (t - 1)) / (mu * (mu - 1));
  const w2 = (t * (t - mu)) / (1 - mu);
  const result = new Array<number>(dimension);
  for (let d = 0; d < dimension; d++) result[d] = w0 * p0[d] + w1 * p1[d] + w2 * p2[d];
  return result;
}

function checkQuadratic(caller: string, p0: Point, p1: Point, p2: Point, mu: number): number {
  const dimension = checkPoint(caller, 'p0', p0);
  checkPoint(caller, 'p1', p1, dimension);
  checkPoint(caller, 'p2', p2, dimension);
  checkOpenParameter(caller, 'mu', mu, 0, 1);
  return dimension;
}
