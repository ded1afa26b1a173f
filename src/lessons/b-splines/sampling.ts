import type { Point } from '../../math';

/** Samples per curve segment (a polynomial piece between two knots). */
export const SAMPLES = 48;

/** The curve `at` sampled from `from` to `to` (interleaved x, y), ending exactly at `to`. */
export function sampleRange(at: (u: number) => Point, from: number, to: number): Float64Array {
  const out = new Float64Array(2 * (SAMPLES + 1));
  for (let k = 0; k <= SAMPLES; k++) {
    const point = at(k === SAMPLES ? to : from + ((to - from) * k) / SAMPLES);
    out[2 * k] = point[0];
    out[2 * k + 1] = point[1];
  }
  return out;
}

/** Sampled pieces one after the other. */
export function flatten(parts: readonly Float64Array[]): Float64Array {
  const out = new Float64Array(parts.reduce((sum, part) => sum + part.length, 0));
  let offset = 0;
  for (const part of parts) {
    out.set(part, offset);
    offset += part.length;
  }
  return out;
}
