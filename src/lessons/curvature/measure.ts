import type { Point } from '../../math';

/** The largest distance between two of the points (1 if they all coincide): scales arrows and teeth. */
export function sizeOf(p: readonly Point[]): number {
  // Plain loops: a spline of 40 points has 160 control points, 12 800 pairs, on every drag.
  let largest = 0;
  for (let i = 0; i < p.length; i++)
    for (let j = i + 1; j < p.length; j++) {
      let squared = 0;
      for (let d = 0; d < p[i].length; d++) squared += (p[i][d] - p[j][d]) ** 2;
      if (squared > largest) largest = squared;
    }
  return Math.sqrt(largest) || 1;
}

/** Twice the 90th percentile of the magnitudes: a scale that one spike cannot set. */
export function robustCap(values: readonly (number | null)[]): number {
  const sorted = values
    .filter((v): v is number => v !== null)
    .map(Math.abs)
    .sort((x, y) => x - y);
  return Math.max(2 * (sorted[Math.floor(0.9 * (sorted.length - 1))] ?? 0), 1e-9);
}

/** Splits values sampled at t = i/(count − 1) into runs (interleaved t, value) where they are defined. */
export function runs(values: readonly (number | null)[]): Float64Array[] {
  const out: Float64Array[] = [];
  let run: number[] = [];
  values.forEach((v, i) => {
    if (v === null) {
      if (run.length >= 4) out.push(Float64Array.from(run));
      run = [];
    } else run.push(i / (values.length - 1), v);
  });
  if (run.length >= 4) out.push(Float64Array.from(run));
  return out;
}
