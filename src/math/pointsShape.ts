import { type Point, distance, subtract } from './vec';

/**
 * How degenerate a list of 2D points is, for the lessons to say so in words:
 * all on one spot, all on one line, two neighbours on one spot (the first
 * such pair, P_i and P_{i+1}), or none of these. Distances are compared
 * relative to the list's size, so the answer is the same at any scale.
 */
export type PointsShape =
  | { kind: 'one spot' }
  | { kind: 'one line' }
  | { kind: 'neighbours on one spot'; index: number }
  | { kind: 'general' };

const cross = (a: Point, b: Point) => a[0] * b[1] - a[1] * b[0];

export function pointsShape(p: readonly Point[]): PointsShape {
  const size = Math.max(1e-300, ...p.map((q) => distance(q, p[0])));
  const tolerance = 1e-12 * size;
  const coincide = (a: Point, b: Point) => distance(a, b) <= tolerance;
  if (p.every((q) => coincide(q, p[0]))) return { kind: 'one spot' };
  // Collinear: every point on the line through P0 and the point farthest from it.
  const far = p.reduce((best, q) => (distance(q, p[0]) > distance(best, p[0]) ? q : best));
  const direction = subtract(far, p[0]);
  if (p.every((q) => Math.abs(cross(direction, subtract(q, p[0]))) <= tolerance * size))
    return { kind: 'one line' };
  const index = p.slice(1).findIndex((q, i) => coincide(q, p[i]));
  return index >= 0 ? { kind: 'neighbours on one spot', index } : { kind: 'general' };
}
