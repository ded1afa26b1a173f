import { checkPoint } from './checkPoints';
import { checkNumber } from './validate';
import type { Point } from './vec';

// Plane maps as 3×3 matrices acting on homogeneous coordinates [x, y, 1]
// (the matrices projectiveMap applies): composing maps is multiplying them.

/** A 3×3 matrix, as rows. */
export type PlaneMatrix = readonly (readonly number[])[];

function checkMatrix(caller: string, name: string, matrix: PlaneMatrix): void {
  const valid =
    Array.isArray(matrix) &&
    matrix.length === 3 &&
    matrix.every((row) => Array.isArray(row) && row.length === 3 && row.every(Number.isFinite));
  if (!valid) throw new RangeError(`${caller}: ${name} must be 3 rows of 3 finite numbers.`);
}

/** The product `a · b`: the map that applies b first, then a. */
export function multiplyPlaneMatrices(a: PlaneMatrix, b: PlaneMatrix): number[][] {
  checkMatrix('multiplyPlaneMatrices', 'a', a);
  checkMatrix('multiplyPlaneMatrices', 'b', b);
  return a.map((row) =>
    [0, 1, 2].map((j) => row[0] * b[0][j] + row[1] * b[1][j] + row[2] * b[2][j]),
  );
}

/** The translation by (x, y). */
export function translationMatrix(x: number, y: number): number[][] {
  checkNumber('translationMatrix', 'x', x);
  checkNumber('translationMatrix', 'y', y);
  return [
    [1, 0, x],
    [0, 1, y],
    [0, 0, 1],
  ];
}

/**
 * The w a plane map gives a 2D point, `m₂₀x + m₂₁y + m₂₂`: 1 everywhere for
 * an affine map; the divisor of a perspective map, which varies.
 */
export function homogeneousWeight(matrix: PlaneMatrix, point: Point): number {
  checkMatrix('homogeneousWeight', 'matrix', matrix);
  checkPoint('homogeneousWeight', 'point', point, 2);
  return matrix[2][0] * point[0] + matrix[2][1] * point[1] + matrix[2][2];
}
