import type { FigureSpec } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import { boundsOf } from '../../render/viewport';
import { interpolant, polynomialPoint, samplePolynomial, splineSegments } from './model';
import { type LagrangeState, MAX_POINTS, degree } from './state';

/** Every point is labelled up to this many; beyond, only the first and the last. */
const LABEL_ALL_UP_TO = 9;

export const curveFigure: FigureSpec<LagrangeState> = {
  id: 'curve',
  title: 'The points with the Lagrange interpolating polynomial through them',
  kind: 'geometry',
  weight: 1.6,
  bounds(state) {
    // The points, and the polynomial's swings up to a point: a wild polynomial
    // may leave the view, which is the lesson, but the points must stay large.
    const points = boundsOf(state.p);
    const size = Math.max(points.maxX - points.minX, points.maxY - points.minY, 1);
    const curve = samplePolynomial(state, interpolant(state).ts, 200);
    const xs: number[] = [];
    const ys: number[] = [];
    for (let i = 0; i < curve.length; i += 2) {
      xs.push(curve[i]);
      ys.push(curve[i + 1]);
    }
    const reach = 0.6 * size;
    const bounds = {
      minX: Math.max(points.minX - reach, Math.min(points.minX, ...xs)),
      maxX: Math.min(points.maxX + reach, Math.max(points.maxX, ...xs)),
      minY: Math.max(points.minY - reach, Math.min(points.minY, ...ys)),
      maxY: Math.min(points.maxY + reach, Math.max(points.maxY, ...ys)),
    };
    // Room at the top for the legend, and for the note when there is one.
    const headroom = interpolant(state).collapsed ? 0.7 : 0.2;
    return { ...bounds, maxY: bounds.maxY + headroom * (bounds.maxY - bounds.minY || 1) };
  },
  draw(painter, state, info) {
    const theme = painter.theme;
    const { ts, collapsed } = interpolant(state);
    painter.polyline(state.p, { color: theme.polygon, width: theme.sizes.thin, dash: [5, 5] });
    painter.polylineFlat(samplePolynomial(state, ts), { color: theme.curve });
    // The spline on top: where the two agree, it is the spline one sees.
    if (state.spline) {
      painter.cubicSegments(splineSegments(state), {
        color: painter.color(2),
        width: theme.sizes.curve,
      });
    }
    const at = polynomialPoint(state, ts, state.t);
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
    let top = painter.theme.sizes.label * 0.5;
    if (collapsed) {
      top = painter.note(
        `P${collapsed[0]} and P${collapsed[1]} coincide, so chord length gives them the same t, and no polynomial is at two places at one t: equally spaced values are used instead.`,
      );
    }
    legend(painter, state, top);
  },
  handles: (state) =>
    state.p.map((point, i) => ({
      id: `p${i}`,
      label: `P_{${i}}`,
      position: point,
      // Many close points: name only the ends, so the labels stay readable.
      showLabel: state.p.length <= LABEL_ALL_UP_TO || i === 0 || i === state.p.length - 1,
    })),
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    return { ...state, p: state.p.map((point, k) => (k === i ? to : point)) };
  },
  addPoint(state, at) {
    if (state.p.length >= MAX_POINTS) return null;
    return { ...state, p: [...state.p, at] };
  },
  removeHandle(state, id) {
    if (state.p.length <= 2) return null;
    const i = Number(id.slice(1));
    return { ...state, p: state.p.filter((_, k) => k !== i) };
  },
};

function legend(painter: Painter, state: LagrangeState, top: number) {
  const theme = painter.theme;
  const size = theme.sizes.label;
  const x = size * 0.8;
  let y = top + size * 0.8;
  const entry = (text: string, color: string) => {
    painter.ctx.save();
    painter.ctx.strokeStyle = color;
    painter.ctx.lineWidth = theme.sizes.curve;
    painter.ctx.setLineDash([]);
    painter.ctx.beginPath();
    painter.ctx.moveTo(x, y);
    painter.ctx.lineTo(x + size * 1.6, y);
    painter.ctx.stroke();
    painter.ctx.restore();
    painter.screenLabel(text, x + size * 2.1, y, { halo: true });
    y += size * 1.5;
  };
  entry(`Lagrange polynomial, degree ${degree(state)}`, theme.curve);
  if (state.spline) entry('natural cubic spline', painter.color(2));
}
