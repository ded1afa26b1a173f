import { coxDeBoorTable } from '../../math';

/** Samples across the knot range, besides one just left of and one at every knot. */
const STEPS = 240;

/**
 * Every row of the Cox–de Boor triangle sampled over [u_0, u_last]:
 * rows[r][i] holds N_{i,r}(u) as interleaved (u, N) pairs over its support
 * [u_i, u_{i+r+1}] and one zero sample either side, for the basis plot.
 * A sample just left of each knot keeps the jumps of the low rows upright.
 */
export function basisRows(knots: readonly number[], degree: number): Float64Array[][] {
  // Dragging a control point keeps the knots: the last plot is reused.
  const key = `${degree}:${knots.join(',')}`;
  if (key === last.key) return last.rows;
  last.key = key;
  last.rows = sampleRows(knots, degree);
  return last.rows;
}

const last: { key: string; rows: Float64Array[][] } = { key: '', rows: [] };

function sampleRows(knots: readonly number[], degree: number): Float64Array[][] {
  const first = knots[0];
  const width = knots[knots.length - 1] - first;
  const us = new Set<number>();
  const end = knots[knots.length - 1];
  // first + width can round past the last knot (−2.979 + 16.76 = 13.781000000000002).
  for (let k = 0; k <= STEPS; k++) us.add(Math.min(end, first + (width * k) / STEPS));
  for (const knot of knots) {
    us.add(knot);
    if (knot > first) us.add(knot - width * 1e-9);
  }
  const sorted = [...us].sort((a, b) => a - b);
  const rows = Array.from({ length: degree + 1 }, (_, r) =>
    Array.from({ length: knots.length - r - 1 }, () => new Float64Array(2 * sorted.length)),
  );
  sorted.forEach((u, s) => {
    const table = coxDeBoorTable(knots, degree, u);
    table.forEach((row, r) =>
      row.forEach((value, i) => {
        rows[r][i][2 * s] = u;
        rows[r][i][2 * s + 1] = value;
      }),
    );
  });
  // Each N_{i,r} is 0 outside [u_i, u_{i+r+1}]: keep its support and the zero on
  // either side, so the plot draws (and hover searches) only where it lives.
  return rows.map((row, r) =>
    row.map((samples, i) => {
      const from = knots[i];
      const to = knots[i + r + 1];
      let first = 0;
      while (first + 1 < sorted.length && sorted[first + 1] < from) first++;
      let last = sorted.length - 1;
      while (last > first + 1 && sorted[last - 1] >= to) last--;
      return samples.subarray(2 * first, 2 * last + 2);
    }),
  );
}
