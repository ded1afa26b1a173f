import type { Handle } from '../../app/lesson';
import { type PointList, pointList } from '../../kit/pointList';
import { type Point, controlPointName } from '../../math';
import { DATASETS, type Dataset } from './model';
import { revealedAt } from './script';
import { type BezierSplinesState, MAX_POINTS, normalize } from './state';

type State = BezierSplinesState;
/** How a point's handle looks: everything but its id and position. */
type Look = Omit<Handle, 'id' | 'position'>;

// A point list that neither adds nor removes (a tangent, a control point of a
// fixed chain): its points come and go with others, or not at all.
const FIXED = { min: Infinity, max: 0 };

/**
 * `list` with its handles as this lesson shows them: a point has a handle only
 * where `look` gives it one, at this state's part and step, and keeps its own
 * label also on one spot with another (a sharp corner's c₂, c₃, c₄ keep their
 * names). The kit's pointList could take this as `label(index, state)` and
 * `shown(index, state)`.
 */
function shownAs(list: PointList<State>, look: (s: State, index: number) => Look | null) {
  return {
    ...list,
    handles: (s: State) =>
      list.handles(s).flatMap(({ id, position }, index) => {
        const own = look(s, index);
        return own ? [{ id, position, ...own }] : [];
      }),
  };
}

/** The grid has its datasets and the inspector its chain: every other part starts from the points. */
const hasGivenPoints = (s: State) => s.part !== 'grid' && s.part !== 'inspector';

const givenList = shownAs(
  pointList<State>({
    id: 'p',
    get: (s) => s.points,
    set: (s, points) => ({ ...s, points }),
    label: (i) => `p_{${i}}`,
    min: 2,
    max: MAX_POINTS,
    // A point takes its hand-set tangent along; a new one gets one (normalize).
    after(before, after) {
      if (after.points.length >= before.points.length) return normalize(after).state;
      const gone = before.points.findIndex((p, k) => after.points[k] !== p);
      return { ...after, tangents: before.tangents.filter((_, k) => k !== gone) };
    },
  }),
  (s, i) => {
    if (!hasGivenPoints(s)) return null;
    // The worked example names them A, D, G, J (or c₃ᵢ) once its C² part starts.
    const letters = s.part === 'system' || (s.part === 'worked' && revealedAt(s).has('c2Count'));
    if (!letters) return { label: `p_{${i}}` };
    const name = controlPointName(3 * i, 3 * (s.points.length - 1) + 1);
    return { label: name.length === 1 ? name : `c_{${3 * i}}` };
  },
);

/** The given points p₀ … pₙ (in the C² system and the worked C² the practical's A, D, G, J), added where a part shows them. */
export const givenPoints: PointList<State> = {
  ...givenList,
  add: (s, at) => (hasGivenPoints(s) ? givenList.add(s, at) : null),
};

/** The quadratic spline's b₀, a diamond, once the first piece is shown. */
export const firstControl = shownAs(
  pointList<State>({
    id: 'b',
    get: (s) => s.firstControl,
    set: (s, firstControl) => ({ ...s, firstControl }),
    label: () => 'b_{0}',
    min: 1,
    max: 1,
  }),
  (s) =>
    s.part === 'quadratic' && revealedAt(s).has('firstPiece')
      ? { label: 'b_{0}', shape: 'diamond' }
      : null,
);

/** The tip pᵢ + Tᵢ/3 of a hand-set tangent: the control point it gives, and its handle. */
const tip = (s: State, i: number): Point => {
  const [p, t] = [s.points[i], s.tangents[i]];
  return [p[0] + t[0] / 3, p[1] + t[1] / 3];
};

/** The hand-set tangents, moved by their tips while the Hermite step shows them. */
export const tangentTips = shownAs(
  pointList<State>({
    id: 't',
    get: (s) => s.tangents.slice(0, s.points.length).map((_, i) => tip(s, i)),
    // Tᵢ = 3(tip − pᵢ); a tip not moved keeps its tangent exactly.
    set: (s, tips) => ({
      ...s,
      tangents: s.tangents.map((t, i) => {
        const [at, before] = [tips[i], tip(s, i)];
        if (!at || (at[0] === before[0] && at[1] === before[1])) return t;
        const p = s.points[i];
        return [3 * (at[0] - p[0]), 3 * (at[1] - p[1])];
      }),
    }),
    label: (i) => `p_{${i}} + T_{${i}}/3`,
    ...FIXED,
  }),
  (s, i) =>
    s.part === 'catmull' && revealedAt(s).is('hermite')
      ? { label: `p_{${i}} + T_{${i}}/3`, shape: 'diamond', small: true, showLabel: false }
      : null,
);

const handBuiltList = pointList<State>({
  id: 'q',
  get: (s) => s.handBuilt,
  set: (s, handBuilt) => ({ ...s, handBuilt }),
  label: (j) => `c_{${j}}`,
  ...FIXED,
});

/** The hand-built chain c₀ … c₃ₖ: joints (circles) first, the inner points (squares) with the pieces. */
export const handBuilt: PointList<State> = shownAs(
  {
    ...handBuiltList,
    // A joint carries its two neighbours along, as a font editor does.
    move(s, j, to) {
      if (j % 3 !== 0) return handBuiltList.move(s, j, to);
      const q = s.handBuilt;
      const [dx, dy] = [to[0] - q[j][0], to[1] - q[j][1]];
      return {
        ...s,
        handBuilt: q.map((c, k) => (Math.abs(k - j) <= 1 ? [c[0] + dx, c[1] + dy] : c)),
      };
    },
  },
  (s, j) => {
    if (s.part !== 'inspector') return null;
    const joint = j % 3 === 0;
    if (!joint && !revealedAt(s).has('pieces')) return null;
    return { label: `c_{${j}}`, shape: joint ? 'circle' : 'square' };
  },
);

/** The points of each dataset of the 3 × 3 grid: every cell of a row shows and moves the same ones. */
export const datasetPoints = Object.fromEntries(
  DATASETS.map((dataset) => [
    dataset,
    shownAs(
      pointList<State>({
        id: 'p',
        get: (s) => s[dataset],
        set: (s, points) => ({ ...s, [dataset]: points }),
        label: (i) => `p_{${i}}`,
        ...FIXED,
      }),
      (_s, i) => ({ label: `p_{${i}}`, small: true, showLabel: false }),
    ),
  ]),
) as Record<Dataset, PointList<State>>;
