import type { FigureSpec, Handle } from '../../app/lesson';
import { insertPoint } from '../../interact/editPoints';
import { type Point, controlPointName } from '../../math';
import { boundsOf } from '../../render/projection';
import { drawParts } from './drawParts';
import type { BezierSplinesModel } from './model';
import { type BezierSplinesState, MAX_POINTS, normalize } from './state';

type Spec = FigureSpec<BezierSplinesState, BezierSplinesModel>;

const replace = (list: readonly Point[], i: number, to: Point) =>
  list.map((q, k) => (k === i ? [to[0], to[1]] : q));

/** Everything the current part draws, so "fit" shows all of it. */
function shownPoints(m: BezierSplinesModel): Point[] {
  const { part, p, b } = m.state;
  switch (part) {
    case 'inspector':
      return m.state.q;
    case 'quadratic':
      return [...p, ...b, ...m.quadraticControls];
    case 'system':
      return [...p, ...m.system.controls];
    case 'catmull':
      return [...p, ...m.hermite.flat(), ...m.alphas.flatMap((a) => a.segments.flat())];
    default:
      return [...p, ...m.movedPoints];
  }
}

/** The interpolated points' names: A, D, G, J for the practical's four points. */
const pointLabel = (m: BezierSplinesModel, i: number) => {
  if (m.state.part !== 'system') return `p_{${i}}`;
  const name = controlPointName(3 * i, 3 * (m.state.p.length - 1) + 1);
  return name.length === 1 ? name : `c_{${3 * i}}`;
};

function handles(m: BezierSplinesModel): Handle[] {
  const { part, step, p } = m.state;
  if (part === 'grid') return [];
  if (part === 'inspector') {
    return m.state.q
      .map((position, j) => ({
        id: `q${j}`,
        label: `c_{${j}}`,
        position,
        shape: j % 3 === 0 ? ('circle' as const) : ('square' as const),
      }))
      .filter((_, j) => step > 0 || j % 3 === 0);
  }
  const list: Handle[] = p.map((position, i) => ({
    id: `p${i}`,
    label: pointLabel(m, i),
    position,
  }));
  if (part === 'quadratic' && step > 0)
    list.push({ id: 'b0', label: 'b_{0}', position: m.state.b[0], shape: 'diamond' });
  if (part === 'catmull' && step === 1) {
    m.state.tg.forEach((t, i) =>
      list.push({
        id: `t${i}`,
        label: `p_{${i}} + T_{${i}}/3`,
        position: [p[i][0] + t[0] / 3, p[i][1] + t[1] / 3],
        shape: 'diamond',
        small: true,
        showLabel: false,
      }),
    );
  }
  return list;
}

/** Moving a joint of the hand-built spline carries its two neighbours along, as a font editor does. */
function moveControl(q: readonly Point[], j: number, to: Point): Point[] {
  if (j % 3 !== 0) return replace(q, j, to);
  const [dx, dy] = [to[0] - q[j][0], to[1] - q[j][1]];
  return q.map((c, k) => (Math.abs(k - j) <= 1 ? [c[0] + dx, c[1] + dy] : c));
}

export const mainFigure: Spec = {
  id: 'main',
  title: 'Bézier splines: the points, the pieces and how they join',
  kind: 'geometry',
  bounds: (m) => boundsOf(shownPoints(m)),
  draw(painter, m, info) {
    drawParts[m.state.part](painter, m, info);
    // The given points (under their handles): what every step starts from.
    const given =
      m.state.part === 'inspector' ? m.state.q.filter((_, j) => j % 3 === 0) : m.state.p;
    for (const q of given) painter.dot(q, painter.theme.ink);
    if (m.oneSpot)
      painter.note(
        'All the points are on one spot: every piece shrinks to that point, so the spline is a single point with no direction, and its joins have nothing to match.',
      );
  },
  handles,
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    if (id === 'b0') return { ...state, b: [[to[0], to[1]]] };
    if (id.startsWith('q')) return { ...state, q: moveControl(state.q, i, to) };
    if (id.startsWith('t')) {
      const at = state.p[i];
      return { ...state, tg: replace(state.tg, i, [3 * (to[0] - at[0]), 3 * (to[1] - at[1])]) };
    }
    return { ...state, p: replace(state.p, i, to) };
  },
  addPoint(state, at) {
    if (state.part === 'grid' || state.part === 'inspector' || state.p.length >= MAX_POINTS)
      return null;
    return normalize({ ...state, p: insertPoint(state.p, [at[0], at[1]]) }).state;
  },
  removeHandle(state, id) {
    if (!id.startsWith('p') || state.p.length <= 2) return null;
    const i = Number(id.slice(1));
    return {
      ...state,
      p: state.p.filter((_, k) => k !== i),
      tg: state.tg.filter((_, k) => k !== i),
    };
  },
};
