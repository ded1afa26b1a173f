import type { FigureSpec } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import { keepLastStep } from '../../kit/keepLastStep';
import { seriesDash } from '../../kit/seriesColours';
import type { LagrangeModel } from './model';
import { type LagrangeState, MAX_POINTS, stepCount } from './state';

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
    const { state, at, shown } = m;
    painter.polyline(state.p, { color: theme.polygon, width: theme.sizes.thin, dash: [5, 5] });
    // Each point whose basis polynomial is shown wears its colour (a dash past the palette).
    state.p.forEach((point, k) => {
      if (k >= shown.basis || shown.curve) return;
      painter.ring(point, theme.sizes.handle * 1.8, {
        color: painter.color(k),
        width: theme.sizes.line,
        dash: seriesDash(painter, k),
      });
    });
    if (shown.curve) painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
    // The spline on top: where the two agree, it is the spline one sees.
    if (m.spline && shown.spline)
      painter.cubicSegments(m.spline, {
        color: painter.color(2),
        width: theme.sizes.curve,
        dash: [theme.sizes.curve * 2, theme.sizes.curve * 1.2],
      });
    if (shown.curve) painter.dot(at, theme.accent, theme.sizes.point * 1.5);
    if (info.thumbnail) return;
    const hovered = /^L\d+$/.test(info.hover ?? '') ? Number(info.hover!.slice(1)) : -1;
    if (hovered >= 0 && hovered < state.p.length) {
      painter.ring(state.p[hovered], theme.sizes.handle * 2, {
        color: painter.color(hovered),
        width: theme.sizes.line,
      });
    }
    if (shown.curve) painter.labelClear('P(t)', at, state.p, { halo: true, bold: true });
    let top = theme.sizes.label * 0.5;
    if (m.collapsedNote) top = painter.note(m.collapsedNote);
    if (m.note) top = painter.note(m.note, { top });
    if (shown.curve) legend(painter, m, top);
  },
  trail: (m) => (m.shown.curve ? m.at : null),
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
    return keepLastStep(state, { ...state, p: [...state.p, [at[0], at[1]]] }, stepCount);
  },
  removeHandle(state, id) {
    if (state.p.length <= 2) return null;
    const i = Number(id.slice(1));
    return keepLastStep(state, { ...state, p: state.p.filter((_, k) => k !== i) }, stepCount);
  },
};

/** What each line is, in the top left corner (screen pixels). */
function legend(painter: Painter, m: LagrangeModel, top: number) {
  const theme = painter.theme;
  const size = theme.sizes.label;
  const x = size * 0.8;
  let y = top + size * 0.8;
  const entry = (text: string, color: string, dashed = false) => {
    const c = painter.ctx;
    c.save();
    c.strokeStyle = color;
    c.lineWidth = theme.sizes.curve;
    c.setLineDash(dashed ? [theme.sizes.curve * 2, theme.sizes.curve * 1.2] : []);
    c.beginPath();
    c.moveTo(x, y);
    c.lineTo(x + size * 1.6, y);
    c.stroke();
    c.restore();
    painter.screenLabel(text, x + size * 2.1, y, { halo: true });
    y += size * 1.5;
  };
  entry(`Lagrange polynomial, degree ${m.n}`, theme.curve);
  if (m.spline && m.shown.spline) entry('natural cubic spline', painter.color(2), true);
}
