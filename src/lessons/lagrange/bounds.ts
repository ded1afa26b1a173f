/**
 * The bounds of the two figures: the curve's "fit view" (the points, and the
 * polynomial's swings up to a point) and the basis plot's range (up to ±CLIP).
 */
import type { BasisSamples, Point } from '../../math';
import { type Bounds, boundsOf } from '../../render/projection';

/** The plot shows L_k between ±CLIP; beyond, the curves are cut and the figure says so. */
export const CLIP = 3;

/** The curve figure's "fit view", with room above the points for a note about them. */
export function curveBounds(p: readonly Point[], curve: Float64Array, note: boolean): Bounds {
  // The view fits the subject: the points, and the polynomial only as far as
  // it stays near them (half the points' smaller side, or a fifth of the
  // larger). A wild polynomial leaves the view, which is the lesson; the
  // legend is not given room of its own, so the points stay large.
  const points = boundsOf(p);
  const width = points.maxX - points.minX;
  const height = points.maxY - points.minY;
  const reach = 0.3 * Math.max(Math.min(width, height), 0.25 * Math.max(width, height), 1);
  let [minX, maxX, minY, maxY] = [points.minX, points.maxX, points.minY, points.maxY];
  for (let i = 0; i < curve.length; i += 2) {
    minX = Math.min(minX, curve[i]);
    maxX = Math.max(maxX, curve[i]);
    minY = Math.min(minY, curve[i + 1]);
    maxY = Math.max(maxY, curve[i + 1]);
  }
  const bounds = {
    minX: Math.max(points.minX - reach, minX),
    maxX: Math.min(points.maxX + reach, maxX),
    minY: Math.max(points.minY - reach, minY),
    maxY: Math.min(points.maxY + reach, maxY),
  };
  // A note about the points (on one line, on one spot) is read before the figure: room for it.
  return note ? { ...bounds, maxY: bounds.maxY + 0.7 * (bounds.maxY - bounds.minY || 1) } : bounds;
}

/** From a little below 0 to a little above 1, and as far as the L_k swing, up to ±CLIP. */
export function basisBounds({ lowest, highest }: BasisSamples): Bounds {
  const low = Math.min(-0.3, lowest.value);
  const high = Math.max(1.2, highest.value);
  return { minX: 0, maxX: 1, minY: Math.max(-CLIP, low * 1.05), maxY: Math.min(CLIP, high * 1.05) };
}
