import type { FigureSpec } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import type { LagrangeModel } from './model';
import { type LagrangeState, MAX_POINTS } from './state';

/** Every point is labelled up to this many; beyond, only the first and the last. */
const LABEL_ALL_UP_TO = 9;

export const curveFigure: FigureSpec<LagrangeState, LagrangeModel> = {
  id: 'curve',
  title: 'The points with the Lagrange interpolating polynomial through them',
  kind: 'geometry',
  weight: 1.6,
  bounds: (m) => m.curveBounds,
  draw(painter, m, info) {
    const theme = painter.theme;
    const { state, at } = m;
    painter.polyline(state.p, { color: theme.polygon, width: theme.sizes.thin, dash: [5, 5] });
    painter.polylineFlat(m.curve, { color: theme.curve });
    // The spline on top: where the two agree, it is the spline one sees.
    if (m.spline)
      painter.cubicSegments(m.spline, { color: painter.color(2), width: theme.sizes.curve });
    painter.dot(at, theme.accent, theme.sizes.point * 1.5);
    if (info.thumbnail) return;
    const hovered = /^L\d+$/.test(info.hover ?? '') ? Number(info.hover!.slice(1)) : -1;
    if (hovered >= 0 && hovered < state.p.length) {
      painter.ring(state.p[hovered], theme.sizes.handle * 2, {
        color: painter.color(hovered),
        width: theme.sizes.line,
      });
    }
    painter.label('P(t)', at, { dx: 10, dy: theme.sizes.label, halo: true, bold: true });
    let top = theme.sizes.label * 0.5;
    if (m.collapsedNote) top = painter.note(m.collapsedNote);
    legend(painter, m, top);
  },
  handles: (m) =>
    m.state.p.map((point, i) => ({
      id: `p${i}`,
      label: `P_{${i}}`,
      position: point,
      // Many close points: name only the ends, so the labels stay readable.
      showLabel: m.state.p.length <= LABEL_ALL_UP_TO || i === 0 || i === m.state.p.length - 1,
    })),
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    return { ...state, p: state.p.map((point, k) => (k === i ? [to[0], to[1]] : point)) };
  },
  addPoint(state, at) {
    if (state.p.length >= MAX_POINTS) return null;
    return { ...state, p: [...state.p, [at[0], at[1]]] };
  },
  removeHandle(state, id) {
    if (state.p.length <= 2) return null;
    const i = Number(id.slice(1));
    return { ...state, p: state.p.filter((_, k) => k !== i) };
  },
};

/** What each line is, in the top left corner (screen pixels). */
function legend(painter: Painter, m: LagrangeModel, top: number) {
  const theme = painter.theme;
  const size = theme.sizes.label;
  const x = size * 0.8;
  let y = top + size * 0.8;
  const entry = (text: string, color: string) => {
    const c = painter.ctx;
    c.save();
    c.strokeStyle = color;
    c.lineWidth = theme.sizes.curve;
    c.setLineDash([]);
    c.beginPath();
    c.moveTo(x, y);
    c.lineTo(x + size * 1.6, y);
    c.stroke();
    c.restore();
    painter.screenLabel(text, x + size * 2.1, y, { halo: true });
    y += size * 1.5;
  };
  entry(`Lagrange polynomial, degree ${m.n}`, theme.curve);
  if (m.spline) entry('natural cubic spline', painter.color(2));
}
