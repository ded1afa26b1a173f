import { niceStep } from '../../render/projection';
import type { Bounds } from '../../render/projection';
import type { BSplineModel } from './model';

/** The basis plot and the knot strip share this u range: the whole knot vector. */
export function plotRange(m: BSplineModel): [number, number] {
  const first = m.knots[0];
  const last = m.knots[m.knots.length - 1];
  return first < last ? [first, last] : [first - 1, last + 1];
}

export function basisBounds(m: BSplineModel): Bounds {
  const [minX, maxX] = plotRange(m);
  return { minX, maxX, minY: -0.15, maxY: 1.12 };
}

export const uStep = (m: BSplineModel) => {
  const [a, b] = plotRange(m);
  return niceStep((b - a) / 10);
};

/** The u of the cursor for a point dragged to x (kept in the domain), as the slider's t. */
export function tFor(m: BSplineModel, x: number): number {
  const [a, b] = m.domain;
  return Math.min(1, Math.max(0, (x - a) / (b - a)));
}
