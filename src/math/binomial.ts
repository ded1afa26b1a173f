import { checkInteger } from './validate';

// Pascal's triangle up to row 56: every entry is an integer below 2^53
// (C(56, 28) = 7 648 690 600 760 440), so adding rows is exact in doubles.
// Row 57 is the first whose middle entry no longer fits.
const exactRows = 56;
const pascal: Float64Array[] = [Float64Array.of(1)];
for (let n = 1; n <= exactRows; n++) {
  const previous = pascal[n - 1];
  const row = new Float64Array(n + 1);
  row[0] = 1;
  row[n] = 1;
  for (let k = 1; k < n; k++) row[k] = previous[k - 1] + previous[k];
  pascal.push(row);
}

/**
 * The binomial coefficient `C(n, k) = n! / (k! (n−k)!)`.
 * Exact for n ≤ 56; for larger n the nearest double to the exact integer
 * (computed in BigInt, rounded once). 0 when k < 0 or k > n.
 */
export function binomial(n: number, k: number): number {
  checkInteger('binomial', 'n', n, 0);
  checkInteger('binomial', 'k', k, Number.MIN_SAFE_INTEGER);
  if (k < 0 || k > n) return 0;
  if (n <= exactRows) return pascal[n][k];
  return largeBinomial(n, Math.min(k, n - k));
}

function largeBinomial(n: number, k: number): number {
  // C(n, k) ≥ (n/k)^k ≥ 2^k, so anything with k > 1024 overflows; checking the
  // logarithm first keeps BigInt work bounded by about a thousand steps.
  let logarithm = 0;
  for (let i = 1; i <= k; i++) {
    logarithm += Math.log2((n - k + i) / i);
    if (logarithm > 1025) return Infinity;
  }
  // Multiplicative formula: after step i the value is C(n − k + i, i), an
  // integer, so each BigInt division is exact.
  let value = 1n;
  const base = BigInt(n - k);
  for (let i = 1; i <= k; i++) {
    const step = BigInt(i);
    value = (value * (base + step)) / step;
  }
  // Number(BigInt) rounds to the nearest double (ties to even).
  return Number(value);
}
