import type { KitFigure } from '../../kit/lesson';
import { drawLegend } from '../../kit/legend';
import type { Painter } from '../../render/painter';
import { seriesDash } from '../../kit/seriesColours';
import { type LagrangeModel, basisId } from './model';
import { interpolatedPoints } from './points';
import type { LagrangeState } from './state';

export const curveFigure: KitFigure<LagrangeState, LagrangeModel> = {
  id: 'curve',
  title: 'The points with the Lagrange interpolating polynomial through them',
  kind: 'geometry',
  weight: 1.6,
  bounds: (m) => m.curveBounds,
  // Beside the spline the key has three lines, and Runge's spike (P₅, which
  // the lecturer drags) rises into the top corners: the key takes a band above it.
  keyLines: (m) => (m.comparison ? 3 : 0),
  draw(painter, m, info) {
    const theme = painter.theme;
    const { state, at, shown } = m;
    const points = state.points;
    painter.polyline(points, { color: theme.polygon, width: theme.sizes.thin, dash: [5, 5] });
    // Each point whose basis polynomial is shown wears its colour (a dash past the palette).
    points.forEach((point, k) => {
      if (!shown.has('basis', k + 1) || shown.has('curve')) return;
      painter.ring(point, theme.sizes.handle * 1.8, {
        color: painter.color(k),
        width: theme.sizes.line,
        dash: seriesDash(painter, k),
      });
    });
    if (shown.has('curve')) painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
    if (m.comparison) drawSpline(painter, m);
    if (shown.has('curve')) painter.movingPoint(at, 1.5);
    if (info.thumbnail) return;
    // The point whose basis curve is under the pointer in the plot.
    const hovered = points.findIndex((_, k) => info.hover === basisId(k));
    if (hovered !== -1) {
      painter.ring(points[hovered], theme.sizes.handle * 2, {
        color: painter.color(hovered),
        width: theme.sizes.line,
      });
    }
    // A wild polynomial can carry P(t) off the figure: an arrow at the edge says where.
    if (shown.has('curve') && !painter.offView(at, 'P(t)', theme.accent))
      painter.labelClear('P(t)', at, points, { halo: true, bold: true });
    let top = theme.sizes.label * 0.5;
    if (m.collapsedNote) top = painter.note(m.collapsedNote);
    if (m.note) top = painter.note(m.note, { top });
    if (shown.has('curve')) legend(painter, m, top);
  },
  trail: (m) => (m.shown.has('curve') ? m.at : null),
  points: [interpolatedPoints],
  addTo: interpolatedPoints,
};

/**
 * The natural spline as far as the steps reveal it: its gradients (arrows at
 * true length), its pieces so far (on top: where the two curves agree, it is
 * the spline one sees), and the spline after one point is moved (dashed).
 */
function drawSpline(painter: Painter, m: LagrangeModel) {
  const theme = painter.theme;
  const { shown, state } = m;
  const c = m.comparison!;
  const colour = painter.color(2);
  if (shown.has('gradients'))
    state.points.forEach((p, k) =>
      painter.arrow(p, [p[0] + c.gradients[k][0], p[1] + c.gradients[k][1]], {
        color: colour,
        width: theme.sizes.line,
      }),
    );
  const pieces = c.segments.slice(0, shown.count('piece'));
  if (pieces.length)
    painter.cubicSegments(pieces, {
      color: colour,
      width: theme.sizes.curve,
      dash: [theme.sizes.curve * 2, theme.sizes.curve * 1.2],
    });
  if (!shown.has('coupled')) return;
  painter.cubicSegments(c.ghost, { color: theme.muted, width: theme.sizes.line, dash: [4, 4] });
  const moved = state.points[c.moved];
  const to: [number, number] = [moved[0], moved[1] + c.nudge];
  painter.arrow(moved, to, { color: theme.muted, width: theme.sizes.line });
  painter.ring(to, theme.sizes.handle, { color: theme.muted, width: theme.sizes.line });
}

/** What each line is, in the clearest corner (below `top`, screen pixels, at the top left). */
function legend(painter: Painter, m: LagrangeModel, top: number) {
  const theme = painter.theme;
  const dashed = (color: string) => ({
    color,
    width: theme.sizes.curve,
    dash: [theme.sizes.curve * 2, theme.sizes.curve * 1.2],
  });
  drawLegend(
    painter,
    [
      {
        text: `Lagrange polynomial, degree ${m.n}`,
        line: { color: theme.curve, width: theme.sizes.curve },
      },
      ...(m.comparison && m.shown.has('piece')
        ? [{ text: 'natural cubic spline', line: dashed(painter.color(2)) }]
        : []),
      ...(m.comparison && m.shown.has('coupled')
        ? [{ text: `spline with P_{${m.comparison.moved}} moved`, line: dashed(theme.muted) }]
        : []),
    ],
    { top },
  );
}
