import type { FigureSpec, Point2 } from '../../app/lesson';
import { boundsOf } from '../../render/viewport';
import { insertPoint } from '../../interact/editPoints';
import { EXPERIMENTS } from './experiments';
import { MAX_POINTS, type PropertiesState, controlPoints, needsCubic } from './state';

const copy = (points: readonly Point2[]): Point2[] => points.map((point) => [point[0], point[1]]);

export const propertiesFigure: FigureSpec<PropertiesState> = {
  id: 'experiment',
  title: 'Bézier curve set up for the experiment',
  kind: 'geometry',
  bounds(state) {
    const extra = EXPERIMENTS[state.x].extent?.(state) ?? [];
    const before = state.x === 'local' ? state.q : [];
    return boundsOf([...state.p, ...controlPoints(state), ...before, ...extra]);
  },
  draw(painter, state, info) {
    EXPERIMENTS[state.x].draw(painter, state, info);
  },
  handles: (state) =>
    state.p.map((point, i) => ({
      id: `p${i}`,
      label: state.x === 'closed' && i === 0 ? `P_0 = P_{${state.p.length}}` : `P_{${i}}`,
      position: point,
    })),
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    return { ...state, p: state.p.map((point, k) => (k === i ? to : point)) };
  },
  addPoint(state, at) {
    if (needsCubic(state.x) || state.p.length >= MAX_POINTS) return null;
    const p = insertPoint(state.p, at);
    // A new point makes a new curve: it becomes the "before" of the local-control experiment.
    return { ...state, p, q: state.x === 'local' ? copy(p) : state.q };
  },
  removeHandle(state, id) {
    const fewest = state.x === 'closed' ? 3 : 2;
    if (needsCubic(state.x) || state.p.length <= fewest) return null;
    const i = Number(id.slice(1));
    const p = state.p.filter((_, k) => k !== i);
    const r = i < state.r ? state.r - 1 : Math.min(state.r, p.length - 1);
    return { ...state, p, r, q: state.x === 'local' ? copy(p) : state.q };
  },
};
