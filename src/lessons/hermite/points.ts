import type { Point } from '../../math';
import { type PointList, pointList } from '../../kit/pointList';
import { ARROW_SCALE, spline } from './model';
import { keptAtEnd, shownAt } from './script';
import { type HermiteState, MAX_POINTS } from './state';

/**
 * After a point is added or removed: the gradients follow the points (a new
 * last point heads away from the one before it), the chosen patch stays a
 * patch, and a script shown to its end stays shown to its end.
 */
function followPoints(before: HermiteState, after: HermiteState): HermiteState {
  const { points } = after;
  const n = points.length;
  const last = before.points[before.points.length - 1];
  const handGradients =
    n > before.handGradients.length
      ? [...before.handGradients, [points[n - 1][0] - last[0], points[n - 1][1] - last[1]]]
      : before.handGradients.slice(0, n);
  const next = { ...after, handGradients, patch: Math.min(before.patch, n - 2) };
  return keptAtEnd(before, next);
}

const chain = pointList<HermiteState>({
  id: 'p',
  get: (s) => s.points,
  set: (s, points) => ({ ...s, points }),
  label: (i) => `P_{${i}}`,
  min: 2,
  max: MAX_POINTS,
  after: followPoints,
  addLabel: 'Add a point',
  removeLabel: 'Remove the last point',
});

/**
 * The points P0 … Pm, each with its gradient: moved, added and removed
 * together. A chain grows at its end, so a point is added after the last
 * one (not into the nearest edge, as a control polygon is).
 */
export const controlPoints: PointList<HermiteState> = {
  ...chain,
  add: (s, at) =>
    s.points.length >= MAX_POINTS
      ? null
      : followPoints(s, { ...s, points: [...s.points, [at[0], at[1]]] }),
  // The point's own gradient goes with it.
  remove: (s, index) =>
    chain.remove({ ...s, handGradients: s.handGradients.filter((_, k) => k !== index) }, index),
};

const same = (a: Point, b: Point) => a[0] === b[0] && a[1] === b[1];

/**
 * The gradients' arrow tips Pk + Dk/3, handles from the step that shows the
 * gradients. Dragging a tip sets D = 3 (tip − P), and an automatic gradient
 * becomes a hand-set one. Tips come and go with their points: never added
 * or removed on their own.
 */
export const gradientTips = pointList<HermiteState>({
  id: 'd',
  get: (s) => (shownAt(s).has('gradients') ? spline(s).tips : []),
  set(s, tips) {
    const { gradients, tips: before } = spline(s);
    const handGradients = gradients.map((d, k): Point => {
      if (same(tips[k], before[k])) return d;
      const p = s.points[k];
      return [(tips[k][0] - p[0]) / ARROW_SCALE, (tips[k][1] - p[1]) / ARROW_SCALE];
    });
    return { ...s, mode: 'hand', handGradients };
  },
  label: (i) => `D_{${i}}`,
  style: () => ({ shape: 'square' }),
  min: Infinity,
  max: 0,
});
