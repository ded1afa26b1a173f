import type { Random } from '../../kit/exercise';
import { pointWords, sub } from '../../kit/format';
import type { Point } from '../../math';
import { construction } from './script';
import type { DeCasteljauState } from './state';

// What the de Casteljau exercises pose and open on: an arch of integer
// points, values of t to work with by hand, the points in words, and the
// construction shown from its polygon only or walked to its end.

/** Values of t a student can multiply by hand. */
export const FRIENDLY_T = [0.2, 0.25, 0.3, 0.4, 0.6, 0.7, 0.75, 0.8];

/** "P₀ = (0, 1), P₁ = (2, 3), …": the control points, to work with by hand. */
export const listText = (p: readonly Point[]) =>
  p.map((q, i) => `P${sub(i)} = ${pointWords(q)}`).join(', ');

/**
 * A control polygon with integer corners that climbs and comes back down:
 * the ends are lower than every inner point, so the points are never on one
 * line and no two neighbours share a spot.
 */
export function arch(r: Random, degree: 2 | 3): Point[] {
  if (degree === 2)
    return [
      [0, r.int(0, 1)],
      [r.int(1, 4), r.int(3, 4)],
      [r.int(5, 6), r.int(0, 1)],
    ];
  return [
    [0, r.int(0, 1)],
    [r.int(0, 2), r.int(2, 4)],
    [r.int(3, 5), r.int(2, 4)],
    [r.int(5, 6), r.int(0, 1)],
  ];
}

/** The construction of these points at t, walked from the points to the curve. */
export const walked = (defaults: DeCasteljauState, p: Point[], t: number): DeCasteljauState => {
  const s: DeCasteljauState = { ...defaults, p, t, mode: 'construction' };
  return { ...s, step: construction.lastStep(s) };
};

/** The control polygon only (step 1): no level cut yet, no P(t), no curve. */
export const polygonOnly = (
  defaults: DeCasteljauState,
  p: Point[],
  t: number,
): DeCasteljauState => ({
  ...defaults,
  p,
  t,
  mode: 'construction',
  step: construction.stepOf({ ...defaults, p, t }, 'polygon'),
});
