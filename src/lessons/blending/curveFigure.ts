import type { FigureSpec, Point } from '../../app/lesson';
import { insertPoint } from '../../interact/editPoints';
import type { Painter } from '../../render/painter';
import { highlightedIndex } from './hover';
import type { BlendingModel, Compared } from './model';
import { type BlendingState, MAX_POINTS } from './state';

/** Weight labels beside the points stay readable up to this degree. */
const LABEL_WEIGHTS_UP_TO = 8;

export const curveFigure: FigureSpec<BlendingState, BlendingModel> = {
  id: 'curve',
  title: 'Bézier curve with every control point weighted at μ',
  kind: 'geometry',
  bounds: (m) => m.curveBounds,
  draw(painter, m, info) {
    const theme = painter.theme;
    const { state, n, weights, point, compared } = m;
    const highlighted = highlightedIndex(info.hover);

    if (compared?.curve) {
      painter.polyline(compared.curve, {
        color: theme.muted,
        width: theme.sizes.curve * 0.8,
        dash: [10, 6],
      });
    }
    if (compared) drawHermiteData(painter, compared);

    painter.polyline(state.p, { color: theme.polygon, width: theme.sizes.line, dash: [6, 5] });
    painter.polylineFlat(m.curve, { color: theme.curve });

    // Each control point's halo grows with its weight at μ: the curve point is
    // their weighted average, so the biggest halo pulls hardest.
    const largest = theme.sizes.handle * 5;
    state.p.forEach((control, i) => {
      const color = painter.color(i);
      const radius = theme.sizes.handle * 1.3 + largest * weights[i];
      const lit = highlighted === i;
      painter.ring(
        control,
        radius,
        { color, width: lit ? theme.sizes.line * 2 : theme.sizes.thin, alpha: 0.9 },
        color,
        lit ? 0.4 : 0.22,
      );
      painter.segment(control, point, {
        color,
        width: Math.max(theme.sizes.thin, theme.sizes.line * 3 * weights[i]),
        alpha: lit ? 0.9 : 0.45,
      });
      if (!info.thumbnail && n <= LABEL_WEIGHTS_UP_TO) {
        painter.label(weights[i].toFixed(3), control, {
          dy: theme.sizes.handle + theme.sizes.small * 1.1,
          align: 'center',
          color,
          halo: true,
          bold: true,
          size: theme.sizes.small,
        });
      }
    });

    const other = compared?.point;
    if (other) {
      painter.ring(other.at, theme.sizes.point * 1.4, {
        color: theme.muted,
        width: theme.sizes.line * 1.5,
      });
      if (!info.thumbnail) {
        painter.label(other.label, other.at, {
          dx: theme.sizes.point + 6,
          dy: -theme.sizes.label * 0.9,
          color: theme.muted,
          halo: true,
          bold: true,
        });
      }
    }
    painter.dot(point, theme.accent, theme.sizes.point * 1.5);
    if (!info.thumbnail) {
      // Away from the control points and the weights written under them.
      const below = painter.view.worldLength(theme.sizes.handle + theme.sizes.small * 1.1);
      const crowd = state.p.flatMap((q) => [q, [q[0], q[1] - below]]);
      painter.labelClear('P(μ)', point, crowd, { color: theme.ink, halo: true, bold: true });
    }
  },
  handles: (m) =>
    m.state.p.map((point, i) => ({ id: `p${i}`, label: `P_{${i}}`, position: point })),
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    const at: Point = [to[0], to[1]];
    return { ...state, p: state.p.map((point, k) => (k === i ? at : point)) };
  },
  addPoint(state, at) {
    if (state.p.length >= MAX_POINTS) return null;
    return { ...state, p: insertPoint(state.p, at) };
  },
  removeHandle(state, id) {
    if (state.p.length <= 2) return null;
    const i = Number(id.slice(1));
    return { ...state, p: state.p.filter((_, k) => k !== i) };
  },
};

/** The Hermite data of the same cubic, x0′ and x1′ at true length, labelled. */
function drawHermiteData(painter: Painter, compared: Compared): void {
  const theme = painter.theme;
  compared.arrows.forEach(([from, tip], k) => {
    painter.arrow(from, tip, { color: theme.accent, width: theme.sizes.line });
    painter.label(k === 0 ? "x_0'" : "x_1'", tip, {
      dx: 6,
      dy: -theme.sizes.label * 0.7,
      color: theme.accent,
      halo: true,
      bold: true,
    });
  });
}
