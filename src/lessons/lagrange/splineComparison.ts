/**
 * The natural cubic spline through the Lagrange lesson's points, compared with
 * the polynomial: how far apart they are on each piece, and how moving one
 * point moves every gradient of the spline.
 */
import { bezierPoint, cubicSplineSegments, naturalCubicTangents, type Point } from '../../math';
import { memoOn } from '../../kit/memoOn';
import { type Polynomial, SAMPLES, polynomial } from './polynomial';
import type { LagrangeState } from './state';

/**
 * The natural cubic spline beside the polynomial: its gradients solve one
 * system for all the points together, so it is global (moving one point moves
 * every gradient), though far calmer than one polynomial of high degree.
 */
export interface SplineComparison {
  /** One cubic Bézier per gap, from the gradients D0 … Dn. */
  segments: Point[][];
  /** D0 … Dn of the natural spline (uniform parameter, one unit per piece). */
  gradients: Point[];
  /** On each piece, the largest distance between the polynomial and the spline. */
  gaps: number[];
  /** The point moved to show the coupling, and how far (up, in y). */
  moved: number;
  nudge: number;
  /** The spline after that move, and |ΔDₖ| for every gradient. */
  ghost: Point[][];
  gradientChange: number[];
  /** How many gradients changed (all, unless the points are symmetric about the moved one). */
  changed: number;
}

/** The point moved to show the coupling: off the middle, so symmetry hides no change. */
export const movedPoint = (n: number) => Math.max(0, Math.ceil(n / 2) - 1);
/** How far it is moved, up. */
export const NUDGE = 1;

/** The natural cubic spline through the same points, when it is compared. */
export const splineThrough = memoOn<
  LagrangeState,
  'points' | 'spacing' | 'spline',
  SplineComparison | null
>(['points', 'spacing', 'spline'], (fields) => {
  if (!fields.spline) return null;
  const { points } = fields;
  const gradients = naturalCubicTangents(points);
  const segments = cubicSplineSegments(points, gradients);
  const n = points.length - 1;
  const moved = movedPoint(n);
  const nudged = points.map((p, k): Point => (k === moved ? [p[0], p[1] + NUDGE] : p));
  const after = naturalCubicTangents(nudged);
  const gradientChange = gradients.map((d, k) =>
    Math.hypot(after[k][0] - d[0], after[k][1] - d[1]),
  );
  return {
    segments,
    gradients,
    gaps: pieceGaps(polynomial(fields), segments),
    moved,
    nudge: NUDGE,
    ghost: cubicSplineSegments(nudged, after),
    gradientChange,
    // A change below rounding is no change.
    changed: gradientChange.filter((c) => c > 1e-9).length,
  };
});

/**
 * On piece k (tₖ to tₖ₊₁ of the polynomial, 0 to 1 of the spline's piece), the
 * largest distance between the two curves at matching parameters.
 */
function pieceGaps({ ts, curve }: Pick<Polynomial, 'ts' | 'curve'>, segments: Point[][]): number[] {
  return segments.map((segment, k) => {
    let gap = 0;
    for (let i = 0; i <= SAMPLES; i++) {
      const t = i / SAMPLES;
      if (t < ts[k] || t > ts[k + 1]) continue;
      const [x, y] = bezierPoint(segment, (t - ts[k]) / (ts[k + 1] - ts[k]));
      gap = Math.max(gap, Math.hypot(curve[2 * i] - x, curve[2 * i + 1] - y));
    }
    return gap;
  });
}
