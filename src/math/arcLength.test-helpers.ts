import { sampleBezier } from './bezier';
import type { Point } from './vec';

/** The length of the polyline through `segments + 1` uniform samples (a lower bound converging to the arc length). */
export function arcLengthByPolyline(points: readonly Point[], segments: number): number {
  const dimension = points[0].length;
  const samples = sampleBezier(points, segments);
  let length = 0;
  for (let i = 1; i <= segments; i++) {
    let squared = 0;
    for (let d = 0; d < dimension; d++) {
      const difference = samples[i * dimension + d] - samples[(i - 1) * dimension + d];
      squared += difference * difference;
    }
    length += Math.sqrt(squared);
  }
  return length;
}
