import { pointList } from '../../kit/pointList';
import { keepShownToEnd } from './script';
import { type BlendingState, MAX_POINTS } from './state';

/** The control points P₀ … P_N: dragged, moved by keyboard, added and removed. */
export const controlPoints = pointList<BlendingState>({
  id: 'p',
  get: (s) => s.p,
  set: (s, p) => ({ ...s, p }),
  label: (i) => `P_{${i}}`,
  min: 2,
  max: MAX_POINTS,
  addLabel: 'N + 1: add a control point',
  removeLabel: 'N − 1: remove the last point',
  // A script shown to its end stays shown to its end.
  after: keepShownToEnd,
});
