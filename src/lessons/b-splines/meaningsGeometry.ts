import { memoOn } from '../../kit/memoOn';
import type { Point } from '../../math';
import { KNOT_FIELDS, type KnotCurve, type KnotFields, knotCurve, knotRuns } from './knotGeometry';

/** A knot value where the curve is, and the curve's point there. */
export interface KnotPoint {
  u: number;
  /** The knot that names it: u(j), the first of its run inside [u(p), u(m+1)]. */
  index: number;
  multiplicity: number;
  /** P(u): where the pieces before and after u join (the curve's ends at u(p) and u(m+1)). */
  at: Point;
  /** The control point P(u) lands on (within 1e-9), else null. */
  on: number | null;
}

/** Every distinct knot value in the curve's domain [u(p), u(m+1)], with P(u) there. */
export function knotPoints({ curve, at }: KnotCurve): KnotPoint[] {
  const { knots, degree, domain, control } = curve;
  const found: KnotPoint[] = [];
  for (const [first, count] of knotRuns(knots)) {
    const u = knots[first];
    if (u < domain[0] || u > domain[1]) continue;
    const point = at(u);
    const size = Math.max(1, Math.hypot(...point));
    const on = control.findIndex(
      (x) => Math.hypot(x[0] - point[0], x[1] - point[1]) <= 1e-9 * size,
    );
    found.push({
      u,
      index: Math.max(first, degree),
      multiplicity: count,
      at: point,
      on: on < 0 ? null : on,
    });
  }
  return found;
}

/** The state's knot points, kept while its curve is the same. */
export const stateKnotPoints = memoOn<KnotFields, keyof KnotFields, KnotPoint[]>(
  KNOT_FIELDS,
  (fields) => knotPoints(knotCurve(fields)),
);

/** The knot point and control point nearest each other, and how far apart. */
export function nearestControl(
  knotPoints: readonly KnotPoint[],
  control: readonly Point[],
): { knot: KnotPoint; point: number; distance: number } {
  let best = { knot: knotPoints[0], point: 0, distance: Infinity };
  for (const knot of knotPoints)
    control.forEach((x, point) => {
      const distance = Math.hypot(x[0] - knot.at[0], x[1] - knot.at[1]);
      if (distance < best.distance) best = { knot, point, distance };
    });
  return best;
}
