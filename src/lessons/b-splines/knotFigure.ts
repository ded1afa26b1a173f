import type { Handle } from '../../app/lesson';
import type { KitFigure } from '../../kit/lesson';
import { drawLegend } from '../../kit/legend';
import { labelWidth } from '../../render/labelWidth';
import type { Painter } from '../../render/painter';
import type { Bounds } from '../../render/projection';
import { knotIds } from './ids';
import { knotRuns } from './knotGeometry';
import type { BSplineModel } from './model';
import { drawnFromAllButPoints } from './basisFigure';
import { plotRange, uStep } from './plotRange';
import { type BSplineState, isUniformPart } from './state';

/** The knots are set by the lesson, not dragged: the matrix form's, and the continuity scene's steps. */
const fixedKnots = (m: BSplineModel) => isUniformPart(m.state.part) || m.kind === 'continuity';
/**
 * Knots are editable where the lesson is about them (not the matrix form's fixed
 * uniform cubic), once the step shows more than the points.
 */
const editable = (m: BSplineModel) => !fixedKnots(m) && !m.shown.is('points');

/** Marks on the strip that a scene ties to the curve: the knot values of its joins, the watched knot. */
function stripMarks(painter: Painter, m: BSplineModel): void {
  const theme = painter.theme;
  // A tick above each knot value that has a point on the curve (the handles cover the line).
  if (m.kind === 'meanings' && m.shown.has('joins'))
    for (const k of m.knotPoints)
      painter.segment([k.u, 0.3], [k.u, 0.9], { color: theme.ink, width: theme.sizes.line * 2 });
  if (m.kind === 'continuity' && !m.shown.is('points'))
    painter.ring([m.watched.u, 0], theme.sizes.handle * 2.2, {
      color: theme.accent,
      width: theme.sizes.line * 2,
    });
}
/** A knot dropped this close to a neighbour (a share of the range) lands on it: a repeated knot. */
const SNAP = 0.015;

function stripBounds(m: BSplineModel): Bounds {
  const [minX, maxX] = plotRange(m);
  return { minX, maxX, minY: -1, maxY: 1 };
}

export const knotFigure: KitFigure<BSplineState, BSplineModel> = {
  id: 'knots',
  title: 'The knot vector: drag a knot, stack knots to repeat one',
  kind: 'plot',
  height: 64,
  bounds: stripBounds,
  drawnFrom: drawnFromAllButPoints,
  draw(painter, m, info) {
    const theme = painter.theme;
    const { minX, maxX } = stripBounds(m);
    const [a, b] = m.domain;
    painter.segment([minX, 0], [maxX, 0], { color: theme.muted, width: theme.sizes.line });
    painter.segment([a, 0], [b, 0], { color: theme.ink, width: theme.sizes.line * 2.5 });
    // The cursor runs down to just under the knots' diamonds, not through the
    // row of knot names below them: a name stays at its knot.
    const [, lineY] = painter.view.toScreen([m.u, 0]);
    const [, cursorEnd] = painter.view.toWorld([0, lineY + theme.sizes.handle * 1.2]);
    painter.segment([m.u, cursorEnd], [m.u, 1], {
      color: theme.accent,
      width: theme.sizes.line,
    });
    const uniform = isUniformPart(m.state.part);
    if (m.shown.is('points') && !uniform) return;
    const size = theme.sizes.label * 0.75;
    stripMarks(painter, m);
    // A name per run of knots, below the line or, where the one before is in
    // the way, above it: in one row at a 1366 × 768 projector, u₄ and the
    // clamped end's u₇…₁₀ ×4 went unnamed.
    // (Not above where the uniform knots' legend stands.)
    const legend = !info.thumbnail && uStep(m) > 0 && uniform;
    const clear = theme.sizes.handle * 1.3 + size * 0.8;
    const rows = [
      { dy: clear, right: -Infinity },
      ...(legend ? [] : [{ dy: -clear, right: -Infinity }]),
    ];
    for (const [j, count] of knotRuns(m.knots)) {
      const u = m.knots[j];
      if (fixedKnots(m)) painter.dot([u, 0], theme.ink, theme.sizes.point);
      if (info.thumbnail) continue;
      const text = count > 1 ? `u_{${j}…${j + count - 1}} ×${count}` : `u_{${j}}`;
      const x = painter.view.toScreen([u, 0])[0];
      // Centred under its knot, or as near it as the figure's edges allow.
      const half = labelWidth(painter, text, { size }) / 2;
      const centre = Math.min(Math.max(x, half + 2), painter.view.width - half - 2);
      const row = rows.find((r) => centre - half >= r.right + size * 0.6);
      if (!row) continue;
      row.right = centre + half;
      painter.label(text, [u, 0], {
        dx: centre - x,
        dy: row.dy,
        color: count > 1 ? theme.accent : theme.muted,
        align: 'center',
        size,
        // A knot's name at its knot or not at all: moved aside, u₆ read as u₇.
        fixed: true,
      });
    }
    if (legend) {
      drawLegend(
        painter,
        [{ text: 'uniform knots (the slides’ matrix form)', color: theme.muted }],
        {
          top: 2,
          size: theme.sizes.label * 0.75,
        },
      );
    }
  },
  handles(m) {
    if (!editable(m)) return [];
    const handles: Handle[] = [];
    for (const [first, count] of knotRuns(m.knots)) {
      for (let j = first; j < first + count; j++) {
        const pull: [number, number] =
          count === 1 ? [0, 1] : j === first ? [-1, 0] : j === first + count - 1 ? [1, 0] : [0, 1];
        handles.push({
          id: knotIds.id(j),
          label: `u_{${j}}`,
          position: [m.knots[j], 0],
          shape: 'diamond',
          showLabel: false,
          pull,
        });
      }
    }
    return handles;
  },
  // A knot moves along its line, between its neighbours; dropped near one, it lands on it.
  moveHandle(state, id, to, m) {
    const j = knotIds.index(id);
    if (j === null) return state;
    const u = state.knots;
    const [minX, maxX] = plotRange(m);
    const low = j > 0 ? u[j - 1] : minX - (maxX - minX);
    const high = j < u.length - 1 ? u[j + 1] : maxX + (maxX - minX);
    const snap = SNAP * (maxX - minX);
    let v = Math.round(to[0] * 1000) / 1000;
    if (v - low < snap) v = low;
    if (high - v < snap) v = high;
    v = Math.min(high, Math.max(low, v));
    const next = u.map((knot, k) => (k === j ? v : knot));
    // The curve lives on [u_p, u_{m+1}]: that interval must not close up.
    if (!(next[state.degree] < next[state.points.length])) return state;
    return { ...state, knots: next };
  },
};
