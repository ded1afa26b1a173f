import { checkPoints } from './checkPoints';
import { checkParameter } from './validate';
import type { Point } from './vec';

// Differential geometry of a Bézier curve at t. The derivatives come from the
// de Casteljau triangle stopped two levels early (Farin, Curves and Surfaces
// for CAGD, §5.3): with Q0, Q1, Q2 the level n−2 points,
//   P′(t) = n((1−t)(Q1 − Q0) + t(Q2 − Q1)),  P″(t) = n(n−1)(Q2 − 2Q1 + Q0).

/** The position, first and second derivative of a Bézier curve at one t. */
export interface BezierJet {
  readonly point: number[];
  readonly first: number[];
  readonly second: number[];
}

let scratch = new Float64Array(16);

/** Position, P′ and P″ at t without argument checks. Internal. */
export function bezierJet(points: readonly Point[], dimension: number, t: number): BezierJet {
  const n = points.length - 1;
  const point = new Array<number>(dimension);
  const first = new Array<number>(dimension).fill(0);
  const second = new Array<number>(dimension).fill(0);
  if (scratch.length < points.length) scratch = new Float64Array(2 * points.length);
  const row = scratch;
  const s = 1 - t;
  for (let d = 0; d < dimension; d++) {
    for (let i = 0; i <= n; i++) row[i] = points[i][d];
    // Reduce to the level with three points (or fewer for degree < 2).
    for (let r = n; r > 2; r--) {
      for (let i = 0; i < r; i++) row[i] = s * row[i] + t * row[i + 1];
    }
    if (n >= 2) {
      const [q0, q1, q2] = [row[0], row[1], row[2]];
      const a = s * q0 + t * q1;
      const b = s * q1 + t * q2;
      point[d] = s * a + t * b;
      first[d] = n * (b - a);
      second[d] = n * (n - 1) * (q2 - 2 * q1 + q0);
    } else if (n === 1) {
      point[d] = s * row[0] + t * row[1];
      first[d] = row[1] - row[0];
    } else {
      point[d] = row[0];
    }
  }
  return { point, first, second };
}

/** The derivative vector P′(t) of the Bézier curve (its velocity; not normalised). */
export function bezierTangent(points: readonly Point[], t: number): Point {
  const dimension = checkPoints('bezierTangent', 'points', points, 1);
  checkParameter('bezierTangent', 't', t, 0, 1);
  return bezierJet(points, dimension, t).first;
}

/**
 * The curvature of a Bézier curve at t. In 2D the signed curvature
 * `(x′y″ − y′x″) / (x′² + y′²)^{3/2}` (positive turning left); in 3D the
 * unsigned `|P′ × P″| / |P′|³`. RangeError where the speed is zero (a cusp or
 * coincident control points), since the direction is undefined there.
 */
export function bezierCurvature(points: readonly Point[], t: number): number {
  const caller = 'bezierCurvature';
  const dimension = checkPoints(caller, 'points', points, 1);
  checkParameter(caller, 't', t, 0, 1);
  if (dimension !== 2 && dimension !== 3) {
    throw new RangeError(
      `${caller}: points are ${dimension}D; curvature is defined here for 2D and 3D curves.`,
    );
  }
  const { first, second } = bezierJet(points, dimension, t);
  const speed = checkSpeed(caller, points, first, t);
  if (dimension === 2) return (first[0] * second[1] - first[1] * second[0]) / speed ** 3;
  const [cx, cy, cz] = [
    first[1] * second[2] - first[2] * second[1],
    first[2] * second[0] - first[0] * second[2],
    first[0] * second[1] - first[1] * second[0],
  ];
  return Math.sqrt(cx * cx + cy * cy + cz * cz) / speed ** 3;
}

/**
 * Returns |P′(t)|, or throws a RangeError when it is zero relative to the size
 * of the control polygon (rounding cannot tell a direction there). Internal.
 */
export function checkSpeed(
  caller: string,
  points: readonly Point[],
  first: Point,
  t: number,
): number {
  let speedSquared = 0;
  for (let d = 0; d < first.length; d++) speedSquared += first[d] * first[d];
  const speed = Math.sqrt(speedSquared);
  let extent = 0;
  for (let i = 1; i < points.length; i++) {
    for (let d = 0; d < first.length; d++) {
      extent = Math.max(extent, Math.abs(points[i][d] - points[0][d]));
    }
  }
  if (!(speed > 1e-12 * (points.length - 1) * extent)) {
    throw new RangeError(
      `${caller}: the curve has zero speed at t = ${t} (P′(t) = 0, e.g. coincident control points or a cusp), so its direction and curvature are undefined there; try another t or move the control points apart.`,
    );
  }
  return speed;
}
