import { cubicSelfIntersection } from './cubicSelfIntersection';
import { bezierPoint, sampleBezier } from './bezier';
import type { Point } from './vec';

// Where a chain of 2D cubic Bézier pieces (a spline) crosses itself: a loop
// inside one piece (exact, cubicSelfIntersection) or two pieces that are not
// neighbours crossing (their flattened polylines, fine enough for a figure).

/** The crossing points of the chain, empty when it is a simple curve. */
export function bezierChainSelfIntersections(segments: readonly (readonly Point[])[]): Point[] {
  const crossings: Point[] = [];
  for (const piece of segments) {
    const loop = cubicSelfIntersection(piece);
    if (loop) crossings.push(bezierPoint(piece, loop[0]));
  }
  const samples = segments.map((piece) => sampleBezier(piece, 96));
  for (let i = 0; i < segments.length; i++) {
    for (let j = i + 2; j < segments.length; j++) {
      crossings.push(...polylineCrossings(samples[i], samples[j]));
    }
  }
  return crossings;
}

/** Crossings of two polylines given as interleaved x, y. */
function polylineCrossings(a: Float64Array, b: Float64Array): Point[] {
  const found: Point[] = [];
  for (let i = 0; i + 3 < a.length; i += 2) {
    for (let j = 0; j + 3 < b.length; j += 2) {
      const [x1, y1, x2, y2] = [a[i], a[i + 1], a[i + 2], a[i + 3]];
      const [x3, y3, x4, y4] = [b[j], b[j + 1], b[j + 2], b[j + 3]];
      const denominator = (x2 - x1) * (y4 - y3) - (y2 - y1) * (x4 - x3);
      if (denominator === 0) continue;
      const u = ((x3 - x1) * (y4 - y3) - (y3 - y1) * (x4 - x3)) / denominator;
      const v = ((x3 - x1) * (y2 - y1) - (y3 - y1) * (x2 - x1)) / denominator;
      if (u >= 0 && u < 1 && v >= 0 && v < 1) found.push([x1 + u * (x2 - x1), y1 + u * (y2 - y1)]);
    }
  }
  return found;
}
