import { binomial } from './binomial';
import { checkInteger, checkParameter } from './validate';

/**
 * The Bernstein blending function `W(n, i, t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ`
 * (lecture notes, Bézier curves). 0 when i < 0 or i > n. Exact at t = 0 and
 * t = 1, where `0⁰ = 1`.
 */
export function bernstein(n: number, i: number, t: number): number {
  checkInteger('bernstein', 'n', n, 0);
  checkInteger('bernstein', 'i', i, Number.MIN_SAFE_INTEGER);
  checkParameter('bernstein', 't', t, 0, 1);
  if (i < 0 || i > n) return 0;
  // Math.pow(0, 0) is 1, which is the convention the formula needs.
  return binomial(n, i) * t ** i * (1 - t) ** (n - i);
}

/**
 * All n + 1 Bernstein values `[W(n, 0, t) … W(n, n, t)]`, e.g. for plotting the
 * blending functions or weighting control points.
 */
export function bernsteinBasis(n: number, t: number): number[] {
  checkInteger('bernsteinBasis', 'n', n, 0);
  checkParameter('bernsteinBasis', 't', t, 0, 1);
  const values = new Float64Array(n + 1);
  fillBernstein(n, t, values);
  return Array.from(values);
}

/**
 * Writes `W(n, 0, t) … W(n, n, t)` into `out[0 … n]` without allocating.
 * Built by the de Casteljau recurrence `W(r, j) = (1−t) W(r−1, j) + t W(r−1, j−1)`:
 * every step is a convex combination, so values stay in [0, 1], sum to 1 to
 * rounding and are exact at the ends. Internal: no argument checks.
 */
export function fillBernstein(n: number, t: number, out: Float64Array): void {
  const s = 1 - t;
  out[0] = 1;
  for (let r = 1; r <= n; r++) {
    out[r] = t * out[r - 1];
    for (let j = r - 1; j > 0; j--) out[j] = s * out[j] + t * out[j - 1];
    out[0] = s * out[0];
  }
}
