import type { FigureSpec } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import { boundsOf } from '../../render/viewport';
import {
  explicitParabola,
  muRules,
  quadraticTicks,
  sampleParabola,
  sampleQuadratic,
  sameXWords,
} from './model';
import { FAMILY, type QuadraticState } from './state';
import type { Point } from '../../math';
import { distanceToSegment } from '../../interact/editPoints';

const fmtMu = (mu: number) => String(Number(mu.toFixed(2)));

export const quadraticFigure: FigureSpec<QuadraticState> = {
  id: 'quadratic',
  title: 'Three points with the parabola y(x) and parametric quadratics through them',
  kind: 'geometry',
  bounds(state) {
    const bounds = boundsOf([...state.p, ...shownCurve(state)]);
    if (state.step > 0 || explicitParabola(state.p).kind === 'ok') return bounds;
    // Room above the points for the note that says why there is no parabola.
    const height = Math.max(bounds.maxY - bounds.minY, (bounds.maxX - bounds.minX) * 0.3, 1);
    return { ...bounds, maxY: bounds.maxY + 0.6 * height };
  },
  draw(painter, state, info) {
    if (state.step <= 1) drawExplicit(painter, state, info.thumbnail, state.step === 0);
    if (state.step >= 1) drawParametric(painter, state, info.thumbnail);
  },
  handles: (state) =>
    state.p.map((point, i) => ({ id: `p${i}`, label: `P_${i}`, position: point })),
  moveHandle(state, id, to) {
    const i = Number(id.slice(1));
    return { ...state, p: state.p.map((point, k) => (k === i ? to : point)) };
  },
};

/** What "fit view" must show besides the points: the main curve of the step, apex included. */
function shownCurve(state: QuadraticState): Point[] {
  if (state.step > 0) {
    const mus = [
      state.mu,
      ...(state.step === 2 ? FAMILY : []),
      ...(state.step === 3 ? usableRuleMus(state) : []),
    ];
    return mus.flatMap((mu) => sampleQuadratic(state.p, mu, 32));
  }
  if (explicitParabola(state.p).kind === 'same-x') return [];
  const xs = state.p.map((q) => q[0]);
  return sampleParabola(state.p, Math.min(...xs), Math.max(...xs), 32);
}

/** Step 0: y = a2x² + a1x + a0, or a plain sentence on why there is none. */
function drawExplicit(painter: Painter, state: QuadraticState, thumbnail: boolean, main: boolean) {
  const theme = painter.theme;
  const parabola = explicitParabola(state.p);
  const p = state.p;
  if (parabola.kind === 'same-x') {
    if (!main || thumbnail) return;
    const { x } = parabola;
    const column = p.filter((q) => q[0] === x);
    painter.segment(column[0], column[column.length - 1], {
      color: theme.accent,
      width: theme.sizes.line,
      dash: [4, 4],
    });
    painter.note(
      `No parabola y(x): ${sameXWords(p, x, fmtNumber)}, and a function has one y at each x.`,
    );
    return;
  }
  const xs = p.map((q) => q[0]);
  const span = Math.max(...xs) - Math.min(...xs);
  const curve = sampleParabola(p, Math.min(...xs) - 0.15 * span, Math.max(...xs) + 0.15 * span);
  const ok = parabola.kind === 'ok';
  if (main) {
    painter.polyline(curve, {
      color: ok ? theme.curve : theme.curveFaint,
      width: ok ? theme.sizes.curve : theme.sizes.line,
      dash: ok ? undefined : [8, 6],
    });
  } else if (ok) {
    painter.polyline(curve, { color: theme.curveFaint, width: theme.sizes.line, dash: [6, 5] });
  }
  if (thumbnail) return;
  if (ok) {
    painter.label('y(x)', curve[Math.round(curve.length * 0.8)], {
      dx: 6,
      dy: -theme.sizes.label,
      color: main ? theme.ink : theme.muted,
      halo: true,
    });
  } else if (main) {
    painter.note(
      `Backwards in x: x1 = ${fmtNumber(p[1][0])} is not between ${fmtNumber(p[0][0])} and ${fmtNumber(p[2][0])}. The dashed y(x) meets all three points, but not in order: a function cannot turn back.`,
    );
  }
}

