import { checkSystem, thomas } from './tridiagonal';

// A cyclic tridiagonal system (the closed spline) has two extra corner entries:
// row 0 also has a_0 x(n−1) and row n−1 also has c(n−1) x0. Sherman–Morrison
// (Numerical Recipes §2.7, "cyclic") writes it as a tridiagonal matrix plus a
// rank-one correction u vᵀ, so two Thomas solves with one matrix give the
// answer in O(n): no dense matrix.

/**
 * Solves the cyclic tridiagonal system in O(n). `sub[0]` is the top-right corner
 * (the coefficient of x(n−1) in row 0) and `sup[n−1]` the bottom-left corner
 * (the coefficient of x0 in row n−1). Needs n ≥ 3 rows. RangeError when the
 * reduced system has a zero pivot or the correction is singular.
 */
export function solveCyclicTridiagonal(
  sub: ArrayLike<number>,
  diag: ArrayLike<number>,
  sup: ArrayLike<number>,
  rhs: ArrayLike<number>,
): number[] {
  const caller = 'solveCyclicTridiagonal';
  checkSystem(caller, sub, diag, sup, rhs, 3);
  const n = diag.length;
  const solution = new Array<number>(n);
  cyclicThomas(caller, sub, diag, sup, rhs, solution);
  return solution;
}

/** Sherman–Morrison on the Thomas algorithm, without argument checks; writes into `out`. */
export function cyclicThomas(
  caller: string,
  sub: ArrayLike<number>,
  diag: ArrayLike<number>,
  sup: ArrayLike<number>,
  rhs: ArrayLike<number>,
  out: { [index: number]: number },
): void {
  const n = diag.length;
  const top = sub[0]; // A[0][n−1]
  const bottom = sup[n - 1]; // A[n−1][0]
  // A = T + u vᵀ with u = (g, 0, …, 0, bottom), v = (1, 0, …, 0, top/g);
  // g = −b0 keeps the modified diagonal away from cancellation.
  const g = -diag[0];
  const reducedDiag = Float64Array.from(diag);
  reducedDiag[0] = diag[0] - g;
  reducedDiag[n - 1] = diag[n - 1] - (bottom * top) / g;
  const correction = new Float64Array(n);
  correction[0] = g;
  correction[n - 1] = bottom;
  const gamma = new Float64Array(n);
  thomas(caller, sub, reducedDiag, sup, rhs, gamma, out);
  thomas(caller, sub, reducedDiag, sup, correction, gamma, correction);
  const denominator = 1 + correction[0] + (top * correction[n - 1]) / g;
  if (denominator === 0) {
    throw new RangeError(
      `${caller}: the cyclic system is singular (Sherman–Morrison denominator 0).`,
    );
  }
  const factor = (out[0] + (top * out[n - 1]) / g) / denominator;
  for (let i = 0; i < n; i++) out[i] -= factor * correction[i];
}
