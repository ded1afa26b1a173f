// Cutting a sampled curve y(t) to a horizontal band, as a function plot with a
// fixed range does: the pieces inside low ≤ y ≤ high, each ending exactly on
// the edge it crosses (linear interpolation between the samples).

/**
 * The pieces of an interleaved polyline `[x0, y0, x1, y1, …]` that lie in
 * `low ≤ y ≤ high`, each as its own interleaved Float64Array, with the points
 * where it crosses the band's edges added. A piece needs two points.
 */
export function clipToBand(curve: ArrayLike<number>, low: number, high: number): Float64Array[] {
  const pieces: Float64Array[] = [];
  let current: number[] = [];
  const inBand = (y: number) => y >= low && y <= high;
  // Where the segment from (x0, y0) to (x1, y1) meets the edge it crosses.
  const edge = (x0: number, y0: number, x1: number, y1: number) => {
    const bound = y1 > high || y0 > high ? high : low;
    const s = (bound - y0) / (y1 - y0);
    return [x0 + s * (x1 - x0), bound];
  };
  for (let i = 0; i + 1 < curve.length; i += 2) {
    const x = curve[i];
    const y = curve[i + 1];
    const inside = inBand(y);
    if (i > 0) {
      const xp = curve[i - 2];
      const yp = curve[i - 1];
      const wasInside = inBand(yp);
      if (wasInside && !inside) {
        current.push(...edge(xp, yp, x, y));
        if (current.length >= 4) pieces.push(Float64Array.from(current));
        current = [];
      } else if (!wasInside && inside) current.push(...edge(x, y, xp, yp));
    }
    if (inside) current.push(x, y);
  }
  if (current.length >= 4) pieces.push(Float64Array.from(current));
  return pieces;
}
