import type { Point } from '../../app/lesson';
import type { KitFigure } from '../../kit/lesson';
import { seriesDash } from '../../kit/seriesColours';
import type { Painter } from '../../render/painter';
import { fixed, words } from '../../kit/format';
import { highlightedIndex } from './hover';
import { halfway } from './comparison';
import type { BlendingModel, Compared } from './model';
import type { Passes } from './passes';
import { controlPoints } from './points';
import type { BlendingState } from './state';

/** Weight labels beside the points stay readable up to this degree. */
const LABEL_WEIGHTS_UP_TO = 8;

export const curveFigure: KitFigure<BlendingState, BlendingModel> = {
  id: 'curve',
  title: 'Bézier curve with every control point weighted at μ',
  kind: 'geometry',
  bounds: (m) => m.curveBounds,
  // The points, what is compared and the step; μ only from the step that
  // draws something at μ (a halo, P(μ), the compared point, P(1 − μ)): until
  // then a drag of μ moves the plot's cursor and leaves this canvas as it is.
  drawnFrom: ({ state, shown, drawn }) => [
    state.p,
    state.comparison,
    shown.key,
    drawn.weights > 0 || drawn.point || drawn.atMu || drawn.reversed ? state.mu : null,
  ],
  draw(painter, m, info) {
    const theme = painter.theme;
    const { state, n, pointWeights, point, compared, drawn } = m;
    const highlighted = highlightedIndex(info.hover);

    if (compared && drawn.hull)
      painter.polygon(compared.hull, theme.muted, theme.tint, {
        color: theme.muted,
        width: theme.sizes.thin,
      });
    if (compared?.curve && drawn.comparedCurve) {
      painter.polyline(compared.curve, {
        color: theme.muted,
        width: theme.sizes.curve * 0.8,
        dash: [10, 6],
      });
    }
    if (compared && drawn.tangents) drawHermiteData(painter, compared);

    painter.polyline(state.p, { color: theme.polygon, width: theme.sizes.line, dash: [6, 5] });
    if (drawn.curve) painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });

    // Each control point's halo grows with its weight at μ: the curve point is
    // their weighted average, so the biggest halo pulls hardest.
    const largest = theme.sizes.handle * 5;
    // Weights written so far: a point too close to one of them goes without (its row in the table has it).
    const placed: Point[] = [];
    // At a comparison's values at μ, the lines go to the point those weights make.
    const weighted = (drawn.atMu && compared?.point?.at) || point;
    state.p.forEach((control, i) => {
      const weight = pointWeights[i];
      if (i >= drawn.weights || weight === null) return;
      const color = painter.color(i);
      const dash = seriesDash(painter, i);
      // A negative weight pulls away: its halo is as large as its size, and its number says the sign.
      const radius = theme.sizes.handle * 1.3 + largest * Math.min(1, Math.abs(weight));
      const lit = highlighted === i;
      painter.ring(
        control,
        radius,
        { color, width: lit ? theme.sizes.line * 2 : theme.sizes.thin, alpha: 0.9, dash },
        color,
        lit ? 0.4 : 0.22,
      );
      if (drawn.point) {
        painter.segment(control, weighted, {
          color,
          width: Math.max(theme.sizes.thin, theme.sizes.line * 3 * Math.min(1, Math.abs(weight))),
          alpha: lit ? 0.9 : 0.45,
          dash,
        });
      }
      if (!info.thumbnail && n <= LABEL_WEIGHTS_UP_TO && !crowded(painter, placed, control)) {
        placed.push(control);
        underPoint(painter, fixed(weight, 3), control, color);
      }
    });
    // The weights are written under the points: P(μ), its label and the
    // compared point keep clear of them.
    const below = painter.view.worldLength(theme.sizes.handle + theme.sizes.small * 1.1);
    const crowd = state.p.flatMap((q) => [q, [q[0], q[1] - below]]);

    // Hermite's data: the patch's end points, named as the lecture names them.
    if (drawn.data && !info.thumbnail)
      [0, n].forEach((i) =>
        painter.ring(state.p[i], theme.sizes.handle * 2.2, {
          color: theme.accent,
          width: theme.sizes.line * 1.5,
        }),
      );
    // The B-spline's ends: not at P0 and PN.
    if (compared?.curve && drawn.ends)
      [compared.curve[0], compared.curve[compared.curve.length - 1]].forEach((end) =>
        painter.dot(end, theme.muted, theme.sizes.point * 1.2),
      );

    const other = drawn.atMu ? compared?.point : null;
    if (other) {
      painter.ring(other.at, theme.sizes.point * 1.4, {
        color: theme.muted,
        width: theme.sizes.line * 1.5,
      });
      if (!info.thumbnail) {
        painter.labelClear(other.label, other.at, [...crowd, point], {
          color: theme.muted,
          halo: true,
          bold: true,
        });
      }
    }
    if (m.passes && (drawn.onLagrange || drawn.onBezier))
      drawPasses(painter, m.passes, state.p, drawn.onBezier, !info.thumbnail);
    if (m.note && !info.thumbnail) painter.note(m.note);
    if (drawn.reversed) {
      painter.dot(m.mirrored, theme.muted, theme.sizes.point * 1.3);
      if (!info.thumbnail)
        painter.labelClear('P(1 − μ)', m.mirrored, [...crowd, point], {
          color: theme.muted,
          halo: true,
          bold: true,
        });
    }
    if (!drawn.point) return;
    painter.movingPoint(point, 1.5);
    if (!info.thumbnail) {
      painter.labelClear('P(μ)', point, other ? [...crowd, other.at] : crowd, {
        color: theme.ink,
        halo: true,
        bold: true,
      });
    }
  },
  trail: (m) => (m.drawn.point ? m.point : null),
  points: [controlPoints],
  addTo: controlPoints,
};

