import type { FigureSpec } from '../../app/lesson';
import { insertPoint } from '../../interact/editPoints';
import { boundsOf } from '../../render/projection';
import type { DeCasteljauModel } from './model';
import { type DeCasteljauState, MAX_POINTS } from './state';

/** Labels for every constructed point stay readable up to this degree. */
const LABEL_ALL_UP_TO = 5;

export const constructionFigure: FigureSpec<DeCasteljauState, DeCasteljauModel> = {
  id: 'construction',
  title: 'Bézier curve with the de Casteljau construction at t',
  kind: 'geometry',
  bounds: (m) => boundsOf(m.state.p),
  draw(painter, m, info) {
    const theme = painter.theme;
    const { state, n, levels } = m;

    // The whole curve, faintly; then the part traced so far (0 … t) strongly.
    painter.polylineFlat(m.curve, { color: theme.curveFaint, width: theme.sizes.curve * 0.8 });
    if (state.split) {
      painter.polylineFlat(m.leftCurve, { color: painter.color(0) });
      painter.polylineFlat(m.rightCurve, { color: painter.color(1) });
    } else if (state.t > 0) {
      painter.polylineFlat(m.leftCurve, { color: theme.curve });
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
      for (const [half, k] of [
        [m.left, 0],
        [m.right, 1],
      ] as const) {
        painter.polyline(half, {
          color: painter.color(k),
          width: theme.sizes.line * 1.6,
          alpha: 0.85,
        });
        for (const q of half) painter.dot(q, painter.color(k), theme.sizes.point * 0.9);
      }
    }
  },
  handles: (m) =>
    m.state.p.map((point, i) => ({ id: `p${i}`, label: `P_{${i}}`, position: point })),
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    return { ...state, p: state.p.map((point, k) => (k === i ? [to[0], to[1]] : point)) };
  },
  addPoint(state, at, m) {
    if (state.p.length >= MAX_POINTS) return null;
    const p = insertPoint(state.p, at);
    return { ...state, p, step: state.step === m.n ? p.length - 1 : state.step };
  },
  removeHandle(state, id) {
    if (state.p.length <= 2) return null;
    const i = Number(id.slice(1));
    return { ...state, p: state.p.filter((_, k) => k !== i) };
  },
};
