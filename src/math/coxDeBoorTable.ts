import { checkKnots, coxDeBoorStep, knotSpan } from './bsplineBasis';
import { checkParameter } from './validate';

// The whole Cox–de Boor triangle at one t (de Boor 1972; Piegl & Tiller, The
// NURBS Book, §2.2, Fig. 2.6), for a lesson that shows how each basis function
// of degree r is built from two of degree r − 1:
//   N(i,0)(t) = 1 if knots[i] ≤ t < knots[i+1], else 0
//   N(i,r)(t) = (t − knots[i]) / (knots[i+r] − knots[i]) · N(i,r−1)(t)
//             + (knots[i+r+1] − t) / (knots[i+r+1] − knots[i+1]) · N(i+1,r−1)(t)
// with 0/0 read as 0 and, at t = knots[last], the last non-empty interval closed.

/**
 * The Cox–de Boor triangle at t ∈ [knots[0], knots[last]]: row r (r = 0 …
 * degree) holds N(i, r)(t) for i = 0 … knots.length − r − 2, each computed by
 * the recursion from row r − 1. Row `degree` equals `bsplineBasis(knots,
 * degree, i, t)` for every i.
 */
export function coxDeBoorTable(knots: readonly number[], degree: number, t: number): number[][] {
  const caller = 'coxDeBoorTable';
  checkKnots(caller, knots, degree);
  checkParameter(caller, 't', t, knots[0], knots[knots.length - 1]);
  const span = knotSpan(caller, knots, t);
  const rows: number[][] = new Array<number[]>(degree + 1);
  const first = new Array<number>(knots.length - 1).fill(0);
  first[span] = 1;
  rows[0] = first;
  for (let r = 1; r <= degree; r++) {
    const previous = rows[r - 1];
    const row = new Array<number>(knots.length - r - 1);
    for (let i = 0; i < row.length; i++) {
      row[i] = coxDeBoorStep(knots, i, r, t, previous[i], previous[i + 1]);
    }
    rows[r] = row;
  }
  return rows;
}
