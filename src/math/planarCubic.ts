import { checkInteger, checkNumbers } from './validate';

// A planar cubic Bézier held as its eight coordinates, sampled in Bernstein
// form: P(t) = (1 − t)³ P0 + 3(1 − t)² t P1 + 3(1 − t) t² P2 + t³ P3 (the
// lecture's blending functions W(3, i, t)). For drawing code that holds a
// curve on screen as numbers, not points: it reads no point arrays and, given
// a buffer, makes none. It is the sum the painter has always inked a curve
// with, to the last bit (where a label may go depends on it); bezierPoint's
// de Casteljau is the careful one, and the two agree within rounding.

/**
 * The cubic with control points (x0, y0) … (x3, y3), given as
 * `[x0, y0, x1, y1, x2, y2, x3, y3]`, sampled at t = 0, 1/segments, …, 1 into
 * one interleaved Float64Array `[x, y, x, y, …]` of 2·(segments + 1) numbers.
 * Pass `out` to reuse a buffer. The first sample is exactly P0 and the last
 * is P3.
 */
export function samplePlanarCubic(
  controls: ArrayLike<number>,
  segments: number,
  out?: Float64Array,
): Float64Array {
  const caller = 'samplePlanarCubic';
  checkNumbers(caller, 'controls', controls, 8);
  if (controls.length !== 8) {
    throw new RangeError(
      `${caller}: controls has ${controls.length} values; a planar cubic has exactly 8 (x0, y0 … x3, y3).`,
    );
  }
  checkInteger(caller, 'segments', segments, 1);
  const length = 2 * (segments + 1);
  const result = out && out.length >= length ? out : new Float64Array(length);
  const x0 = controls[0];
  const y0 = controls[1];
  const x1 = controls[2];
  const y1 = controls[3];
  const x2 = controls[4];
  const y2 = controls[5];
  const x3 = controls[6];
  const y3 = controls[7];
  result[0] = x0;
  result[1] = y0;
  for (let i = 1; i <= segments; i++) {
    const t = i / segments;
    const s = 1 - t;
    const a = s * s * s;
    const b = 3 * s * s * t;
    const c = 3 * s * t * t;
    const d = t * t * t;
    result[2 * i] = a * x0 + b * x1 + c * x2 + d * x3;
    result[2 * i + 1] = a * y0 + b * y1 + c * y2 + d * y3;
  }
  return result;
}
