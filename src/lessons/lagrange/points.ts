import { type PointList, pointList } from '../../kit/pointList';
import { keepShownToEnd } from './script';
import { type LagrangeState, MAX_POINTS } from './state';

/** Every point is labelled up to this many; beyond, only the first and the last. */
const LABEL_ALL_UP_TO = 9;

const name = (i: number) => `P_{${i}}`;

const declared = pointList<LagrangeState>({
  id: 'p',
  get: (s) => s.points,
  set: (s, points) => ({ ...s, points }),
  label: name,
  min: 2,
  max: MAX_POINTS,
  // The script shown to its end stays shown to its end.
  after: keepShownToEnd,
  addLabel: 'Add a point',
  removeLabel: 'Remove the last point',
});

/**
 * The points P0 … Pn to pass through: dragged, moved by keyboard, added and
 * removed. Two things differ from the kit's list, and are kept from before:
 * - each point keeps its own label, even on one spot as another (the figure
 *   and the notes say what coincident points do); with many points, only the
 *   ends are named, so the labels stay readable;
 * - a double-click adds a point after the last, not into the nearest edge:
 *   the order of the points is the order of their tₖ.
 */
export const interpolatedPoints: PointList<LagrangeState> = {
  ...declared,
  handles: (state) =>
    declared.handles(state).map((handle, i, all) => ({
      ...handle,
      label: name(i),
      showLabel: all.length <= LABEL_ALL_UP_TO || i === 0 || i === all.length - 1,
    })),
  add(state, at) {
    if (state.points.length >= MAX_POINTS) return null;
    return keepShownToEnd(state, { ...state, points: [...state.points, [at[0], at[1]]] });
  },
};
