import { checkPoints } from './checkPoints';
import type { Point } from './vec';

/**
 * Applies the plane map with 3×3 matrix `matrix` (rows) to 2D points in
 * homogeneous coordinates: `[x′ w, y′ w, w]ᵀ = matrix · [x, y, 1]ᵀ`. An affine
 * map has last row `[0, 0, 1]` (w = 1); any other last row is a perspective
 * (projective) map. A point with `w ≤ 0` lies on or beyond the map's vanishing
 * line, where the image is at infinity or folds over: that is a RangeError.
 */
export function projectiveMap(
  matrix: readonly (readonly number[])[],
  points: readonly Point[],
): Point[] {
  checkPoints('projectiveMap', 'points', points, 0, 2);
  const valid =
    Array.isArray(matrix) &&
    matrix.length === 3 &&
    matrix.every((row) => Array.isArray(row) && row.length === 3 && row.every(Number.isFinite));
  if (!valid) {
    throw new RangeError('projectiveMap: matrix must be 3 rows of 3 finite numbers.');
  }
  const [r0, r1, r2] = matrix;
  return points.map((point, i) => {
    const [x, y] = point;
    const w = r2[0] * x + r2[1] * y + r2[2];
    if (!(w > 0)) {
      throw new RangeError(
        `projectiveMap: points[${i}] = (${x}, ${y}) has w = ${w}; it lies on or beyond the vanishing line, so its image is not a finite point on this side.`,
      );
    }
    return [(r0[0] * x + r0[1] * y + r0[2]) / w, (r1[0] * x + r1[1] * y + r1[2]) / w];
  });
}
