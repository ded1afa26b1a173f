import { checkPoint } from './checkPoints';
import { checkInteger, checkParameter } from './validate';
import type { Point } from './vec';

// Cubic Hermite interpolation: the cubic x(μ) = a0 + a1 μ + a2 μ² + a3 μ³
// with x(0) = x0, x(1) = x1, x′(0) = x0′, x′(1) = x1′ gives
// a0 = x0, a1 = x0′, a2 = −3x0 + 3x1 − 2x0′ − x1′, a3 = 2x0 − 2x1 + x0′ + x1′.
// The lecture notes (equations 6 and 7) order the data (Pi, P′i, Pi+1, P′i+1):
// HERMITE_LECTURE_MATRIX and HERMITE_LECTURE_INVERSE. hermiteMatrix orders it
// (x0, x1, x0′, x1′), as the continuation notes do, so it is not equation 7.

/**
 * Equation 6 of the lecture notes as a matrix: row k is condition k on
 * `[a0, a1, a2, a3]` for the data in the lecture's order `(Pi, P′i, Pi+1, P′i+1)`:
 * `Pi = a0`, `P′i = a1`, `Pi+1 = a0 + a1 + a2 + a3`, `P′i+1 = a1 + 2a2 + 3a3`.
 */
export const HERMITE_LECTURE_MATRIX: readonly (readonly number[])[] = [
  [1, 0, 0, 0],
  [0, 1, 0, 0],
  [1, 1, 1, 1],
  [0, 1, 2, 3],
];

/**
 * Equation 7 of the lecture notes: the inverse of `HERMITE_LECTURE_MATRIX`, so
 * `[a0, a1, a2, a3] = HERMITE_LECTURE_INVERSE · [Pi, P′i, Pi+1, P′i+1]`.
 */
export const HERMITE_LECTURE_INVERSE: readonly (readonly number[])[] = [
  [1, 0, 0, 0],
  [0, 1, 0, 0],
  [-3, -2, 3, -1],
  [2, 1, -2, 1],
];

/**
 * `[a0, a1, a2, a3]` of `P(μ) = a3μ³ + a2μ² + a1μ + a0` from the data in the
 * lecture's order (point, gradient, next point, next gradient): equation 7,
 * `HERMITE_LECTURE_INVERSE` times the data, row by row.
 */
export function hermiteLectureCoefficients(
  point: Point,
  gradient: Point,
  nextPoint: Point,
  nextGradient: Point,
): [Point, Point, Point, Point] {
  const data = [point, gradient, nextPoint, nextGradient];
  const dimension = checkHermite(
    'hermiteLectureCoefficients',
    point,
    gradient,
    nextPoint,
    nextGradient,
  );
  const [a0, a1, a2, a3] = HERMITE_LECTURE_INVERSE.map((row) => {
    const coefficient = new Array<number>(dimension).fill(0);
    row.forEach((entry, k) => {
      for (let d = 0; d < dimension; d++) coefficient[d] += entry * data[k][d];
    });
    return coefficient;
  });
  return [a0, a1, a2, a3];
}

/**
 * The inverse of `[[1,0,0,0],[1,1,1,1],[0,1,0,0],[0,1,2,3]]`: row k gives `ak`
 * as a combination of `[x0, x1, x0′, x1′]`. That is the continuation notes'
 * order of the data, and their inverse with its rows reversed (they write
 * x(t) = at³ + bt² + ct + d, so their a, b, c, d are a3, a2, a1, a0). Equation 7
 * of the lecture notes orders the data otherwise: `HERMITE_LECTURE_INVERSE`.
 */
export function hermiteMatrix(): number[][] {
  return [
    [1, 0, 0, 0],
    [0, 0, 1, 0],
    [-3, 3, -2, -1],
    [2, -2, 1, 1],
  ];
}

/**
 * `[H0, H1, H2, H3]` weighting `x0, x1, x0′, x1′` at t ∈ [0, 1]:
 * `2t³−3t²+1`, `−2t³+3t²`, `t³−2t²+t`, `t³−t²`.
 */
export function hermiteBasis(t: number): [number, number, number, number] {
  checkParameter('hermiteBasis', 't', t, 0, 1);
  return hermiteWeights(t);
}

/** hermiteBasis without checks, for callers that have already validated t. */
export function hermiteWeights(t: number): [number, number, number, number] {
  // Factored forms of the same polynomials: exact at t = 0 and 1, and H0 + H1
  // stays 1 to rounding, so large coordinates keep their precision.
  const s = 1 - t;
  return [s * s * (1 + 2 * t), t * t * (3 - 2 * t), t * s * s, -t * t * s];
}

