import { checkPoints } from './checkPoints';
import { bezierToPowerBasis } from './powerBasis';
import type { Point } from './vec';

// P(t) − P(s) = (t − s)·[a1 + a2 σ + a3 (σ² − π)] with σ = t + s, π = t·s.
// Crossing the bracket with a3 removes π: σ = −(a1×a3)/(a2×a3); then π follows
// from the component along a3, and t, s are the roots of z² − σz + π.
// (The same reduction as in Stone & DeRose, "A geometric characterization of
// parametric cubic curves", 1989.)

/**
 * Where a 2D cubic Bézier curve crosses itself: the two parameters `[t, s]`,
 * `0 ≤ t < s ≤ 1`, with `P(t) = P(s)`; null when the curve has no loop on
 * [0, 1] (including straight and degenerate curves).
 */
export function cubicSelfIntersection(points: readonly Point[]): [number, number] | null {
  checkPoints('cubicSelfIntersection', 'points', points, 4, 2);
  if (points.length !== 4) {
    throw new RangeError(
      `cubicSelfIntersection: points must hold exactly 4 control points (a cubic), but got ${points.length}.`,
    );
  }
  const [, a1, a2, a3] = bezierToPowerBasis(points);
  const a3Squared = a3[0] * a3[0] + a3[1] * a3[1];
  const scale = Math.max(a1[0] ** 2 + a1[1] ** 2, a2[0] ** 2 + a2[1] ** 2, a3Squared);
  const denominator = cross(a2, a3);
  if (scale === 0 || Math.abs(denominator) <= 1e-12 * scale) return null;
  const sigma = -cross(a1, a3) / denominator;
  const bx = a1[0] + sigma * a2[0] + sigma * sigma * a3[0];
  const by = a1[1] + sigma * a2[1] + sigma * sigma * a3[1];
  const pi = (bx * a3[0] + by * a3[1]) / a3Squared;
  const discriminant = sigma * sigma - 4 * pi;
  if (!(discriminant > 1e-12)) return null;
  const root = Math.sqrt(discriminant);
  const t = (sigma - root) / 2;
  const s = (sigma + root) / 2;
  return t >= 0 && s <= 1 ? [t, s] : null;
}

function cross(a: Point, b: Point): number {
  return a[0] * b[1] - a[1] * b[0];
}
