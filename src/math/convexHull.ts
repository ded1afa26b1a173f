import { checkPoint, checkPoints } from './checkPoints';
import { checkNumber } from './validate';
import type { Point } from './vec';

// Andrew's monotone chain (A. M. Andrew, "Another efficient algorithm for
// convex hulls in two dimensions", 1979): sort by x then y, build the lower and
// upper chains keeping only left turns. O(n log n).

/**
 * The convex hull of 2D points (at least one): its corners anticlockwise,
 * starting at the lowest x (then lowest y), without repeated or collinear
 * points. One distinct point gives one corner, collinear points their two ends.
 */
export function convexHull(points: readonly Point[]): Point[] {
  checkPoints('convexHull', 'points', points, 1, 2);
  const sorted = points.slice().sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  const lower: Point[] = [];
  for (const point of sorted) {
    while (
      lower.length >= 2 &&
      turn(lower[lower.length - 2], lower[lower.length - 1], point) <= 0
    ) {
      lower.pop();
    }
    lower.push(point);
  }
  const upper: Point[] = [];
  for (let i = sorted.length - 1; i >= 0; i--) {
    const point = sorted[i];
    while (
      upper.length >= 2 &&
      turn(upper[upper.length - 2], upper[upper.length - 1], point) <= 0
    ) {
      upper.pop();
    }
    upper.push(point);
  }
  // Each chain ends where the other starts.
  lower.pop();
  upper.pop();
  const hull = lower.concat(upper);
  if (hull.length === 0 || (hull.length === 2 && samePoint(hull[0], hull[1]))) {
    return [sorted[0].slice()];
  }
  return hull.map((point) => point.slice());
}

/**
 * Whether a 2D point lies in the convex polygon `hull` (anticlockwise corners,
 * as returned by convexHull), boundary included, allowing `tolerance` of
 * distance outside each edge. Works for one- and two-corner hulls too.
 */
export function convexHullContains(hull: readonly Point[], point: Point, tolerance = 0): boolean {
  checkPoints('convexHullContains', 'hull', hull, 1, 2);
  checkPoint('convexHullContains', 'point', point, 2);
  checkNumber('convexHullContains', 'tolerance', tolerance);
  if (hull.length === 1) return distanceToSegment(point, hull[0], hull[0]) <= tolerance;
  if (hull.length === 2) return distanceToSegment(point, hull[0], hull[1]) <= tolerance;
  for (let i = 0; i < hull.length; i++) {
    const a = hull[i];
    const b = hull[(i + 1) % hull.length];
    const edge = Math.hypot(b[0] - a[0], b[1] - a[1]);
    // turn / |edge| is the signed distance of the point to the left of the edge.
    if (turn(a, b, point) < -tolerance * edge) return false;
  }
  return true;
}

/** Twice the signed area of triangle o, a, b: positive when o → a → b turns left. */
function turn(o: Point, a: Point, b: Point): number {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

function samePoint(a: Point, b: Point): boolean {
  return a[0] === b[0] && a[1] === b[1];
}

function distanceToSegment(p: Point, a: Point, b: Point): number {
  const [dx, dy] = [b[0] - a[0], b[1] - a[1]];
  const lengthSquared = dx * dx + dy * dy;
  const t =
    lengthSquared > 0
      ? Math.min(1, Math.max(0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / lengthSquared))
      : 0;
  return Math.hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy));
}
