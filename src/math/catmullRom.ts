import { checkPoints } from './checkPoints';
import { cubicSplinePoint, cubicSplineSegments } from './cubicSpline';
import { checkParameter } from './validate';
import { distance, type Point } from './vec';

// Catmull-Rom splines: a cubic Hermite spline whose gradient at each inner
// point comes from its neighbours. The lecture's uniform version uses
// (P(i+1) − P(i−1)) / 2. With parameterisation alpha (knot gaps |ΔP|^alpha:
// 0 uniform, 0.5 centripetal, 1 chordal) the gradient is the Barry–Goldman
// one, as in Yuksel, Schaefer & Keyser, "Parameterization and applications of
// Catmull-Rom curves" (2011):
//   V_i = (Pi − P(i−1))/Δ(i−1) − (P(i+1) − P(i−1))/(Δ(i−1) + Δi) + (P(i+1) − Pi)/Δi,
// a derivative per unit knot, scaled by Δi on the segment leaving Pi and by
// Δ(i−1) on the one arriving. Both ends have zero gradient, as in the lecture.

/** `(P(i+1) − P(i−1)) / 2` inside, zero vectors at both ends (uniform Catmull-Rom). */
export function catmullRomTangents(points: readonly Point[]): Point[] {
  checkPoints('catmullRomTangents', 'points', points, 1);
  return points.map((_, i) => uniformTangent(points, i));
}

/**
 * The Catmull-Rom spline through points with parameterisation alpha ∈ [0, 1]
 * (0 uniform, 0.5 centripetal, 1 chordal) as m cubic Bézier segments
 * `[Pi, Bi, Ci, P(i+1)]`. alpha = 0 gives the curve of `catmullRomTangents`.
 * A repeated point acts like an end (zero gradient), so nothing divides by zero.
 */
export function catmullRomSegments(points: readonly Point[], alpha: number): Point[][] {
  checkPoints('catmullRomSegments', 'points', points, 1);
  checkParameter('catmullRomSegments', 'alpha', alpha, 0, 1);
  const m = points.length - 1;
  if (alpha === 0) return cubicSplineSegments(points, catmullRomTangents(points));
  const gaps = knotGaps(points, alpha);
  const velocities = knotVelocities(points, gaps);
  const segments: Point[][] = new Array<Point[]>(m);
  const dimension = points[0].length;
  for (let i = 0; i < m; i++) {
    const first = new Array<number>(dimension);
    const second = new Array<number>(dimension);
    for (let d = 0; d < dimension; d++) {
      first[d] = points[i][d] + (gaps[i] * velocities[i][d]) / 3;
      second[d] = points[i + 1][d] - (gaps[i] * velocities[i + 1][d]) / 3;
    }
    segments[i] = [points[i].slice(), first, second, points[i + 1].slice()];
  }
  return segments;
}

/**
 * The point at global `s ∈ [0, m]` (uniform local parameter per segment) on the
 * Catmull-Rom spline with parameterisation alpha.
 */
export function catmullRomPoint(points: readonly Point[], alpha: number, s: number): Point {
  checkPoints('catmullRomPoint', 'points', points, 1);
  checkParameter('catmullRomPoint', 'alpha', alpha, 0, 1);
  const m = points.length - 1;
  checkParameter('catmullRomPoint', 's', s, 0, m);
  if (m === 0) return points[0].slice();
  // Only segment i's two gradients are needed: its knot gap times the knot
  // velocities (for alpha = 0 exactly the lecture's (P(i+1) − P(i−1))/2).
  const i = Math.min(Math.floor(s), m - 1);
  const gap = alpha === 0 ? 1 : distance(points[i], points[i + 1]) ** alpha;
  const tangents = [i, i + 1].map((j) =>
    alpha === 0 ? uniformTangent(points, j) : knotVelocity(points, alpha, j).map((v) => gap * v),
  );
  return cubicSplinePoint([points[i], points[i + 1]], tangents, s - i);
}

/** The uniform Catmull-Rom gradient at Pi: (P(i+1) − P(i−1))/2, zero at the ends. */
function uniformTangent(points: readonly Point[], i: number): number[] {
  const m = points.length - 1;
  const tangent = new Array<number>(points[0].length).fill(0);
  if (i === 0 || i === m) return tangent;
  for (let d = 0; d < tangent.length; d++) tangent[d] = (points[i + 1][d] - points[i - 1][d]) / 2;
  return tangent;
}

/** Δi = |P(i+1) − Pi|^alpha. */
function knotGaps(points: readonly Point[], alpha: number): number[] {
  const gaps = new Array<number>(points.length - 1);
  for (let i = 0; i + 1 < points.length; i++) gaps[i] = distance(points[i], points[i + 1]) ** alpha;
  return gaps;
}

/** The derivative with respect to the knot parameter at each point (zero at the ends). */
function knotVelocities(points: readonly Point[], gaps: readonly number[]): Point[] {
  return points.map((_, i) => velocity(points, i, gaps[i - 1], gaps[i]));
}

/** The knot velocity at point i alone. */
function knotVelocity(points: readonly Point[], alpha: number, i: number): number[] {
  const m = points.length - 1;
  const before = i > 0 ? distance(points[i - 1], points[i]) ** alpha : 0;
  const after = i < m ? distance(points[i], points[i + 1]) ** alpha : 0;
  return velocity(points, i, before, after);
}

/** Barry–Goldman velocity at Pi from its knot gaps; zero at the ends and at repeated points. */
function velocity(points: readonly Point[], i: number, before: number, after: number): number[] {
  const m = points.length - 1;
  const dimension = points[0].length;
  const result = new Array<number>(dimension).fill(0);
  // Zero gaps (repeated points) would divide 0 by 0: treat them as an end.
  if (i === 0 || i === m || !(before > 0) || !(after > 0)) return result;
  const [previous, current, next] = [points[i - 1], points[i], points[i + 1]];
  for (let d = 0; d < dimension; d++) {
    result[d] =
      (current[d] - previous[d]) / before -
      (next[d] - previous[d]) / (before + after) +
      (next[d] - current[d]) / after;
  }
  return result;
}
