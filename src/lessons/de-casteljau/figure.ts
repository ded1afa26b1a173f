import type { DrawInfo } from '../../app/lesson';
import type { KitFigure } from '../../kit/lesson';
import type { Painter } from '../../render/painter';
import { boundsOf } from '../../render/projection';
import { HALF_DASH, halfColour, levelColour, levelDash } from '../../kit/seriesColours';
import { handleLabelBoxes, placeLabel } from '../../kit/labels';
import { drawBernstein, drawPseudocode } from './drawWalks';
import type { DeCasteljauModel } from './model';
import { controlPoints } from './points';
import type { DeCasteljauState } from './state';

/** Labels for every constructed point stay readable up to this degree (3 on a narrow screen). */
const LABEL_ALL_UP_TO = 5;
const NARROW = 600;

export const constructionFigure: KitFigure<DeCasteljauState, DeCasteljauModel> = {
  id: 'construction',
  title: 'Bézier curve with the de Casteljau construction at t',
  kind: 'geometry',
  bounds: (m) => boundsOf(m.state.p),
  draw(painter, m, info) {
    if (m.state.mode === 'pseudocode') drawPseudocode(painter, m, info);
    else if (m.state.mode === 'bernstein') drawBernstein(painter, m, info);
    else drawConstruction(painter, m, info);
    if (m.note && !info.thumbnail) painter.note(m.note);
  },
  points: [controlPoints],
  addTo: controlPoints,
  trail: (m) => (pointReached(m) ? m.levels[m.n][0] : null),
};

/** P(t) is on the figure: the construction's last level, the pseudocode's return, the last blend. */
function pointReached({ state, shown, n }: DeCasteljauModel): boolean {
  if (state.mode === 'pseudocode') return shown.has('return');
  if (state.mode === 'bernstein') return shown.has('blend', n);
  return shown.has('level', n);
}

/** The construction level by level, with its subdivision's halves in the mode that shows them. */
function drawConstruction(painter: Painter, m: DeCasteljauModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { state, n, levels, shown } = m;
  const split = state.mode === 'halves';

  // The last step: the whole curve faintly, the part traced so far (0 … t) strongly.
  if (shown.has('curve') && !split) {
    painter.polylineFlat(m.curve, {
      color: theme.curveFaint,
      width: theme.sizes.curve * 0.8,
      role: 'curve',
    });
    if (state.t > 0) painter.polylineFlat(m.leftCurve, { color: theme.curve, role: 'curve' });
  }
  if (split) drawHalves(painter, m, shown.has('curve'));

  // Level 0 is the control polygon.
  if (shown.has('polygon')) {
    painter.polyline(state.p, { color: theme.polygon, width: theme.sizes.line, dash: [6, 5] });
  }
  for (let r = 1; r <= shown.count('level'); r++) {
    const color = levelColour(theme.palette, r);
    painter.polyline(levels[r], { color, width: theme.sizes.line, dash: levelDash(r) });
    // The last level's one point is P(t): over the handles (P(0) is on P₀).
    if (r === n) painter.movingPoint(levels[r][0], 1.6);
    else levels[r].forEach((point) => painter.dot(point, color, theme.sizes.point));
  }
  if (!info.thumbnail) drawLabels(painter, m);
}

/** The labels of the levels shown, each where it covers no other label and no point. */
function drawLabels(painter: Painter, m: DeCasteljauModel): void {
  const theme = painter.theme;
  const { n, levels, shown } = m;
  const points = levels.slice(0, shown.count('level') + 1).flat();
  const taken = handleLabelBoxes(painter, m.state.p);
  const labelAll = n <= (painter.view.width < NARROW ? 3 : LABEL_ALL_UP_TO);
  // The point on the curve first: it matters most, and gets the best spot.
  for (let r = shown.count('level'); r >= 1; r--) {
    const last = r === n;
    if (!labelAll && !last) continue;
    levels[r].forEach((point, i) =>
      placeLabel(
        painter,
        last ? `P_{${r},${i}} = P(t)` : `P_{${r},${i}}`,
        point,
        points,
        {
          color: last ? theme.ink : levelColour(theme.palette, r),
          halo: true,
          bold: last,
          size: theme.sizes.label * 0.9,
        },
        taken,
      ),
    );
  }
}

/** The two halves of the subdivision at t: polygons and curves, each in its own colour and dash. */
function drawHalves(painter: Painter, m: DeCasteljauModel, withCurves: boolean): void {
  const theme = painter.theme;
  ([0, 1] as const).forEach((half) => {
    const color = halfColour(theme.palette, half);
    if (withCurves) {
      painter.polylineFlat(half === 0 ? m.leftCurve : m.rightCurve, { color, role: 'curve' });
    }
    painter.polyline(half === 0 ? m.left : m.right, {
      color,
      width: theme.sizes.line * 1.6,
      alpha: 0.85,
      dash: HALF_DASH[half],
    });
    for (const q of half === 0 ? m.left : m.right) {
      painter.dot(q, color, theme.sizes.point * 0.9);
    }
  });
}
