import type { Handle } from '../../app/lesson';
import { type PointList, pointList } from '../../kit/pointList';
import type { Point } from '../../math';
import { sceneOf, shownIn } from './scenes';
import type { SurfaceState } from './state';

// The movable points: the 16 control points Pₘ,ₙ of the net, and in the scene of
// two patches the rows Q₁ … Q₃ of the second net (its row Q₀ sits on P₃: it
// is edited in the table, so the edge's points stay one handle each). The
// handles' ids stay 'x' and 'y' (the links' keys); only their names are P and Q.

const COLUMNS = 4;
/** Row by row, as the link writes the net. */
const flat = (net: readonly (readonly Point[])[]): Point[] => net.flat();
const grid = (points: readonly Point[]): Point[][] =>
  Array.from({ length: points.length / COLUMNS }, (_, m) =>
    points.slice(m * COLUMNS, (m + 1) * COLUMNS),
  );
/** Row and column of the i-th point of a net written row by row. */
const place = (i: number) => ({ row: Math.floor(i / COLUMNS), column: i % COLUMNS });

/**
 * A net's handles, each with its own label (not one label for points on one
 * spot, as the kit gives: the lesson names every point apart) and small dots.
 */
function netHandles<S>(
  list: PointList<S>,
  label: (i: number) => string,
  showLabel: (state: S, i: number) => boolean,
): PointList<S> {
  return {
    ...list,
    handles: (state): Handle[] =>
      list.handles(state).map((handle, i) => ({
        ...handle,
        label: label(i),
        showLabel: showLabel(state, i),
      })),
  };
}

const netLabel = (i: number) => `P_{${place(i).row},${place(i).column}}`;
const isCorner = (i: number) => {
  const { row, column } = place(i);
  return (row === 0 || row === 3) && (column === 0 || column === 3);
};

/**
 * Which points of the net are named: every one while the net itself is the
 * subject (the patch's first steps), then its four corners (none beside a
 * second patch). The figure places the names (netLabels.ts) clear of one
 * another and of the points: names at one fixed offset beside each handle ran
 * together where a row's points crowd, seen from the side.
 */
export function namedPoints(state: SurfaceState): (i: number) => boolean {
  if (state.mode === 'join') return () => false;
  if (sceneOf(state) === 'patch' && !shownIn(state).has('corners')) return () => true;
  return isCorner;
}

/** The control points Pₘ,ₙ (their names are placed by the figure). */
export const netPoints = netHandles(
  pointList<SurfaceState>({
    id: 'x',
    get: (s) => flat(s.net),
    set: (s, points) => ({ ...s, net: grid(points) }),
    label: netLabel,
    min: 16,
    max: 16,
    style: () => ({ small: true }),
  }),
  netLabel,
  () => false,
);

const secondLabel = (i: number) => `Q_{${place(i).row + 1},${place(i).column}}`;
const secondList = netHandles(
  pointList<SurfaceState>({
    id: 'y',
    get: (s) => flat(s.secondNet.slice(1)),
    set: (s, points) => ({ ...s, secondNet: [s.secondNet[0], ...grid(points)] }),
    label: secondLabel,
    min: 12,
    max: 12,
    style: () => ({ small: true }),
  }),
  secondLabel,
  () => false,
);

/** The second net's rows Q₁ … Q₃, movable only in the scene of two patches. */
export const secondNetPoints: PointList<SurfaceState> = {
  ...secondList,
  handles: (state) => (state.mode === 'join' ? secondList.handles(state) : []),
};
