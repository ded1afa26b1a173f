import { type Point, sampleBezier } from '../../math';

/** What the model of every experiment holds. */
export interface ExperimentBase {
  /** The control points of the curve drawn: the user's points, repeated, closed or elevated. */
  controls: Point[];
  /** Points the view must show besides the control points (arrow tips, images, the "before" curve). */
  extra: Point[];
}

/** Samples enough for a smooth curve of degree n. */
export const samplesFor = (n: number) => Math.max(96, 24 * n);

/** The Bézier curve of `points`, sampled for drawing (interleaved x, y). */
export const sampleCurve = (points: readonly Point[]) =>
  sampleBezier(points, samplesFor(points.length - 1));

/**
 * What 0, 1, 2, … elevations, splits or copies give, each made the first time
 * a step asks for it and kept: stepping back and forth costs no new curve.
 */
export function byCount<T>(make: (count: number) => T): (count: number) => T {
  const made: T[] = [];
  return (count) => (made[count] ??= make(count));
}
