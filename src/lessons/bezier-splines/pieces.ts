import { bezierDerivative, bezierPoint, elevateDegree, type Point, sampleBezier } from '../../math';
import type { Bounds } from '../../render/projection';

/** A tooth of the curvature comb: from the curve, along the normal, as long as the curvature. */
export type Tooth = [Point, Point];

/** A line or quadratic piece as the same curve of degree 3 (to draw all pieces alike). */
export function asCubic(segment: Point[]): Point[] {
  let result = segment;
  while (result.length < 4) result = elevateDegree(result);
  return result;
}

/** Control points c0 … c3k as k cubic pieces. */
export const piecesOf = (q: readonly Point[]): Point[][] =>
  Array.from({ length: Math.floor((q.length - 1) / 3) }, (_, k) => q.slice(3 * k, 3 * k + 4));

/** Teeth along every piece, scaled so the longest is an eighth of the spline's size. */
export function comb(pieces: readonly Point[][]): Tooth[] {
  const raw: { at: Point; normal: Point; kappa: number }[] = [];
  for (const piece of pieces) {
    const first = bezierDerivative(piece);
    const second = bezierDerivative(first);
    for (let sample = 0; sample <= 16; sample++) {
      const t = sample / 16;
      const [dx, dy] = bezierPoint(first, t);
      const [ex, ey] = bezierPoint(second, t);
      const speed = Math.hypot(dx, dy);
      if (!(speed > 1e-9)) continue;
      const kappa = (dx * ey - dy * ex) / speed ** 3;
      raw.push({ at: bezierPoint(piece, t), normal: [-dy / speed, dx / speed], kappa });
    }
  }
  const xs = pieces.flat().map((q) => q[0]);
  const ys = pieces.flat().map((q) => q[1]);
  const size = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys), 1e-9);
  const largest = Math.max(...raw.map((r) => Math.abs(r.kappa)), 1e-9);
  const factor = (0.125 * size) / largest;
  // The comb points away from the centre of curvature, as CAD systems draw it.
  return raw.map(({ at, normal, kappa }) => [
    at,
    [at[0] - normal[0] * kappa * factor, at[1] - normal[1] * kappa * factor],
  ]);
}

/** Samples per cubic piece when a loop is traced. */
const LOOP_SAMPLES = 64;

/**
 * Where a chain of cubic pieces loops through its crossing: the bounds of the
 * stretch between its first and its last pass within `near` of the crossing
 * (the loop, and the crossing at its ends), or null if the chain passes there
 * only once.
 */
export function loopBounds(
  segments: readonly (readonly Point[])[],
  crossing: Point,
  near: number,
): Bounds | null {
  const xy: number[] = [];
  for (const segment of segments) {
    const samples = sampleBezier(segment as Point[], LOOP_SAMPLES);
    for (let i = xy.length ? 2 : 0; i < samples.length; i++) xy.push(samples[i]);
  }
  const close: number[] = [];
  for (let i = 0; i < xy.length; i += 2)
    if (Math.hypot(xy[i] - crossing[0], xy[i + 1] - crossing[1]) <= near) close.push(i);
  if (close.length < 2) return null;
  const first = close[0];
  const last = close[close.length - 1];
  const box = { minX: crossing[0], minY: crossing[1], maxX: crossing[0], maxY: crossing[1] };
  for (let i = first; i <= last; i += 2) {
    box.minX = Math.min(box.minX, xy[i]);
    box.maxX = Math.max(box.maxX, xy[i]);
    box.minY = Math.min(box.minY, xy[i + 1]);
    box.maxY = Math.max(box.maxY, xy[i + 1]);
  }
  return box;
}
