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

/** How far past the typical value (the 90th percentile) a peak is still drawn whole. */
const WHOLE_PEAK = 4;

/**
 * A scale for values drawn up to 1.25 times it: twice the 90th percentile of
 * the magnitudes, so that one spike cannot set it (at a cusp κ grows without
 * bound); but a peak within four times that percentile (a natural spline's
 * tight bend) is finite and drawn whole, so the plot shows no gap where
 * there is none (a gap beside a C² join reads as a jump in κ).
 */
export function robustCap(values: readonly (number | null)[]): number {
  const sorted = values
    .filter((v): v is number => v !== null)
    .map(Math.abs)
    .sort((x, y) => x - y);
  const typical = sorted[Math.floor(0.9 * (sorted.length - 1))] ?? 0;
  const largest = sorted[sorted.length - 1] ?? 0;
  const whole = largest <= WHOLE_PEAK * typical ? largest / 1.25 : 0;
  return Math.max(2 * typical, whole, 1e-9);
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
