import type { FigureSpec } from '../../app/lesson';
import { deCasteljau, sampleBezier, splitBezier } from '../../math';
import { boundsOf } from '../../render/viewport';
import { type DeCasteljauState, MAX_POINTS, degree } from './state';
import { insertPoint } from '../../interact/editPoints';

/** Labels for every constructed point stay readable up to this degree. */
const LABEL_ALL_UP_TO = 5;

export const constructionFigure: FigureSpec<DeCasteljauState> = {
  id: 'construction',
  title: 'Bézier curve with the de Casteljau construction at t',
  kind: 'geometry',
  bounds: (state) => boundsOf(state.p),
  draw(painter, state, info) {
    const theme = painter.theme;
    const n = degree(state);
    const levels = deCasteljau(state.p, state.t);
    const samples = Math.max(64, 24 * n);

    // The whole curve, faintly; then the part traced so far (0 … t) strongly.
    painter.polylineFlat(sampleBezier(state.p, samples), {
      color: theme.curveFaint,
      width: theme.sizes.curve * 0.8,
    });
    const [left, right] = splitBezier(state.p, state.t);
    if (state.split) {
      painter.polylineFlat(sampleBezier(left, samples), { color: painter.color(0) });
      painter.polylineFlat(sampleBezier(right, samples), { color: painter.color(1) });
    } else if (state.t > 0) {
      painter.polylineFlat(sampleBezier(left, samples), { color: theme.curve });
    }

    // Level 0 is the control polygon.
    painter.polyline(state.p, { color: theme.polygon, width: theme.sizes.line, dash: [6, 5] });

    for (let r = 1; r <= state.step; r++) {
      const color = painter.color(r - 1);
      painter.polyline(levels[r], { color, width: theme.sizes.line });
      levels[r].forEach((point, i) => {
        const last = r === n;
        painter.dot(
          point,
          last ? theme.accent : color,
          last ? theme.sizes.point * 1.6 : theme.sizes.point,
        );
        if (!info.thumbnail && (n <= LABEL_ALL_UP_TO || last)) {
          painter.label(last ? `P_{${r},${i}} = P(t)` : `P_{${r},${i}}`, point, {
            dx: 8,
            dy: 14 + theme.sizes.label * 0.3,
            color: last ? theme.ink : color,
            halo: true,
            size: theme.sizes.label * 0.9,
          });
        }
      });
    }

    if (state.split && !info.thumbnail) {
      painter.polyline(left, {
        color: painter.color(0),
        width: theme.sizes.line * 1.6,
        alpha: 0.85,
      });
      painter.polyline(right, {
        color: painter.color(1),
        width: theme.sizes.line * 1.6,
        alpha: 0.85,
      });
      for (const q of left) painter.dot(q, painter.color(0), theme.sizes.point * 0.9);
      for (const q of right) painter.dot(q, painter.color(1), theme.sizes.point * 0.9);
    }
  },
  handles: (state) =>
    state.p.map((point, i) => ({ id: `p${i}`, label: `P_{${i}}`, position: point })),
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    return { ...state, p: state.p.map((point, k) => (k === i ? to : point)) };
  },
  addPoint(state, at) {
    if (state.p.length >= MAX_POINTS) return null;
    const p = insertPoint(state.p, at);
    return { ...state, p, step: state.step === degree(state) ? p.length - 1 : state.step };
  },
  removeHandle(state, id) {
    if (state.p.length <= 2) return null;
    const i = Number(id.slice(1));
    return { ...state, p: state.p.filter((_, k) => k !== i) };
  },
};