/**
 * Derivatives of the Hermite basis with respect to t, of the given order (1, 2
 * or 3): order 1 gives `[6t²−6t, −6t²+6t, 3t²−4t+1, 3t²−2t]`, order 2
 * `[12t−6, −12t+6, 6t−4, 6t−2]`, order 3 `[12, −12, 6, 6]`.
 */
export function hermiteBasisDerivatives(t: number, order = 1): [number, number, number, number] {
  checkParameter('hermiteBasisDerivatives', 't', t, 0, 1);
  checkInteger('hermiteBasisDerivatives', 'order', order, 1);
  if (order === 1) {
    return [6 * t * (t - 1), 6 * t * (1 - t), (1 - t) * (1 - 3 * t), t * (3 * t - 2)];
  }
  if (order === 2) return [12 * t - 6, 6 - 12 * t, 6 * t - 4, 6 * t - 2];
  if (order === 3) return [12, -12, 6, 6];
  return [0, 0, 0, 0];
}

/**
 * `[a0, a1, a2, a3]` of the cubic patch `P(μ) = a0 + a1·μ + a2·μ² + a3·μ³`
 * with end points p0, p1 and end gradients d0, d1 (lecture equation 7).
 */
export function hermiteCoefficients(
  p0: Point,
  d0: Point,
  p1: Point,
  d1: Point,
): [Point, Point, Point, Point] {
  const dimension = checkHermite('hermiteCoefficients', p0, d0, p1, d1);
  const a2 = new Array<number>(dimension);
  const a3 = new Array<number>(dimension);
  for (let d = 0; d < dimension; d++) {
    a2[d] = 3 * (p1[d] - p0[d]) - 2 * d0[d] - d1[d];
    a3[d] = 2 * (p0[d] - p1[d]) + d0[d] + d1[d];
  }
  return [p0.slice(), d0.slice(), a2, a3];
}

/** The point at t ∈ [0, 1] on the Hermite cubic with end points p0, p1 and gradients d0, d1. */
export function hermitePoint(p0: Point, d0: Point, p1: Point, d1: Point, t: number): Point {
  const dimension = checkHermite('hermitePoint', p0, d0, p1, d1);
  checkParameter('hermitePoint', 't', t, 0, 1);
  const [h0, h1, h2, h3] = hermiteWeights(t);
  const result = new Array<number>(dimension);
  for (let d = 0; d < dimension; d++) {
    result[d] = h0 * p0[d] + h1 * p1[d] + h2 * d0[d] + h3 * d1[d];
  }
  return result;
}

/**
 * The Bézier control points of the same cubic: `P0, P0 + D0/3, P1 − D1/3, P1`
 * (because a cubic Bézier has P′(0) = 3(P1 − P0) and P′(1) = 3(P3 − P2)).
 */
export function hermiteToBezier(p0: Point, d0: Point, p1: Point, d1: Point): Point[] {
  const dimension = checkHermite('hermiteToBezier', p0, d0, p1, d1);
  const first = new Array<number>(dimension);
  const second = new Array<number>(dimension);
  for (let d = 0; d < dimension; d++) {
    first[d] = p0[d] + d0[d] / 3;
    second[d] = p1[d] - d1[d] / 3;
  }
  return [p0.slice(), first, second, p1.slice()];
}

/**
 * The Hermite data `[p0, d0, p1, d1]` of a cubic Bézier curve:
 * `P0, 3(P1 − P0), P3, 3(P3 − P2)`.
 */
export function bezierToHermite(points: readonly Point[]): [Point, Point, Point, Point] {
  if (!Array.isArray(points) || points.length !== 4) {
    throw new RangeError(
      `bezierToHermite: points must hold exactly 4 control points (a cubic), but got ${Array.isArray(points) ? points.length : 'no array'}.`,
    );
  }
  const dimension = checkPoint('bezierToHermite', 'points[0]', points[0]);
  for (let i = 1; i < 4; i++) checkPoint('bezierToHermite', `points[${i}]`, points[i], dimension);
  const d0 = new Array<number>(dimension);
  const d1 = new Array<number>(dimension);
  for (let d = 0; d < dimension; d++) {
    d0[d] = 3 * (points[1][d] - points[0][d]);
    d1[d] = 3 * (points[3][d] - points[2][d]);
  }
  return [points[0].slice(), d0, points[3].slice(), d1];
}

function checkHermite(caller: string, p0: Point, d0: Point, p1: Point, d1: Point): number {
  const dimension = checkPoint(caller, 'p0', p0);
  checkPoint(caller, 'd0', d0, dimension);
  checkPoint(caller, 'p1', p1, dimension);
  checkPoint(caller, 'd1', d1, dimension);
  return dimension;
}
