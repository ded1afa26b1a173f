import { h } from '../../app/dom';
import { bezierPoint, convexHull, convexHullContains, sampleBezier } from '../../math';
import { type Experiment, drawBezier, drawMarked, drawPolygon } from './experiment';
import { controlPoints } from './state';

const SAMPLES = 400;

/** The hull and how many curve samples lie in it. */
export function hullCheck(points: readonly (readonly number[])[]) {
  const hull = convexHull(points);
  const scale = Math.max(1, ...points.flat().map(Math.abs));
  const flat = sampleBezier(points, SAMPLES);
  let inside = 0;
  for (let k = 0; k < flat.length; k += 2) {
    if (convexHullContains(hull, [flat[k], flat[k + 1]], 1e-9 * scale)) inside++;
  }
  return { hull, inside, total: SAMPLES + 1 };
}

export const hull: Experiment = {
  id: 'hull',
  title: 'Convex hull',
  sentence:
    'Every point of the curve is an average of the control points with non-negative weights, so the curve never leaves their convex hull. Drag the points and try to make it escape.',
  draw(painter, state, info) {
    const theme = painter.theme;
    const p = controlPoints(state);
    const { hull: corners } = hullCheck(p);
    if (corners.length >= 3) {
      painter.polygon(corners, painter.color(2), 0.14, {
        color: painter.color(2),
        width: theme.sizes.line,
      });
    } else if (corners.length === 2) {
      painter.segment(corners[0], corners[1], {
        color: painter.color(2),
        width: theme.sizes.line * 3,
        alpha: 0.4,
      });
    }
    drawPolygon(painter, p);
    drawBezier(painter, p, { color: theme.curve });
    drawMarked(painter, bezierPoint(p, state.t), 'P(t)', info);
  },
  explain(state) {
    const p = controlPoints(state);
    const { hull: corners, inside, total } = hullCheck(p);
    const verdict =
      inside === total
        ? `All ${total} sampled curve points lie in the hull.`
        : `${total - inside} of ${total} samples lie outside the hull: that would contradict the theorem — please report it.`;
    const shape =
      corners.length === 1
        ? 'All control points coincide: the hull is a single point, and the "curve" is that point.'
        : corners.length === 2
          ? 'All control points lie on one line: the hull is a segment, and the curve runs along it (possibly back and forth).'
          : `The hull has ${corners.length} corners; ${p.length - corners.length} control point${p.length - corners.length === 1 ? ' lies' : 's lie'} inside it or on an edge.`;
    return [h('p', {}, verdict), h('p', {}, shape)];
  },
};
