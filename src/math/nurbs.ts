import { checkKnots, fillBasis, knotSpan } from './bsplineBasis';
import { checkPoint, checkPoints } from './checkPoints';
import { checkNumber, checkNumbers, checkParameter, checkSameLength } from './validate';
import type { Point } from './vec';

// Non-uniform rational B-splines (Piegl & Tiller, The NURBS Book, eq. 4.2):
// C(t) = Σ wi Pi N(i,p)(t) / Σ wi N(i,p)(t). Only the p + 1 basis functions of
// the knot span holding t are non-zero, so a point costs O(p²), not O(n).

/**
 * The rational B-spline point `Σ wᵢ Pᵢ Nᵢ(t) / Σ wᵢ Nᵢ(t)` at t ∈ [knots[0],
 * knots[last]]; needs `knots.length = points.length + degree + 1` and weights
 * ≥ 0, not all zero where t is.
 */
export function nurbsPoint(
  points: readonly Point[],
  weights: readonly number[],
  knots: readonly number[],
  degree: number,
  t: number,
): Point {
  const caller = 'nurbsPoint';
  const dimension = checkPoints(caller, 'points', points, 1);
  checkNumbers(caller, 'weights', weights, 1);
  checkSameLength(caller, 'weights', weights, 'points', points);
  for (let i = 0; i < weights.length; i++) {
    if (weights[i] < 0) {
      throw new RangeError(
        `${caller}: weights[${i}] = ${weights[i]} is negative; weights must be ≥ 0.`,
      );
    }
  }
  checkKnots(caller, knots, degree);
  if (knots.length !== points.length + degree + 1) {
    throw new RangeError(
      `${caller}: knots has ${knots.length} entries but ${points.length} points of degree ${degree} need points + degree + 1 = ${points.length + degree + 1}.`,
    );
  }
  checkParameter(caller, 't', t, knots[0], knots[knots.length - 1]);
  const span = knotSpan(caller, knots, t);
  const basis = new Float64Array(degree + 1);
  fillBasis(knots, degree, span, t, basis);
  const result = new Array<number>(dimension).fill(0);
  let denominator = 0;
  for (let o = 0; o <= degree; o++) {
    const i = span - degree + o;
    if (i < 0 || i >= points.length || basis[o] === 0) continue;
    const weight = weights[i] * basis[o];
    denominator += weight;
    for (let d = 0; d < dimension; d++) result[d] += weight * points[i][d];
  }
  if (!(denominator > 0)) {
    throw new RangeError(
      `${caller}: every control point acting at t = ${t} has weight 0, so the curve is undefined there; give one of them a positive weight.`,
    );
  }
  for (let d = 0; d < dimension; d++) result[d] /= denominator;
  return result;
}

/** The data of a NURBS curve: control points, weights, knot vector and degree. */
export interface NurbsCurve {
  readonly points: Point[];
  readonly weights: number[];
  readonly knots: number[];
  readonly degree: number;
}

/**
 * The exact circle as a quadratic NURBS (The NURBS Book, §7.5): 9 control
 * points on the square around it, weights 1 at the edge midpoints and √2/2 at
 * the corners, knots `[0,0,0, ¼,¼, ½,½, ¾,¾, 1,1,1]`.
 */
export function nurbsCircle(centre: Point = [0, 0], radius = 1): NurbsCurve {
  checkPoint('nurbsCircle', 'centre', centre, 2);
  if (!(checkNumber('nurbsCircle', 'radius', radius) > 0)) {
    throw new RangeError(`nurbsCircle: radius = ${radius}; it must be positive.`);
  }
  const [x, y] = centre;
  const r = radius;
  const corner = Math.SQRT1_2;
  return {
    points: [
      [x + r, y],
      [x + r, y + r],
      [x, y + r],
      [x - r, y + r],
      [x - r, y],
      [x - r, y - r],
      [x, y - r],
      [x + r, y - r],
      [x + r, y],
    ],
    weights: [1, corner, 1, corner, 1, corner, 1, corner, 1],
    knots: [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
    degree: 2,
  };
}