/** Steps 1–3: the quadratic on the slider, strong, over the members of the step. */
function drawParametric(painter: Painter, state: QuadraticState, thumbnail: boolean) {
  const theme = painter.theme;
  const members =
    state.step === 2
      ? familyMembers(painter, state.mu)
      : state.step === 3
        ? ruleMembers(painter, state)
        : [];
  const curves = members.map((member) => sampleQuadratic(state.p, member.mu));
  members.forEach((member, k) =>
    painter.polyline(curves[k], { color: member.color, width: theme.sizes.line * 1.3 }),
  );
  const current = sampleQuadratic(state.p, state.mu);
  painter.polyline(current, { color: theme.curve });
  if (thumbnail) return;
  members.forEach((member) =>
    drawTicks(painter, quadraticTicks(state.p, member.mu), member.color, theme.sizes.point * 0.75),
  );
  drawTicks(painter, quadraticTicks(state.p, state.mu), theme.accent, theme.sizes.point);
  const slider = {
    mu: state.mu,
    color: theme.ink,
    text: members.length ? `slider: μ_1 = ${fmtMu(state.mu)}` : `μ_1 = ${fmtMu(state.mu)}`,
  };
  placeLabels(painter, state, [...members, slider], [...curves, current]);
}

/** Larger dots at μ = 0, 0.5 and 1, smaller ones at the tenths between. */
function drawTicks(painter: Painter, ticks: readonly Point[], color: string, radius: number) {
  ticks.forEach((tick, k) => painter.dot(tick, color, k % 5 === 0 ? radius : radius * 0.65));
}

interface Member {
  mu: number;
  color: string;
  text: string;
}

/** Figure 2 of the notes: the same three points, five values of μ1, five curves. */
const familyMembers = (painter: Painter, mu: number): Member[] =>
  FAMILY.map((mu, k) => ({ mu, color: painter.color(k), text: `μ_1 = ${fmtMu(mu)}` })).filter(
    // The slider's curve is drawn (and labelled) on top anyway.
    (member) => Math.abs(member.mu - mu) > 1e-9,
  );

const usableRuleMus = (state: QuadraticState) =>
  muRules(state.p)
    .filter((rule) => rule.usable)
    .map((rule) => rule.mu);

/** Step 3: the members chosen by the uniform, chord-length and centripetal rules. */
const ruleMembers = (painter: Painter, state: QuadraticState): Member[] =>
  muRules(state.p)
    .map((rule, k) => ({
      mu: rule.mu,
      color: painter.color(k),
      text: `${rule.name}: μ_1 = ${fmtMu(rule.mu)}`,
      usable: rule.usable,
    }))
    .filter((member) => member.usable);

/**
 * Each member's μ1 in a box, where its curve strays furthest from the polygon
 * P0 P1 P2 (where the members differ), moved along the curve if it would
 * cover a label already placed.
 */
function placeLabels(
  painter: Painter,
  state: QuadraticState,
  members: readonly Member[],
  curves: readonly Point[][],
) {
  const theme = painter.theme;
  const size = theme.sizes.label * 0.9;
  const placed: { x: number; y: number; w: number; h: number }[] = [];
  members.forEach((member, k) => {
    const width = member.text.length * size * 0.52 + size;
    const height = size * 1.6;
    const inside = (point: Point) => {
      const [x, y] = painter.view.toScreen(point);
      return (
        x > width / 2 + 4 &&
        x < painter.view.width - width / 2 - 4 &&
        y > height &&
        y < painter.view.height - height
      );
    };
    const candidates = curves[k]
      .slice(4, -4)
      .filter(inside)
      .map((point) => ({ point, away: distanceToPolygon(point, state.p) }))
      .sort((a, b) => b.away - a.away);
    let best = candidates[0];
    for (const candidate of candidates) {
      const [x, y] = painter.view.toScreen(candidate.point);
      const overlaps = placed.some(
        (box) => Math.abs(box.x - x) < (box.w + width) / 2 && Math.abs(box.y - y) < height,
      );
      if (!overlaps) {
        best = candidate;
        break;
      }
    }
    if (!best) return;
    const [x, y] = painter.view.toScreen(best.point);
    placed.push({ x, y, w: width, h: height });
    painter.dot(best.point, member.color, theme.sizes.point * 0.6);
    painter.label(member.text, best.point, {
      align: 'center',
      box: true,
      color: member.color,
      size,
      bold: true,
    });
  });
}

function distanceToPolygon(point: Point, polygon: readonly Point[]): number {
  let best = Infinity;
  for (let i = 0; i + 1 < polygon.length; i++) {
    best = Math.min(best, distanceToSegment(point, polygon[i], polygon[i + 1]));
  }
  return best;
}

/** A coordinate as a person would write it: up to three decimals. */
export const fmtNumber = (v: number) => String(Number(v.toFixed(3)));
