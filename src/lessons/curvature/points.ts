import type { Point } from '../../math';
import { type PointList, pointList } from '../../kit/pointList';
import { MAX_LINKED_POINTS } from '../../kit/lessonLinks';
import type { CurvatureState } from './state';

/**
 * Two things differ from the kit's list, and are kept from before: the lesson
 * takes the points it is given (another lesson's link, a scene) and neither
 * adds nor removes one; and each point keeps its own label, even on one spot
 * as another.
 */
function asBefore(
  list: PointList<CurvatureState>,
  label: (i: number) => string,
): PointList<CurvatureState> {
  return {
    ...list,
    resizable: false,
    handles: (state: CurvatureState) =>
      list.handles(state).map((handle, i) => ({ ...handle, label: label(i), showLabel: true })),
    add: () => null,
    remove: () => null,
  };
}

const planeName = (i: number) => `P_{${i}}`;

/** The plane curve's points P0 … Pm (parts plane and arc). */
export const planePoints = asBefore(
  pointList<CurvatureState>({
    id: 'p',
    get: (s) => (s.part === 'space' ? [] : s.points),
    set: (s, points) => ({ ...s, points }),
    constrain: (_, __, to) => [to[0], to[1]],
    label: planeName,
    min: 2,
    max: MAX_LINKED_POINTS,
  }),
  planeName,
);

/** The Hermite gradients' handles Pi + Di/3, the inner Bézier control points (none for other sources). */
export function gradientTips(state: CurvatureState): Point[] {
  const { source, part, points, gradients } = state;
  if (source !== 'hermite' || part !== 'plane' || gradients.length !== points.length) return [];
  return points.map((p, i) => [p[0] + gradients[i][0] / 3, p[1] + gradients[i][1] / 3]);
}

const gradientName = (i: number) => `P_{${i}} + D_{${i}}/3`;

/** A Hermite spline's gradients Di, dragged by their tips Pi + Di/3. */
export const gradientHandles = asBefore(
  pointList<CurvatureState>({
    id: 'd',
    get: gradientTips,
    // Only the moved tip's gradient changes: the others keep their values exactly.
    set: (s, tips) => {
      const before = gradientTips(s);
      const moved = (i: number) => tips[i][0] !== before[i][0] || tips[i][1] !== before[i][1];
      return {
        ...s,
        gradients: s.gradients.map((d, i) =>
          moved(i) ? [3 * (tips[i][0] - s.points[i][0]), 3 * (tips[i][1] - s.points[i][1])] : d,
        ),
      };
    },
    label: gradientName,
    style: () => ({ small: true }),
    min: 0,
    max: MAX_LINKED_POINTS,
  }),
  gradientName,
);

const spaceName = (i: number) => `Q_{${i}}`;
/** The space cubic's control points, where there is one (part space, curve bezier). */
const spaceCubic = (s: CurvatureState) =>
  s.part === 'space' && s.spaceCurve === 'bezier' ? s.spacePoints : [];

/** The space cubic's Q0 … Q3 in space: Shift moves one along an axis. */
export const spacePoints = asBefore(
  pointList<CurvatureState>({
    id: 'q',
    get: spaceCubic,
    set: (s, spacePoints) => ({ ...s, spacePoints }),
    constrain: (s, i, to) => [to[0], to[1], to[2] ?? s.spacePoints[i][2]],
    label: spaceName,
    style: () => ({ shape: 'square' }),
    min: 4,
    max: 4,
  }),
  spaceName,
);

/** The same Q0 … Q3 in the top view: moved in x and y, each keeps its height z. */
export const topViewPoints = asBefore(
  pointList<CurvatureState>({
    id: 'q',
    get: (s) => spaceCubic(s).map((q) => [q[0], q[1]]),
    set: (s, flat) => ({
      ...s,
      spacePoints: s.spacePoints.map((q, i) => [flat[i][0], flat[i][1], q[2]]),
    }),
    label: spaceName,
    style: () => ({ shape: 'square' }),
    min: 4,
    max: 4,
  }),
  spaceName,
);
