import type { DrawInfo, FigureSpec, Point } from '../../app/lesson';
import { insertPoint } from '../../interact/editPoints';
import { stackedLabels } from '../../kit/labels';
import { movingPoint } from './script';
import type { Painter } from '../../render/painter';
import { boundsOf } from '../../render/projection';
import { drawAffine } from './affine/draw';
import { drawClosed } from './closed/draw';
import { drawCubic } from './cubic/draw';
import { drawElevate } from './elevate/draw';
import { drawEnds } from './ends/draw';
import { drawHermite } from './hermite/draw';
import { drawHull } from './hull/draw';
import { drawLocal } from './local/draw';
import type { ModelOf, PropertiesModel } from './model';
import { drawRepeat } from './repeat/draw';
import { drawSplit } from './split/draw';
import { type ExperimentId, MAX_POINTS, type PropertiesState, needsCubic } from './state';

type Drawings = {
  [X in ExperimentId]: (painter: Painter, m: ModelOf<X>, info: DrawInfo) => void;
};

/** Each experiment's drawing, reading that experiment's model. */
const DRAWINGS: Drawings = {
  ends: drawEnds,
  hull: drawHull,
  local: drawLocal,
  repeat: drawRepeat,
  closed: drawClosed,
  elevate: drawElevate,
  split: drawSplit,
  affine: drawAffine,
  cubic: drawCubic,
  hermite: drawHermite,
};

function drawExperiment<X extends ExperimentId>(
  painter: Painter,
  x: X,
  m: ModelOf<X>,
  info: DrawInfo,
): void {
  DRAWINGS[x](painter, m, info);
}

const copy = (points: readonly Point[]): Point[] => points.map((point) => [...point]);

export const propertiesFigure: FigureSpec<PropertiesState, PropertiesModel> = {
  id: 'experiment',
  title: 'Bézier curve set up for the experiment',
  kind: 'geometry',
  bounds: (m) => boundsOf(m.extent),
  draw: (painter, m, info) => drawExperiment(painter, m.x, m, info),
  handles: (m) => {
    const name = (i: number) =>
      m.x === 'closed' && i === 0 ? `P_0 = P_{${m.state.p.length}}` : `P_{${i}}`;
    const labels = stackedLabels(m.state.p, name);
    return m.state.p.map((point, i) => ({ id: `p${i}`, ...labels[i], position: point }));
  },
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    return { ...state, p: state.p.map((point, k) => (k === i ? [to[0], to[1]] : point)) };
  },
  addPoint(state, at) {
    if (needsCubic(state.x) || state.p.length >= MAX_POINTS) return null;
    const p = insertPoint(state.p, at);
    // A new point makes a new curve: it becomes the "before" of the local-control experiment.
    return { ...state, p, q: state.x === 'local' ? copy(p) : state.q };
  },
  trail: movingPoint,
  removeHandle(state, id) {
    const fewest = state.x === 'closed' ? 3 : 2;
    if (needsCubic(state.x) || state.p.length <= fewest) return null;
    const i = Number(id.slice(1));
    const p = state.p.filter((_, k) => k !== i);
    const r = i < state.r ? state.r - 1 : Math.min(state.r, p.length - 1);
    return { ...state, p, r, q: state.x === 'local' ? copy(p) : state.q };
  },
};
