import { pointList } from '../../kit/pointList';
import { construction } from './script';
import { type DeCasteljauState, MAX_POINTS } from './state';

/** The control points P₀ … Pₙ: dragged, moved by keyboard, added and removed. */
export const controlPoints = pointList<DeCasteljauState>({
  id: 'p',
  get: (s) => s.p,
  set: (s, p) => ({ ...s, p }),
  label: (i) => `P_{${i}}`,
  min: 2,
  max: MAX_POINTS,
  // A construction shown to its end stays shown to its end.
  after: (before, after) => construction.keptAtEnd(before, after, 'step'),
});
