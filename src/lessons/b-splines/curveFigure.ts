import type { FigureSpec, Handle } from '../../app/lesson';
import { insertPoint } from '../../interact/editPoints';
import type { Point } from '../../math';
import { boundsOf } from '../../render/projection';
import {
  drawConvert,
  drawKnots,
  drawLocal,
  drawProperties,
  drawRational,
  drawUniform,
  segmentAt,
} from './drawScenes';
import { dragHalo, haloAt, showsHalos } from './halo';
import type { BSplineModel } from './model';
import { type BSplineState, MAX_POINTS, refitKnots } from './state';

const DRAW = {
  uniform: drawUniform,
  closed: drawUniform,
  local: drawLocal,
  convert: drawConvert,
  properties: drawProperties,
  knots: drawKnots,
  clamped: drawKnots,
  repeated: drawKnots,
  nurbs: drawRational,
  circle: drawRational,
  projective: drawRational,
} as const;

/** The line of the variation-diminishing test is shown (and movable) from this step on. */
export const LINE_STEP = 3;
const showsLine = (s: BSplineState) => s.x === 'properties' && s.k >= LINE_STEP;

function withPoints(state: BSplineState, p: Point[], at: number, added: boolean): BSplineState {
  const w = added
    ? [...state.w.slice(0, at), 1, ...state.w.slice(at)]
    : state.w.filter((_, i) => i !== at);
  const q = added
    ? [...state.q.slice(0, at), p[at], ...state.q.slice(at)]
    : state.q.filter((_, i) => i !== at);
  return { ...state, p, q, w, u: refitKnots(state.u, p.length, state.d) };
}

export const curveFigure: FigureSpec<BSplineState, BSplineModel> = {
  id: 'curve',
  title: 'The B-spline curve with its control points',
  kind: 'geometry',
  weight: 1.5,
  bounds(m) {
    const extra: Point[] = [...m.state.p];
    if (m.properties) extra.push(...m.properties.image, ...m.state.l);
    if (m.projective) extra.push(...m.projective.points);
    return boundsOf(extra);
  },
  draw(painter, m, info) {
    painter.grid();
    DRAW[m.state.x](painter, m, info);
  },
  handles(m) {
    const handles: Handle[] = m.state.p.map((point, i) => ({
      id: `p${i}`,
      label: `x_{${i}}`,
      position: point,
    }));
    if (showsLine(m.state)) {
      m.state.l.forEach((point, i) =>
        handles.push({ id: `l${i}`, label: `L_{${i}}`, position: point, shape: 'square' }),
      );
    }
    return handles;
  },
  moveHandle(state, id, to, m) {
    const i = Number(id.slice(1));
    if (id.startsWith('w')) return m.rational ? dragHalo(state, i, to, m.rational.haloUnit) : state;
    const moved = (list: readonly Point[]) =>
      list.map((point, k) => (k === i ? [to[0], to[1]] : point));
    return id.startsWith('l') ? { ...state, l: moved(state.l) } : { ...state, p: moved(state.p) };
  },
  addPoint(state, at) {
    if (state.p.length >= MAX_POINTS) return null;
    const p = insertPoint(state.p, [at[0], at[1]]);
    const index = p.findIndex((point) => point[0] === at[0] && point[1] === at[1]);
    return withPoints(state, p, index, true);
  },
  removeHandle(state, id) {
    if (!id.startsWith('p') || state.p.length <= Math.max(4, state.d + 1)) return null;
    const i = Number(id.slice(1));
    return withPoints(
      state,
      state.p.filter((_, k) => k !== i),
      i,
      false,
    );
  },
  // A weight's halo is grabbed on its ring, away from the point: in or out sets the weight.
  pickAt: (m, at, tolerance) =>
    m.rational && showsHalos(m.state)
      ? haloAt(m.state.p, m.weights, m.rational.haloUnit, at, tolerance)
      : null,
  hoverAt: (m, at, tolerance) => segmentAt(m, at, tolerance),
  trail: (m) => (m.state.k >= 1 ? m.point : null),
};
