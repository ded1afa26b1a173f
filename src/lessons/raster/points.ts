import { pointList } from '../../kit/pointList';
import { MAX_POINTS, type RasterState } from './state';

/** The control points P₀ … Pₙ: dragged, moved by keyboard, added and removed. */
export const controlPoints = pointList<RasterState>({
  id: 'p',
  get: (s) => s.points,
  set: (s, points) => ({ ...s, points }),
  label: (i) => `P_{${i}}`,
  min: 2,
  max: MAX_POINTS,
  // Outside the first scene the points only shape the curve: small, so they hide no pixel.
  style: (_, s) => ({ small: s.view !== 'plot' }),
});
