import { binomial } from './binomial';
import { checkPoints } from './checkPoints';
import { checkInteger } from './validate';
import type { Point } from './vec';

// The power (monomial) basis 1, u, u², … against the Bernstein basis. Expanding
// W(n, i, u) = C(n, i) uⁱ (1 − u)ⁿ⁻ⁱ gives the coefficient of uᵏ as
// C(n, i) C(n − i, k − i) (−1)^(k−i) for k ≥ i (lecture notes, matrix form).

/**
 * The power-basis matrix M with `x(u) = [1 u u² … uⁿ] · M · [P0 … Pn]ᵀ`; row k
 * holds the coefficients of uᵏ. For n = 3:
 * `[[1,0,0,0],[-3,3,0,0],[3,-6,3,0],[-1,3,-3,1]]`.
 */
export function bezierBasisMatrix(n: number): number[][] {
  checkInteger('bezierBasisMatrix', 'n', n, 0);
  const matrix: number[][] = [];
  for (let k = 0; k <= n; k++) {
    const row = new Array<number>(n + 1).fill(0);
    for (let i = 0; i <= k; i++) {
      const sign = (k - i) % 2 === 0 ? 1 : -1;
      row[i] = sign * binomial(n, i) * binomial(n - i, k - i);
    }
    matrix.push(row);
  }
  return matrix;
}

/**
 * The power-form coefficient vectors `[a0, a1, …, an]` of the Bézier curve, so
 * that `P(u) = a0 + a1·u + … + an·uⁿ` (i.e. `M · [P0 … Pn]ᵀ`). Good for display;
 * evaluate with de Casteljau, which is better conditioned.
 */
export function bezierToPowerBasis(points: readonly Point[]): Point[] {
  const dimension = checkPoints('bezierToPowerBasis', 'points', points, 1);
  const n = points.length - 1;
  const matrix = bezierBasisMatrix(n);
  return matrix.map((row) => {
    const coefficient = new Array<number>(dimension).fill(0);
    for (let i = 0; i <= n; i++) {
      if (row[i] === 0) continue;
      for (let d = 0; d < dimension; d++) coefficient[d] += row[i] * points[i][d];
    }
    return coefficient;
  });
}

/**
 * The Bézier control points of the polynomial `a0 + a1·u + … + an·uⁿ`
 * (the inverse of `bezierToPowerBasis`): `Pi = Σ_{k ≤ i} C(i, k) / C(n, k) · ak`.
 */
export function powerBasisToBezier(coefficients: readonly Point[]): Point[] {
  const dimension = checkPoints('powerBasisToBezier', 'coefficients', coefficients, 1);
  const n = coefficients.length - 1;
  const result: Point[] = [];
  for (let i = 0; i <= n; i++) {
    const point = new Array<number>(dimension).fill(0);
    for (let k = 0; k <= i; k++) {
      const weight = binomial(i, k) / binomial(n, k);
      for (let d = 0; d < dimension; d++) point[d] += weight * coefficients[k][d];
    }
    result.push(point);
  }
  return result;
}
