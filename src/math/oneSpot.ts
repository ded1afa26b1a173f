/**
 * Are all the points on one spot? Each coordinate of each point within a
 * relative 1e-12 of the first point's (relative to the largest coordinate in
 * play, so a net a million units out and a net at the origin are judged
 * alike). Any dimension; no points, or one, is trivially one spot.
 */
export function onOneSpot(points: readonly (readonly number[])[]): boolean {
  if (points.length < 2) return true;
  const first = points[0];
  const size = Math.max(1, ...points.flatMap((p) => p.map(Math.abs)));
  const tolerance = 1e-12 * size;
  return points.every((p) => p.every((v, i) => Math.abs(v - first[i]) <= tolerance));
}
