import type { Point } from './vec';

// The nearest point of a segment to a point, and the distance between them:
// the foot of a chord (chordDeviation), the nearest point of a polyline. Any
// dimension; a segment whose ends coincide is that one point.

/** Where the nearest point of segment a–b to p lies along it: 0 at a, 1 at b (0 if a = b). */
function alongSegment(p: ArrayLike<number>, a: Point, b: Point): number {
  let along = 0;
  let length = 0;
  for (let d = 0; d < a.length; d++) {
    along += (p[d] - a[d]) * (b[d] - a[d]);
    length += (b[d] - a[d]) ** 2;
  }
  return length > 0 ? Math.min(1, Math.max(0, along / length)) : 0;
}

/** The nearest point of segment a–b to p. */
export function nearestOnSegment(p: Point, a: Point, b: Point): Point {
  const s = alongSegment(p, a, b);
  return a.map((value, d) => value + s * (b[d] - value));
}

/** The distance from p to segment a–b: nearestOnSegment and distanceBetween's arithmetic, without the arrays. */
export function distanceToChord(p: ArrayLike<number>, a: Point, b: Point): number {
  const s = alongSegment(p, a, b);
  let squared = 0;
  for (let d = 0; d < a.length; d++) {
    const foot = a[d] + s * (b[d] - a[d]);
    squared += (p[d] - foot) ** 2;
  }
  return Math.sqrt(squared);
}
