import { pointList } from '../../kit/pointList';
import type { QuadraticState } from './state';

/** P₀, P₁, P₂: dragged and moved by keyboard; always three of them. */
export const threePoints = pointList<QuadraticState>({
  id: 'p',
  get: (s) => s.points,
  set: (s, points) => ({ ...s, points }),
  label: (i) => `P_${i}`,
  min: 3,
  max: 3,
});
