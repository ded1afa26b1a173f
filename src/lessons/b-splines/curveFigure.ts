import type { DrawInfo } from '../../app/lesson';
import type { KitFigure } from '../../kit/lesson';
import type { Point } from '../../math';
import type { Painter } from '../../render/painter';
import { boundsOf } from '../../render/projection';
import { segmentAt } from './drawParts';
import { dragHalo, haloAt, showsHalos } from './halo';
import { haloIds } from './ids';
import { drawContinuity } from './continuityDrawing';
import { drawMeanings, meaningsReach } from './meaningsDrawing';
import { drawCircle, drawKnots, drawNurbs, drawProjective } from './knotDrawing';
import type { BSplineModel } from './model';
import { controlPoints, linePoints } from './points';
import type { BSplineState } from './state';
import { drawConvert, drawLocal, drawProperties, drawUniform } from './uniformDrawing';

/** Each scene family draws its own picture. */
function drawScene(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  switch (m.kind) {
    case 'uniform':
      return drawUniform(painter, m, info);
    case 'local':
      return drawLocal(painter, m, info);
    case 'convert':
      return drawConvert(painter, m, info);
    case 'properties':
      return drawProperties(painter, m, info);
    case 'knots':
      return drawKnots(painter, m, info);
    case 'nurbs':
      return drawNurbs(painter, m, info);
    case 'circle':
      return drawCircle(painter, m, info);
    case 'projective':
      return drawProjective(painter, m, info);
    case 'meanings':
      return drawMeanings(painter, m, info);
    case 'continuity':
      return drawContinuity(painter, m, info);
  }
}

/** The line of the variation-diminishing test is shown (and movable) from its step on. */
const showsLine = (m: BSplineModel) => m.kind === 'properties' && m.shown.has('line');

export const curveFigure: KitFigure<BSplineState, BSplineModel> = {
  id: 'curve',
  title: 'The B-spline curve with its control points',
  kind: 'geometry',
  weight: 1.5,
  bounds(m) {
    const extra: Point[] = [...m.state.points];
    if (m.kind === 'properties') extra.push(...m.properties.image, ...m.state.line);
    if (m.kind === 'projective') extra.push(...m.projective.points);
    return boundsOf(extra);
  },
  // The key to the two kinds of ring, two lines, has no clear corner among
  // seven control points and their rings: it takes a band above them.
  keyLines: (m) => (m.kind === 'meanings' ? 2 : 0),
  // Their rings reach nearly four handles round P₀ and P₆, at the subject's edge.
  marksReach: (m, theme) => (m.kind === 'meanings' ? meaningsReach(theme) : 0),
  draw(painter, m, info) {
    painter.grid();
    drawScene(painter, m, info);
  },
  points: [controlPoints],
  addTo: controlPoints,
  handles: (m) => (showsLine(m) ? linePoints.handles(m.state) : []),
  // The line's points, and a weight's halo (grabbed on its ring: in or out sets the weight).
  moveHandle(state, id, to, m) {
    const line = linePoints.ref(id);
    if (line) return linePoints.move(state, line.index, to);
    const halo = haloIds.index(id);
    if (halo !== null && (m.kind === 'nurbs' || m.kind === 'circle'))
      return dragHalo(state, halo, to, m.rational.haloUnit);
    return state;
  },
  pickAt: (m, at, tolerance) =>
    showsHalos(m) ? haloAt(m.state.points, m.weights, m.rational.haloUnit, at, tolerance) : null,
  hoverAt: (m, at, tolerance) => segmentAt(m, at, tolerance),
  trail: (m) => (m.shown.is('points') ? null : m.point),
};
