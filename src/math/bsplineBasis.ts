import { checkInteger, checkNumbers, checkParameter } from './validate';

// B-spline basis functions on an arbitrary non-decreasing knot vector by the
// Cox–de Boor recursion (de Boor 1972; Piegl & Tiller, The NURBS Book, §2.2):
//   N(j,0)(t) = 1 if knots[j] ≤ t < knots[j+1], else 0
//   N(j,d)(t) = (t − knots[j]) / (knots[j+d] − knots[j]) · N(j,d−1)(t)
//             + (knots[j+d+1] − t) / (knots[j+d+1] − knots[j+1]) · N(j+1,d−1)(t)
// with 0/0 read as 0. At t = knots[last] the last non-empty interval counts as
// closed, so a clamped curve reaches its last control point.

/**
 * The Cox–de Boor basis function `N(i, degree)` at t ∈ [knots[0], knots[last]]
 * on a non-decreasing knot vector. i runs over 0 … knots.length − degree − 2.
 */
export function bsplineBasis(
  knots: readonly number[],
  degree: number,
  i: number,
  t: number,
): number {
  const caller = 'bsplineBasis';
  checkKnots(caller, knots, degree);
  checkInteger(caller, 'i', i, 0);
  const count = knots.length - degree - 1;
  if (i >= count) {
    throw new RangeError(
      `${caller}: i = ${i} is too large; with ${knots.length} knots and degree ${degree} there are ${count} basis functions, i = 0 … ${count - 1}.`,
    );
  }
  checkParameter(caller, 't', t, knots[0], knots[knots.length - 1]);
  const span = knotSpan(caller, knots, t);
  const first = span - degree;
  if (i < first || i > span) return 0;
  const values = new Float64Array(degree + 1);
  fillBasis(knots, degree, span, t, values);
  return values[i - first];
}

/**
 * The index k of the knot interval `[knots[k], knots[k+1])` holding t, the last
 * non-empty one when t = knots[last]. Internal; expects checked knots and t.
 */
export function knotSpan(caller: string, knots: readonly number[], t: number): number {
  const last = knots.length - 1;
  if (t >= knots[last]) {
    let k = last - 1;
    while (k >= 0 && knots[k] === knots[k + 1]) k--;
    if (k < 0) {
      throw new RangeError(
        `${caller}: every knot is ${knots[0]}; the knot vector needs at least one non-empty interval knots[k] < knots[k+1].`,
      );
    }
    return k;
  }
  // Binary search for the last k with knots[k] ≤ t (then knots[k+1] > t).
  let low = 0;
  let high = last;
  while (high - low > 1) {
    const middle = (low + high) >> 1;
    if (knots[middle] <= t) low = middle;
    else high = middle;
  }
  return low;
}

/**
 * The degree + 1 basis values `N(span − degree … span, degree)(t)` into `out`;
 * functions whose index falls outside the knot vector are 0. Internal.
 */
export function fillBasis(
  knots: readonly number[],
  degree: number,
  span: number,
  t: number,
  out: { [index: number]: number },
): void {
  const first = span - degree;
  const last = knots.length - 1;
  for (let o = 0; o < degree; o++) out[o] = 0;
  out[degree] = 1;
  for (let d = 1; d <= degree; d++) {
    // Ascending j: N(j, d) reads the old N(j) and N(j + 1), the latter not yet overwritten.
    for (let j = span - d; j <= span; j++) {
      const o = j - first;
      if (j < 0 || j + d + 1 > last) {
        out[o] = 0;
        continue;
      }
      out[o] = coxDeBoorStep(knots, j, d, t, out[o], j + 1 <= span ? out[o + 1] : 0);
    }
  }
}

/**
 * One step of the recursion: N(j, d)(t) from `left` = N(j, d−1)(t) and `right`
 * = N(j+1, d−1)(t), with 0/0 read as 0. Internal; shared with coxDeBoorTable so
 * that both give the same bits.
 */
export function coxDeBoorStep(
  knots: readonly number[],
  j: number,
  d: number,
  t: number,
  left: number,
  right: number,
): number {
  const leftWidth = knots[j + d] - knots[j];
  const rightWidth = knots[j + d + 1] - knots[j + 1];
  const leftTerm = leftWidth > 0 ? ((t - knots[j]) / leftWidth) * left : 0;
  const rightTerm = rightWidth > 0 ? ((knots[j + d + 1] - t) / rightWidth) * right : 0;
  return leftTerm + rightTerm;
}

/** Throws unless degree is a whole number ≥ 0 and knots are finite, non-decreasing and enough. */
export function checkKnots(caller: string, knots: readonly number[], degree: number): void {
  checkInteger(caller, 'degree', degree, 0);
  checkNumbers(caller, 'knots', knots, degree + 2);
  for (let k = 1; k < knots.length; k++) {
    if (knots[k] < knots[k - 1]) {
      throw new RangeError(
        `${caller}: knots[${k}] = ${knots[k]} is less than knots[${k - 1}] = ${knots[k - 1]}; knots must never decrease.`,
      );
    }
  }
}

/**
 * A clamped knot vector on [0, 1] with uniform inner knots for `pointCount`
 * control points: degree + 1 zeros, the inner knots 1/(n−p), 2/(n−p), …, and
 * degree + 1 ones. The curve starts at the first and ends at the last control point.
 */
export function clampedUniformKnots(pointCount: number, degree: number): number[] {
  checkInteger('clampedUniformKnots', 'degree', degree, 0);
  checkInteger('clampedUniformKnots', 'pointCount', pointCount, degree + 1);
  const intervals = pointCount - degree;
  const knots: number[] = [];
  for (let k = 0; k <= degree; k++) knots.push(0);
  for (let k = 1; k < intervals; k++) knots.push(k / intervals);
  for (let k = 0; k <= degree; k++) knots.push(1);
  return knots;
}

/**
 * The unclamped uniform knot vector `0, 1, 2, …, pointCount + degree`. For a
 * cubic on [3, pointCount] it reproduces the lecture's uniform B-spline.
 */
export function uniformKnots(pointCount: number, degree: number): number[] {
  checkInteger('uniformKnots', 'degree', degree, 0);
  checkInteger('uniformKnots', 'pointCount', pointCount, 1);
  return Array.from({ length: pointCount + degree + 1 }, (_, k) => k);
}
