import type { Point } from '../../math';

/** The largest distance between two of the points (1 if they all coincide): scales arrows and teeth. */
export function sizeOf(p: readonly Point[]): number {
  let size = 0;
  for (const a of p)
    for (const b of p) size = Math.max(size, Math.hypot(...a.map((v, d) => v - b[d])));
  return size || 1;
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
