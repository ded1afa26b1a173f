/**
 * Editing a list of points the way a person sketches: a new point goes into
 * the polygon edge it is nearest (so the curve changes least), or continues
 * the polygon past its last edge. Pure geometry, no DOM.
 */
import type { Point } from '../math';

/**
 * Inserts `at` into the polygon edge it is closest to; where the closest spot
 * of the polygon is its first or its last point, before or after it instead.
 */
export function insertPoint<P extends Point>(points: readonly P[], at: P): P[] {
  if (points.length < 2) return [...points, at];
  let best = 1;
  let bestDistance = Infinity;
  let bestAlong = 0;
  for (let i = 0; i + 1 < points.length; i++) {
    const along = projectOnSegment(at, points[i], points[i + 1]);
    const d = distance(at, along.point);
    if (d < bestDistance) {
      bestDistance = d;
      best = i + 1;
      bestAlong = along.s;
    }
  }
  if (best === 1 && bestAlong === 0) best = 0;
  else if (best === points.length - 1 && bestAlong === 1) best = points.length;
  return [...points.slice(0, best), at, ...points.slice(best)];
}

/**
 * Where an "add a point" button puts the next point: past the last edge,
 * continuing it at 70 % of its length and turning a little left, so repeated
 * additions curl instead of running off in a straight line.
 */
export function extendPolygon(points: readonly Point[]): [number, number] {
  const b = points[points.length - 1] ?? [0, 0];
  const a = points[points.length - 2] ?? [b[0] - 1, b[1]];
  let dx = b[0] - a[0];
  let dy = b[1] - a[1];
  if (dx === 0 && dy === 0) [dx, dy] = [1, 0];
  return [b[0] + 0.7 * dx - 0.25 * dy, b[1] + 0.7 * dy + 0.25 * dx];
}

export function distance(a: readonly number[], b: readonly number[]): number {
  return Math.hypot(a[0] - b[0], a[1] - b[1]);
}

/** The point of segment ab nearest to p, and where it lies along ab (0 at a, 1 at b). */
export function projectOnSegment(
  p: readonly number[],
  a: readonly number[],
  b: readonly number[],
): { point: [number, number]; s: number } {
  const dx = b[0] - a[0];
  const dy = b[1] - a[1];
  const length2 = dx * dx + dy * dy;
  const s =
    length2 === 0
      ? 0
      : Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2));
  return { point: [a[0] + s * dx, a[1] + s * dy], s };
}

export function distanceToSegment(
  p: readonly number[],
  a: readonly number[],
  b: readonly number[],
): number {
  return distance(p, projectOnSegment(p, a, b).point);
}
