import { checkPoints } from './checkPoints';
import { bezierJointContinuity, type Continuity } from './continuity';
import { bezierJet } from './curvature';
import type { Point } from './vec';

// The numbers behind a joint's verdict (lecture: continuity of Bézier
// splines), where `left` ends (t = 1) and `right` begins (t = 0): the two
// velocities, the angle between them and the ratio of their lengths, the two
// second derivatives and the curvature on both sides.

export interface JointReport {
  continuity: Continuity;
  leftVelocity: number[];
  rightVelocity: number[];
  /**
   * Angle between the two velocities in degrees (0 when they point the same
   * way); NaN where either velocity is zero, since a zero vector has no direction.
   */
  angle: number;
  /** |right velocity| / |left velocity| (1 for C¹); NaN where either velocity is zero. */
  lengthRatio: number;
  leftSecond: number[];
  rightSecond: number[];
  /** Signed curvature at the end of left and the start of right (NaN where the velocity is zero). */
  leftCurvature: number;
  rightCurvature: number;
  /** A control point sits on the joint: the speed is zero there, a corner as fonts make it. */
  degenerate: boolean;
}

const length = (v: readonly number[]) => Math.hypot(...v);

/** Below this speed a velocity counts as zero: the parameterisation stops. */
const STOPPED = 1e-12;

/** Signed 2D curvature from P′ and P″ (NaN where P′ = 0: no tangent, no curvature). */
function curvature(first: readonly number[], second: readonly number[]): number {
  const speed = length(first);
  if (!(speed > STOPPED)) return NaN;
  return (first[0] * second[1] - first[1] * second[0]) / speed ** 3;
}

/** The geometric tangent direction leaving the joint into a piece: to the first control point off the joint. */
function direction(from: readonly number[], controls: readonly Point[]): number[] | null {
  for (const q of controls) {
    const v = q.map((value, d) => value - from[d]);
    if (length(v) > 1e-12) return v;
  }
  return null;
}

/**
 * The continuity of a 2D cubic Bézier joint and its numbers. Where a control
 * point lies on the joint the parameterisation stops (zero velocity): the
 * derivatives agree trivially but the curve may turn a corner, so such a joint
 * is C⁰, or G¹ if the geometric tangents (towards the next distinct control
 * points) are opposite.
 */
export function bezierJointReport(
  left: readonly Point[],
  right: readonly Point[],
  tolerance = 1e-9,
): JointReport {
  const dimension = checkPoints('bezierJointReport', 'left', left, 2, 2);
  checkPoints('bezierJointReport', 'right', right, 2, 2);
  const end = bezierJet(left, dimension, 1);
  const start = bezierJet(right, dimension, 0);
  const joint = end.point;
  const back = direction(joint, [...left].reverse().slice(1));
  const ahead = direction(joint, right.slice(1));
  // The turn between the geometric tangents (towards the nearest distinct
  // control points): for a moving joint these are the velocities' directions.
  let turn = NaN;
  if (back && ahead) {
    // atan2 of cross and dot keeps digits near 0° (acos would lose half of them).
    const cross = back[0] * ahead[1] - back[1] * ahead[0];
    const along = -(back[0] * ahead[0] + back[1] * ahead[1]);
    turn = (Math.abs(Math.atan2(cross, along)) * 180) / Math.PI;
  }
  const degenerate = !(length(end.first) > STOPPED) || !(length(start.first) > STOPPED);
  let continuity = bezierJointContinuity(left, right, tolerance);
  if (degenerate && continuity !== 'none') continuity = turn <= 1e-6 ? 'G1' : 'C0';
  return {
    continuity,
    leftVelocity: end.first,
    rightVelocity: start.first,
    angle: degenerate ? NaN : turn,
    lengthRatio: degenerate ? NaN : length(start.first) / length(end.first),
    leftSecond: end.second,
    rightSecond: start.second,
    leftCurvature: curvature(end.first, end.second),
    rightCurvature: curvature(start.first, start.second),
    degenerate,
  };
}

/**
 * Snaps the control point after a joint so the joint becomes G¹ (on the line
 * from the control point before through the joint, keeping its distance) or
 * C¹ (the mirror image of the one before: the joint is their midpoint).
 */
export function snapJoint(before: Point, joint: Point, after: Point, mode: 'G1' | 'C1'): Point {
  const back = joint.map((value, d) => value - before[d]);
  if (mode === 'C1') return joint.map((value, d) => value + back[d]);
  const size = length(back);
  const keep = length(after.map((value, d) => value - joint[d]));
  if (!(size > 0)) return after.slice();
  return joint.map((value, d) => value + (back[d] / size) * keep);
}
