import { checkPoints } from './checkPoints';
import { bezierToPowerBasis } from './powerBasis';
import type { Point } from './vec';

// With P(t) = a0 + a1 t + a2 t² + a3 t³, the curvature's numerator
// P′ × P″ = 2(a1×a2) + 6(a1×a3) t + 6(a2×a3) t² is only quadratic (the t³ terms
// cancel), so a planar cubic has at most two inflections.

/**
 * The parameters t in [0, 1] where a 2D cubic Bézier curve inflects: its signed
 * curvature changes sign, i.e. `P′(t) × P″(t)` has a simple root. Sorted; empty
 * when there is none, and when the curve is straight (all points collinear),
 * where the curvature is zero everywhere.
 */
export function cubicInflections(points: readonly Point[]): number[] {
  checkPoints('cubicInflections', 'points', points, 4, 2);
  if (points.length !== 4) {
    throw new RangeError(
      `cubicInflections: points must hold exactly 4 control points (a cubic), but got ${points.length}.`,
    );
  }
  const [, a1, a2, a3] = bezierToPowerBasis(points);
  const scale = Math.max(lengthSquared(a1), lengthSquared(a2), lengthSquared(a3));
  if (scale === 0) return [];
  const tiny = 1e-12 * scale;
  // Roots of A t² + B t + C, a third of the numerator above.
  const A = cross(a2, a3);
  const B = cross(a1, a3);
  const C = cross(a1, a2) / 3;
  const roots: number[] = [];
  if (Math.abs(A) <= tiny) {
    if (Math.abs(B) > tiny) roots.push(-C / B);
  } else {
    const discriminant = B * B - 4 * A * C;
    // A double root touches zero without a change of sign: no inflection.
    if (discriminant > tiny * tiny) {
      const root = Math.sqrt(discriminant);
      // Citardauq form for the smaller root avoids cancellation.
      const q = -0.5 * (B + Math.sign(B || 1) * root);
      roots.push(q / A);
      if (q !== 0) roots.push(C / q);
    }
  }
  return roots.filter((t) => t >= 0 && t <= 1).sort((a, b) => a - b);
}

function cross(a: Point, b: Point): number {
  return a[0] * b[1] - a[1] * b[0];
}

function lengthSquared(a: Point): number {
  return a[0] * a[0] + a[1] * a[1];
}
