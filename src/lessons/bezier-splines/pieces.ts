import { bezierDerivative, bezierPoint, elevateDegree, type Point } from '../../math';

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
