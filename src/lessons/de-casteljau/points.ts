import { pointList } from '../../kit/pointList';
import { type DeCasteljauState, MAX_POINTS } from './state';
import { scriptOf } from './walks';

/** The control points P₀ … Pₙ: dragged, moved by keyboard, added and removed. */
export const controlPoints = pointList<DeCasteljauState>({
  id: 'p',
  get: (s) => s.p,
  set: (s, p) => ({ ...s, p }),
  label: (i) => `P_{${i}}`,
  min: 2,
  max: MAX_POINTS,
  // A walk shown to its end stays shown to its end.
  after: (before, after) => scriptOf(before).keptAtEnd(before, after, 'step'),
});
