import { checkPoints } from './checkPoints';
import { bezierJet } from './curvature';
import type { Point } from './vec';

// Continuity at the joint where one Bézier segment ends (t = 1) and the next
// begins (t = 0), in the lecture's hierarchy: C0 positions meet; G1 the unit
// tangents agree; C1 the first derivatives agree; G2 G1 and the curvature
// vectors agree; C2 the first and second derivatives agree. Cn is measured
// in each segment's own parameter t ∈ [0, 1].

/** Continuity classes from weakest to strongest, in the order of the lecture. */
export type Continuity = 'none' | 'C0' | 'G1' | 'C1' | 'G2' | 'C2';

/**
 * The highest of C0, G1, C1, G2, C2 (in that order) that holds where `left`
 * ends and `right` begins, or 'none' if not even the positions meet. Vectors
 * count as equal when they differ by at most `tolerance · max(1, their size)`.
 */
export function bezierJointContinuity(
  left: readonly Point[],
  right: readonly Point[],
  tolerance = 1e-9,
): Continuity {
  const caller = 'bezierJointContinuity';
  const dimension = checkPoints(caller, 'left', left, 1);
  checkPoints(caller, 'right', right, 1, dimension);
  if (!(tolerance >= 0) || !Number.isFinite(tolerance)) {
    throw new RangeError(`${caller}: tolerance = ${tolerance}; it must be a finite number ≥ 0.`);
  }
  const end = bezierJet(left, dimension, 1);
  const start = bezierJet(right, dimension, 0);
  if (!same(end.point, start.point, tolerance)) return 'none';
  if (same(end.first, start.first, tolerance) && same(end.second, start.second, tolerance)) {
    return 'C2';
  }
  const endTangent = unit(end.first);
  const startTangent = unit(start.first);
  const g1 =
    endTangent !== undefined &&
    startTangent !== undefined &&
    same(endTangent, startTangent, tolerance);
  if (
    g1 &&
    same(
      curvatureVector(end.first, end.second),
      curvatureVector(start.first, start.second),
      tolerance,
    )
  ) {
    return 'G2';
  }
  if (same(end.first, start.first, tolerance)) return 'C1';
  return g1 ? 'G1' : 'C0';
}

function same(a: readonly number[], b: readonly number[], tolerance: number): boolean {
  let difference = 0;
  let size = 1;
  for (let d = 0; d < a.length; d++) {
    difference = Math.max(difference, Math.abs(a[d] - b[d]));
    size = Math.max(size, Math.abs(a[d]), Math.abs(b[d]));
  }
  return difference <= tolerance * size;
}

function unit(v: readonly number[]): number[] | undefined {
  const length = Math.hypot(...v);
  return length > 0 ? v.map((value) => value / length) : undefined;
}

/** κN = (P″ − (P″·T)T) / |P′|², the curvature vector (independent of the parameterisation). */
function curvatureVector(first: readonly number[], second: readonly number[]): number[] {
  let speedSquared = 0;
  let along = 0;
  for (let d = 0; d < first.length; d++) {
    speedSquared += first[d] * first[d];
    along += first[d] * second[d];
  }
  return second.map((value, d) => (value - (along / speedSquared) * first[d]) / speedSquared);
}
