import type { FigureSpec } from '../../app/lesson';
import type { Point } from '../../math';
import type { Painter } from '../../render/painter';
import { placeMemberLabels } from './labels';
import type { Member, QuadraticModel } from './model';
import { seriesColour } from '../../kit/seriesColours';
import { stackedLabels } from '../../kit/labels';
import { type QuadraticState, STEP } from './state';

export const quadraticFigure: FigureSpec<QuadraticState, QuadraticModel> = {
  id: 'quadratic',
  title: 'Three points with the parabola y(x) and parametric quadratics through them',
  kind: 'geometry',
  bounds: (m) => m.bounds,
  draw(painter, m, info) {
    const step = m.state.step;
    if (step >= STEP.parabola && step <= STEP.ticks) {
      drawExplicit(painter, m, info.thumbnail, step === STEP.parabola);
    }
    if (step >= STEP.parametric) drawParametric(painter, m, info.thumbnail, step >= STEP.ticks);
  },
  handles: (m) => {
    const labels = stackedLabels(m.state.p, (i) => `P_${i}`);
    return m.state.p.map((point, i) => ({ id: `p${i}`, ...labels[i], position: point }));
  },
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    return { ...state, p: state.p.map((point, k) => (k === i ? [to[0], to[1]] : point)) };
  },
};

/** Step 1: y = a2x² + a1x + a0, or a plain sentence on why there is none (faint under steps 2–3). */
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

/** From step 2: the quadratic on the slider, strong, over the members of the step; dots from step 3. */
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
