// The Thomas algorithm specialised to the natural spline's system (rows
// [2 1], [1 4 1] …, [1 2]; see naturalCubic.ts), for Float64Arrays of any size.
//
// Its γi depend only on i: γ0 = 1/2 and γi = 1/(4 − γ(i−1)), converging to
// c = 2 − √3. Once a value repeats exactly it is a fixed point of the
// floating-point recurrence, so tabulating γ up to there and using c after is
// bit for bit the full recurrence.
//
// Past the table both sweeps are first-order recurrences with the constant c,
// Γi = c(ri − Γ(i−1)) and Di = Γi − c·D(i+1). Each step waits for the one before
// (a multiply and a subtract of latency), so they are regrouped in blocks of 8:
// inside a block the recurrence is run from 0, independent of the block before,
// and the carried-in value g enters each entry as (−c)^(k+1)·g. Algebraically the
// same elimination; the CPU can overlap the blocks, about 2–3× faster.

const table: number[] = [0.5];
for (;;) {
  const next = 1 / (4 - table[table.length - 1]);
  if (next === table[table.length - 1]) break;
  table.push(next);
}
const gamma = Float64Array.from(table);
const tableLength = gamma.length;
const c = gamma[tableLength - 1];
// (−c)^k for k = 1 … 8: the weight of the carried value k steps on.
const [w1, w2, w3, w4, w5, w6, w7, w8] = [1, 2, 3, 4, 5, 6, 7, 8].map((k) => (-c) ** k);

/** γi of the natural system. */
export function naturalGamma(i: number): number {
  return i < tableLength ? gamma[i] : c;
}

/**
 * The forward sweep, with the right-hand side 3(y(i+1) − y(i−1)) formed on the
 * fly: writes Γ0 … Γ(m−1) into `Gamma` and returns Γm = Dm. Needs m ≥ 1.
 */
export function naturalForwardSweep(ys: Float64Array, Gamma: Float64Array): number {
  const m = ys.length - 1;
  let g = 1.5 * (ys[1] - ys[0]); // Γ0 = 3(y1 − y0) / 2
  Gamma[0] = g;
  const end = Math.min(m, tableLength);
  let i = 1;
  for (; i < end; i++) {
    // Γi = (ri − ai Γ(i−1)) / pivot with ai = 1 and γi = ci / pivot = 1 / pivot.
    g = (3 * (ys[i + 1] - ys[i - 1]) - g) * gamma[i];
    Gamma[i] = g;
  }
  // In the blocks, c·3(y(i+1) − y(i−1)) is folded to c3·(y(i+1) − y(i−1)).
  const c3 = 3 * c;
  for (; i + 8 <= m; i += 8) {
    const u0 = c3 * (ys[i + 1] - ys[i - 1]);
    const u1 = c3 * (ys[i + 2] - ys[i]) - c * u0;
    const u2 = c3 * (ys[i + 3] - ys[i + 1]) - c * u1;
    const u3 = c3 * (ys[i + 4] - ys[i + 2]) - c * u2;
    const u4 = c3 * (ys[i + 5] - ys[i + 3]) - c * u3;
    const u5 = c3 * (ys[i + 6] - ys[i + 4]) - c * u4;
    const u6 = c3 * (ys[i + 7] - ys[i + 5]) - c * u5;
    const u7 = c3 * (ys[i + 8] - ys[i + 6]) - c * u6;
    Gamma[i] = u0 + w1 * g;
    Gamma[i + 1] = u1 + w2 * g;
    Gamma[i + 2] = u2 + w3 * g;
    Gamma[i + 3] = u3 + w4 * g;
    Gamma[i + 4] = u4 + w5 * g;
    Gamma[i + 5] = u5 + w6 * g;
    Gamma[i + 6] = u6 + w7 * g;
    g = u7 + w8 * g;
    Gamma[i + 7] = g;
  }
  for (; i < m; i++) {
    g = (3 * (ys[i + 1] - ys[i - 1]) - g) * c;
    Gamma[i] = g;
  }
  // Last row [1 2]: pivot 2 − γ(m−1).
  return (3 * (ys[m] - ys[m - 1]) - g) / (2 - naturalGamma(m - 1));
}

/**
 * Back substitution in place: `x[0 … m−1]` holds Γ on entry and D0 … D(m−1) on
 * exit, given `last` = Dm.
 */
export function naturalBackSubstitution(x: Float64Array, m: number, last: number): void {
  let h = last;
  let i = m - 1;
  for (; i - 7 >= tableLength; i -= 8) {
    const v0 = x[i];
    const v1 = x[i - 1] - c * v0;
    const v2 = x[i - 2] - c * v1;
    const v3 = x[i - 3] - c * v2;
    const v4 = x[i - 4] - c * v3;
    const v5 = x[i - 5] - c * v4;
    const v6 = x[i - 6] - c * v5;
    const v7 = x[i - 7] - c * v6;
    x[i] = v0 + w1 * h;
    x[i - 1] = v1 + w2 * h;
    x[i - 2] = v2 + w3 * h;
    x[i - 3] = v3 + w4 * h;
    x[i - 4] = v4 + w5 * h;
    x[i - 5] = v5 + w6 * h;
    x[i - 6] = v6 + w7 * h;
    h = v7 + w8 * h;
    x[i - 7] = h;
  }
  for (; i >= 0; i--) {
    h = x[i] - naturalGamma(i) * h;
    x[i] = h;
  }
}

/** The natural-spline gradients D0 … Dm of ys into `out` (a different array of the same length). */
export function fillNaturalDerivatives(ys: Float64Array, out: Float64Array): void {
  const m = ys.length - 1;
  if (m === 0) {
    out[0] = 0;
    return;
  }
  const last = naturalForwardSweep(ys, out);
  out[m] = last;
  naturalBackSubstitution(out, m, last);
}
