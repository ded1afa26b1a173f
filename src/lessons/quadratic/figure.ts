import type { KitFigure } from '../../kit/lesson';
import type { Point } from '../../math';
import type { Painter } from '../../render/painter';
import { placeMemberLabels } from './labels';
import type { Member, QuadraticModel } from './model';
import { seriesColour } from '../../kit/seriesColours';
import { threePoints } from './points';
import type { QuadraticState } from './state';

export const quadraticFigure: KitFigure<QuadraticState, QuadraticModel> = {
  id: 'quadratic',
  title: 'Three points with the parabola y(x) and parametric quadratics through them',
  kind: 'geometry',
  bounds: (m) => m.bounds,
  draw(painter, m, info) {
    const { shown } = m;
    // y(x) from its step until the family: strong at its own step, faint under P(μ) after.
    if (shown.has('parabola') && !shown.has('family')) {
      drawExplicit(painter, m, info.thumbnail, shown.is('parabola'));
    }
    if (shown.has('parametric')) drawParametric(painter, m, info.thumbnail, shown.has('ticks'));
  },
  points: [threePoints],
};

/** y = a2x² + a1x + a0, or a plain sentence on why there is none (faint under P(μ) and its dots). */
function drawExplicit(painter: Painter, m: QuadraticModel, thumbnail: boolean, main: boolean) {
  const theme = painter.theme;
  const { parabola, curve, column, labelAt, figureNote } = m.explicit;
  if (column) {
    if (!main || thumbnail) return;
    painter.segment(column[0], column[1], {
      color: theme.accent,
      width: theme.sizes.line,
      dash: [4, 4],
    });
    if (figureNote) painter.note(figureNote);
    return;
  }
  const ok = parabola.kind === 'ok';
  if (main) {
    painter.polyline(curve, {
      color: ok ? theme.curve : theme.curveFaint,
      width: ok ? theme.sizes.curve : theme.sizes.line,
      dash: ok ? undefined : [8, 6],
      role: 'curve',
    });
  } else if (ok) {
    painter.polyline(curve, { color: theme.curveFaint, width: theme.sizes.line, dash: [6, 5] });
  }
  if (thumbnail) return;
  if (ok && labelAt) {
    painter.label('y(x)', labelAt, {
      dx: 6,
      dy: -theme.sizes.label,
      color: main ? theme.ink : theme.muted,
      halo: true,
    });
  } else if (main && figureNote) {
    painter.note(figureNote);
  }
}

/** The quadratic on the slider, strong, over the members of the step; its dots once they are shown. */
function drawParametric(painter: Painter, m: QuadraticModel, thumbnail: boolean, dots: boolean) {
  const theme = painter.theme;
  const { current, members } = m.parametric;
  if (!current) return;
  const colour = (member: Member) =>
    member.colour === null ? theme.ink : seriesColour(theme.palette, member.colour);
  for (const member of members) {
    painter.polyline(member.curve, {
      color: colour(member),
      width: theme.sizes.line * 1.3,
      role: 'curve',
    });
  }
  painter.polyline(current.curve, { color: theme.curve, role: 'curve' });
  // A member that is the chosen curve (uniform's μ₁ = 0.5 chosen) goes over
  // it, dashed: drawn beneath, the legend named a curve no one could see.
  const dash = theme.sizes.line * 3;
  const same = members.filter((member) => Math.abs(member.mu - current.mu) < 1e-9);
  same.forEach((member, k) =>
    painter.polyline(member.curve, {
      color: colour(member),
      width: theme.sizes.line * 1.3,
      // Where two rules agree too, each dashed at its own period: both seen.
      dash: [dash, dash * (k + 1)],
    }),
  );
  if (thumbnail) return;
  if (dots) {
    for (const member of members)
      drawTicks(painter, member.ticks, colour(member), theme.sizes.point * 0.75);
    drawTicks(painter, current.ticks, theme.accent, theme.sizes.point);
  }
  placeMemberLabels(painter, [...members, current], colour);
}

/** Larger dots at μ = 0, 0.5 and 1, smaller ones at the tenths between. */
function drawTicks(painter: Painter, ticks: readonly Point[], color: string, radius: number) {
  ticks.forEach((tick, k) => painter.dot(tick, color, k % 5 === 0 ? radius : radius * 0.65));
}
