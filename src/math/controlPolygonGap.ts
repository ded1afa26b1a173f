import { bezierPoint } from './bezier';
import { checkPoints } from './checkPoints';
import { distance, type Point } from './vec';

/**
 * How far the control polygon is from its curve: the largest distance
 * `|Pi − P(i/n)|` between a control point and the curve point at the matching
 * uniform parameter. Degree elevation and subdivision drive it to zero (as
 * O(1/n) and O(1/4ᵏ)), which is why the polygon converges to the curve.
 * Zero for a single point.
 */
export function controlPolygonGap(points: readonly Point[]): number {
  checkPoints('controlPolygonGap', 'points', points, 1);
  const n = points.length - 1;
  let gap = 0;
  for (let i = 0; i <= n; i++) {
    gap = Math.max(gap, distance(points[i], bezierPoint(points, n === 0 ? 0 : i / n)));
  }
  return gap;
}
