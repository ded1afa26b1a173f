import { type PointList, pointList } from '../../kit/pointList';
import type { Point } from '../../math';
import { type BSplineState, CONTINUITY_POINTS, MAX_POINTS, refitKnots } from './state';

/**
 * A list whose points keep their own labels even on one spot: the lesson
 * names every point apart (the circle's P0 and P8 share a spot, each labelled).
 */
function labelledApart<S>(list: PointList<S>, label: (i: number) => string): PointList<S> {
  return {
    ...list,
    handles: (state) =>
      list.handles(state).map((handle, i) => ({ ...handle, label: label(i), showLabel: true })),
  };
}

/**
 * Where an edit of the list put or took a point: the first point that is not
 * the same object as before (an edit keeps the other points as they were).
 */
function editedAt(before: readonly Point[], after: readonly Point[]): number {
  const at = after.findIndex((point, i) => point !== before[i]);
  return at < 0 ? after.length : at;
}

/** The state with new control points; a point added or removed takes its weight and "before" point along. */
function withPoints(state: BSplineState, points: Point[]): BSplineState {
  const count = state.points.length;
  if (points.length === count) return { ...state, points };
  const at = editedAt(state.points, points);
  const added = points.length > count;
  const weights = added
    ? [...state.weights.slice(0, at), 1, ...state.weights.slice(at)]
    : state.weights.filter((_, i) => i !== at);
  const before = added
    ? [...state.before.slice(0, at), points[at], ...state.before.slice(at)]
    : state.before.filter((_, i) => i !== at);
  // Knots that fit the new number of points: clamped if they were, else uniform.
  const knots = refitKnots(state.knots, points.length, state.degree);
  return { ...state, points, before, weights, knots };
}

const label = (i: number) => `P_{${i}}`;
const list = pointList<BSplineState>({
  id: 'p',
  get: (s) => s.points,
  set: withPoints,
  label,
  // A cubic needs four points (the closed one too, once edited).
  min: 4,
  max: MAX_POINTS,
  constrain: (_s, _i, to) => [to[0], to[1]],
});

/** The control points P0 … Pm: dragged, moved by keyboard, added and removed. */
export const controlPoints: PointList<BSplineState> = {
  ...labelledApart(list, label),
  // Degree p needs p + 1 points; the continuity scene's triple knot needs seven.
  remove: (state, index) =>
    state.points.length <= state.degree + 1 ||
    (state.part === 'continuity' && state.points.length <= CONTINUITY_POINTS)
      ? null
      : list.remove(state, index),
};

/** The two points of the line that tests variation diminishing (square handles). */
export const linePoints = labelledApart(
  pointList<BSplineState>({
    id: 'l',
    get: (s) => s.line,
    set: (s, line) => ({ ...s, line }),
    label: (i) => `L_{${i}}`,
    min: 2,
    max: 2,
    constrain: (_s, _i, to) => [to[0], to[1]],
    style: () => ({ shape: 'square' }),
  }),
  (i) => `L_{${i}}`,
);
