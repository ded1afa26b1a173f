import { frenetFrame } from './frenetFrame';
import type { Point } from './vec';

// The osculating circle touches the curve to second order: radius 1/|κ|,
// centre P + N/κ (N the unit normal, κ signed in 2D), do Carmo §1.6.

/** A circle (in 3D: lying in the osculating plane). */
export interface Circle {
  readonly centre: Point;
  readonly radius: number;
}

/**
 * The osculating circle of a 2D or 3D Bézier curve at t: centre `P + N/κ`,
 * radius `1/|κ|`. RangeError where the curvature is zero (the circle would be a
 * straight line) or the speed is zero.
 */
export function osculatingCircle(points: readonly Point[], t: number): Circle {
  const { point, normal, curvature } = frenetFrame('osculatingCircle', points, t);
  if (curvature === 0 || !Number.isFinite(1 / curvature)) {
    throw new RangeError(
      `osculatingCircle: the curvature at t = ${t} is zero (the curve is straight there), so the osculating circle has infinite radius; try another t.`,
    );
  }
  const centre = point.map((value, d) => value + normal[d] / curvature);
  return { centre, radius: 1 / Math.abs(curvature) };
}
