import { type Point, distance, subtract } from '../../math';

const cross = (a: Point, b: Point) => a[0] * b[1] - a[1] * b[0];

/**
 * What the construction does with degenerate control points, in words (null
 * when there is nothing to say): the figure would otherwise draw them
 * without a word.
 */
export function degenerateNote(p: readonly Point[]): string | null {
  const size = Math.max(1e-300, ...p.map((q) => distance(q, p[0])));
  const tolerance = 1e-12 * size;
  const coincide = (a: Point, b: Point) => distance(a, b) <= tolerance;
  if (p.every((q) => coincide(q, p[0]))) {
    return 'All control points are on one spot: every level is that spot, and the “curve” is a single point.';
  }
  // Collinear: every point on the line through P0 and the point farthest from it.
  const far = p.reduce((best, q) => (distance(q, p[0]) > distance(best, p[0]) ? q : best));
  const direction = subtract(far, p[0]);
  const onLine = p.every((q) => Math.abs(cross(direction, subtract(q, p[0]))) <= tolerance * size);
  if (onLine) {
    return 'The control points lie on one line: every level stays on it, so the curve is a piece of that line (it may run back over itself).';
  }
  const same = p.slice(1).flatMap((q, i) => (coincide(q, p[i]) ? [i] : []));
  if (same.length > 0) {
    const i = same[0];
    return `P${i} and P${i + 1} are on one spot: their edge has length 0, so its point on every level is that spot.`;
  }
  return null;
}