/**
 * The Hermite data of the same cubic, the gradients D0 and D3, drawn at half
 * length and labelled so (as bezier-properties draws its end tangents): at
 * full length, three times the polygon's end legs, they took the view and
 * left the curve a small loop in its middle (#19).
 */
function drawHermiteData(painter: Painter, compared: Compared): void {
  const theme = painter.theme;
  compared.arrows.forEach(([from, tip], end) => {
    const half = halfway(from, tip);
    painter.arrow(from, half, { color: theme.accent, width: theme.sizes.line });
    painter.label(end === 0 ? '½D_0' : '½D_3', half, {
      dx: 6,
      dy: -theme.sizes.label * 0.7,
      color: theme.accent,
      halo: true,
      bold: true,
    });
  });
}

/**
 * Which points a curve passes through: a ring round each point on the
 * Lagrange curve, and once the Bézier curve is asked, a smaller ring round
 * each point on it and a line from each other point to its nearest point.
 * Under every point, its distance to the curve asked last.
 */
function drawPasses(
  painter: Painter,
  passes: Passes,
  p: readonly Point[],
  bezier: boolean,
  labels: boolean,
): void {
  const theme = painter.theme;
  const width = theme.sizes.line * 1.5;
  p.forEach((control, i) => {
    if (passes.onLagrange[i])
      painter.ring(control, theme.sizes.handle * 2.4, { color: theme.muted, width });
  });
  if (bezier)
    p.forEach((control, i) => {
      const near = passes.bezier[i];
      if (passes.onBezier[i])
        painter.ring(control, theme.sizes.handle * 1.6, { color: theme.curve, width });
      else {
        painter.segment(control, near.point, {
          color: theme.curve,
          width: theme.sizes.line,
          dash: [4, 3],
        });
        painter.dot(near.point, theme.curve, theme.sizes.point);
      }
    });
  if (!labels) return;
  const [near, color] = bezier ? [passes.bezier, theme.curve] : [passes.lagrange, theme.muted];
  p.forEach((control, i) => underPoint(painter, `d = ${words(near[i].distance)}`, control, color));
}

/** Would a weight written under `p` run into one written under an earlier point? */
function crowded(painter: Painter, placed: readonly Point[], p: Point): boolean {
  const [x, y] = painter.view.toScreen(p);
  const size = painter.theme.sizes.small;
  return placed.some((q) => {
    const [qx, qy] = painter.view.toScreen(q);
    return Math.abs(qx - x) < size * 3.6 && Math.abs(qy - y) < size * 1.6;
  });
}

/** A small value written under a control point, in the point's colour: its weight, or its distance to a curve. */
function underPoint(painter: Painter, text: string, at: Point, color: string): void {
  const sizes = painter.theme.sizes;
  painter.label(text, at, {
    dy: sizes.handle + sizes.small * 1.1,
    align: 'center',
    color,
    halo: true,
    bold: true,
    size: sizes.small,
  });
}
