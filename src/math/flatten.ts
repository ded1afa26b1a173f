import { splitBezier } from './bezier';
import { checkPoints } from './checkPoints';
import type { Point } from './vec';

// Flattening by adaptive bisection. A Bézier curve of degree n stays within
// n(n−1)/8 · max‖P(i+2) − 2P(i+1) + Pi‖ of its chord, point for point in t
// (Wang 1984; Filip, Magedson & Markot 1986). Subdividing to a piece of
// parameter length h scales the second differences by h², so bisecting until
// each piece passes the bound needs at most 2N pieces, where N is the uniform
// count ⌈√(n(n−1)·max‖Δ²P‖ / (8·tolerance))⌉, and fewer where the curve is flat.

/**
 * A polyline from exactly P0 to exactly Pn whose vertices lie on the curve and
 * which stays within `tolerance` of it (every curve point within tolerance of
 * the polyline and vice versa), with at most `4N + 16` points for the uniform
 * count N above. `tolerance ≤ 0` is a RangeError.
 */
export function flattenBezier(points: readonly Point[], tolerance: number): Point[] {
  const caller = 'flattenBezier';
  checkPoints(caller, 'points', points, 1);
  if (typeof tolerance !== 'number' || !(tolerance > 0) || !Number.isFinite(tolerance)) {
    throw new RangeError(
      `${caller}: tolerance = ${tolerance}; it must be a positive finite distance, such as 0.25 pixels.`,
    );
  }
  const n = points.length - 1;
  const first = points[0].slice();
  if (n === 0) return [first];
  const maximumDepth = flatteningDepth(points, tolerance);
  const polyline: Point[] = [first];
  const stack: { piece: readonly Point[]; depth: number }[] = [{ piece: points, depth: 0 }];
  while (stack.length > 0) {
    const { piece, depth } = stack.pop() as { piece: readonly Point[]; depth: number };
    if (depth >= maximumDepth || flatness(piece) <= tolerance) {
      polyline.push(piece[n].slice());
      continue;
    }
    const [left, right] = splitBezier(piece, 0.5);
    // Right first so the left half is flattened first.
    stack.push({ piece: right, depth: depth + 1 }, { piece: left, depth: depth + 1 });
  }
  return polyline;
}

/**
 * n(n−1)/8 · max‖P(i+2) − 2P(i+1) + Pi‖: no point of the piece is further than
 * this from its chord. The split test of flattenBezier and flatteningTree.
 */
export function flatness(piece: readonly Point[]): number {
  const n = piece.length - 1;
  return (n * (n - 1) * secondDifference(piece)) / 8;
}

/**
 * The depth at which flattening stops splitting: rounding can keep a piece
 * above a tolerance far below the coordinates' precision, so stop at the
 * depth the uniform count would need (and at most 50 halvings).
 */
export function flatteningDepth(points: readonly Point[], tolerance: number): number {
  const uniformCount = Math.ceil(Math.sqrt(flatness(points) / tolerance));
  return Math.min(50, Math.ceil(Math.log2(Math.max(1, uniformCount))) + 1);
}

/** max‖P(i+2) − 2P(i+1) + Pi‖ over the control polygon. */
function secondDifference(points: readonly Point[]): number {
  let maximum = 0;
  for (let i = 0; i + 2 < points.length; i++) {
    let squared = 0;
    for (let d = 0; d < points[i].length; d++) {
      const value = points[i + 2][d] - 2 * points[i + 1][d] + points[i][d];
      squared += value * value;
    }
    maximum = Math.max(maximum, squared);
  }
  return Math.sqrt(maximum);
}
