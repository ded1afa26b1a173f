// The Lebesgue function Σ_k |L_k(t)| of an interpolation scheme bounds how far
// the interpolant moves when every data point moves by at most ε: by at most
// Σ_k |L_k(t)|·ε at t. Its largest value is the Lebesgue constant (Trefethen,
// Approximation Theory and Approximation Practice, ch. 15).

/**
 * The largest Σ_k |L_k(t)| over sampled basis curves (each interleaved
 * `[t0, L_k(t0), t1, L_k(t1), …]` at the same t's, as `sampleBasis` gives
 * them), and the first t where it is reached: the Lebesgue constant,
 * as fine as the samples. `{ value: 0, t: 0 }` for no curves.
 */
export function lebesgueConstant(curves: readonly ArrayLike<number>[]): {
  value: number;
  t: number;
} {
  let best = { value: 0, t: 0 };
  const samples = curves.length ? curves[0].length >> 1 : 0;
  for (let i = 0; i < samples; i++) {
    let value = 0;
    for (const curve of curves) value += Math.abs(curve[2 * i + 1]);
    if (value > best.value) best = { value, t: curves[0][2 * i] };
  }
  return best;
}
