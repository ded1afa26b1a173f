import type { Point2 } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

/** Everything the de Casteljau lesson shows, and all of it goes in the link. */
export interface DeCasteljauState {
  /** Control points P0 … Pn. */
  p: Point2[];
  t: number;
  /** Levels of the construction shown: 0 (control polygon) … n (the point on the curve). */
  step: number;
  /** Show the two control polygons that subdivision at t produces. */
  split: boolean;
}

export const MAX_POINTS = 16;

/** The lecture's cubic. */
export const LECTURE_CUBIC: Point2[] = [
  [0, 0],
  [1, 2],
  [3, 2],
  [4, 0],
];

export const schema: Schema<DeCasteljauState> = {
  p: { kind: 'points', default: LECTURE_CUBIC, min: 2, max: MAX_POINTS },
  t: { kind: 'number', default: 0.4, min: 0, max: 1 },
  step: { kind: 'int', default: 3, min: 0, max: MAX_POINTS - 1 },
  split: { kind: 'bool', default: false },
};

/** Degree of the curve. */
export const degree = (state: DeCasteljauState) => state.p.length - 1;

/** Inserts `at` into the polygon edge it is closest to, so the curve changes least. */
export function insertPoint(points: readonly Point2[], at: Point2): Point2[] {
  let best = points.length;
  let bestDistance = Infinity;
  for (let i = 0; i + 1 < points.length; i++) {
    const d = distanceToSegment(at, points[i], points[i + 1]);
    if (d < bestDistance) {
      bestDistance = d;
      best = i + 1;
    }
  }
  const endDistance = Math.min(dist(at, points[0]), dist(at, points[points.length - 1]));
  if (endDistance < bestDistance)
    best = dist(at, points[0]) < dist(at, points[points.length - 1]) ? 0 : points.length;
  return [...points.slice(0, best), at, ...points.slice(best)];
}

const dist = (a: Point2, b: Point2) => Math.hypot(a[0] - b[0], a[1] - b[1]);

function distanceToSegment(p: Point2, a: Point2, b: Point2): number {
  const dx = b[0] - a[0];
  const dy = b[1] - a[1];
  const length2 = dx * dx + dy * dy;
  const s =
    length2 === 0
      ? 0
      : Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2));
  return Math.hypot(p[0] - a[0] - s * dx, p[1] - a[1] - s * dy);
}
