import { insertPoint } from '../../interact/editPoints';
import { stackedLabels } from '../../kit/labels';
import { type PointList, pointList } from '../../kit/pointList';
import type { Point } from '../../math';
import { MAX_POINTS, type PropertiesState, copy, needsCubic } from './state';

const list = pointList<PropertiesState>({
  id: 'p',
  get: (s) => s.points,
  set: (s, points) => ({ ...s, points }),
  label: (i) => `P_{${i}}`,
  min: 2,
  max: MAX_POINTS,
});

/** A new set of points makes a new curve: it becomes the "before" of the local-control experiment. */
const withPoints = (state: PropertiesState, points: Point[]): PropertiesState => ({
  ...state,
  points,
  before: state.experiment === 'local' ? copy(points) : state.before,
});

/**
 * The control points P₀ … Pₙ: dragged and moved by keyboard through the kit's
 * list. Three things are the lesson's own, which the kit's list cannot say
 * yet: the closed curve names P₀ also as Pₙ₊₁ (a label that depends on the
 * state); the cubic experiments neither add nor remove a point, and a closed
 * curve keeps three; and removing a point moves the index of the repeated one.
 */
export const controlPoints: PointList<PropertiesState> = {
  ...list,
  handles(state) {
    const { points } = state;
    const name = (i: number) =>
      state.experiment === 'closed' && i === 0 ? `P_0 = P_{${points.length}}` : `P_{${i}}`;
    const labels = stackedLabels(points, name);
    return points.map((position, i) => ({ id: `p${i}`, ...labels[i], position }));
  },
  add(state, at) {
    if (needsCubic(state.experiment) || state.points.length >= MAX_POINTS) return null;
    return withPoints(state, insertPoint(state.points, at));
  },
  remove(state, index) {
    const fewest = state.experiment === 'closed' ? 3 : 2;
    if (needsCubic(state.experiment) || state.points.length <= fewest) return null;
    const points = state.points.filter((_, k) => k !== index);
    const { repeated } = state;
    const r = index < repeated ? repeated - 1 : Math.min(repeated, points.length - 1);
    return { ...withPoints(state, points), repeated: r };
  },
};
