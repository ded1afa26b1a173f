import { checkPoint } from './checkPoints';
import type { Point } from './vec';

/**
 * The angle (radians, in (−π, π]) that turns the direction of the 2D vector
 * `a` onto that of `b`: positive anticlockwise. atan2 of the cross and dot
 * products stays accurate for nearly parallel vectors, unlike acos. 0 if
 * either vector is zero.
 */
export function signedAngle(a: Point, b: Point): number {
  checkPoint('signedAngle', 'a', a, 2);
  checkPoint('signedAngle', 'b', b, 2);
  return Math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]);
}
