/**
 * What the raster lesson's exercises start from: a scene of the lesson at
 * step 0 with the exercise's control points, and those points listed in words
 * for a prompt.
 */
import { pointWords, sub } from '../../kit/format';
import type { Point } from '../../math';
import type { RasterState, View } from './state';

/** "P₀ (3, 4), P₁ (14, 20) and P₂ (28, 6)": the control points as the prompt lists them. */
export function listed(points: readonly Point[]): string {
  const names = points.map((p, i) => `P${sub(i)} ${pointWords(p)}`);
  return `${names.slice(0, -1).join(', ')} and ${names[names.length - 1]}`;
}

/** A scene of the lesson at step 0 with these control points, at zoom 1 (1 unit = 1 pixel). */
export const sceneState = (
  defaults: RasterState,
  view: View,
  points: Point[],
  change: Partial<RasterState> = {},
): RasterState => ({
  ...defaults,
  view,
  points,
  zoom: 1,
  steppedSegment: 0,
  step: 0,
  ...change,
});
