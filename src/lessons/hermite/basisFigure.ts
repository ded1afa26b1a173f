import { basisValuesAt } from '../../math';
import { texNumber } from '../../render/formula';
import type { Painter } from '../../render/painter';
import type { Bounds } from '../../render/projection';
import type { KitFigure } from '../../kit/lesson';
import type { Revealed } from '../../kit/script';
import { valueColumn } from '../../kit/cursorValues';
import { plotYName } from '../../kit/plotMarks';
import type { HermiteModel } from './model';
import type { Reveal } from './script';
import type { HermiteState } from './state';

const BOUNDS: Bounds = { minX: 0, maxX: 1, minY: -0.25, maxY: 1.1 };
/** What each basis function weighs: H0 P_i, H1 P_i+1, H2 D_i, H3 D_i+1. */
const WEIGHS = ['P_i', 'P_{i+1}', 'D_i', 'D_{i+1}'];

/** H_k's value at the cursor as the plot writes it, with what it weighs. */
const valueText = (k: number, w: number) =>
  `H_${k} = ${texNumber(w, 3).replace('-', '−')} (× ${WEIGHS[k]})`;

/**
 * The step between the value axis' ticks: 0.25, or coarser where the plot is
 * too short for its numbers to stand one above another (presenter view under
 * a tall formula).
 */
function valueStep(painter: Painter): number {
  const [, top] = painter.view.toScreen([0, 1]);
  const [, bottom] = painter.view.toScreen([0, 0]);
  const room = painter.theme.sizes.small * 1.5;
  return [0.25, 0.5].find((step) => Math.abs(bottom - top) * step >= room) ?? 1;
}

/** How many of H0 … H3 the plot shows: those weighting the points, then those weighting the gradients. */
export const plottedBasis = (shown: Revealed<Reveal>) =>
  shown.has('gradientWeights') ? 4 : shown.has('pointWeights') ? 2 : 0;

export const basisFigure: KitFigure<HermiteState, HermiteModel> = {
  id: 'basis',
  title: 'The Hermite basis functions H0 to H3, with the cursor at μ',
  kind: 'plot',
  bounds: () => BOUNDS,
  // H0 … H3 at μ in rows above the plot, off the curves' peaks; kept in
  // every step, so the plot keeps its size as they appear.
  // (The widest: a negative value, with the longest name it weighs.)
  cursorValues: () => ({ count: 4, widest: valueText(3, -0.5) }),
  // H0 … H3 and their values at μ: the points and gradients do not change them.
  drawnFrom: (m) => [m.state.mu, m.shown.key],
  draw(painter, m, info) {
    const theme = painter.theme;
    const mu = m.state.mu;
    const plotted = plottedBasis(m.shown);
    painter.plotAxes(BOUNDS, 0.1, valueStep(painter), 'μ', '');
    const top = info.thumbnail ? 0 : plotYName(painter, BOUNDS, 'H_k(μ)');
    m.basis.curves.forEach((curve, k) => {
      if (k >= plotted) return;
      painter.polylineFlat(curve, {
        color: painter.color(k),
        width: info.hover === `H${k}` ? theme.sizes.curve * 1.6 : theme.sizes.line * 1.4,
      });
    });
    // The cursor in ink: no basis function has its colour.
    painter.segment([mu, BOUNDS.minY], [mu, BOUNDS.maxY], {
      color: theme.ink,
      width: theme.sizes.line,
      dash: [theme.sizes.line * 2, theme.sizes.line * 1.5],
    });
    const weights = m.patch.weights.slice(0, plotted);
    weights.forEach((w, k) => painter.dot([mu, w], painter.color(k), theme.sizes.point));
    if (info.thumbnail || !plotted) return;
    valueColumn(
      painter,
      mu,
      BOUNDS,
      top,
      weights.map((w, k) => ({
        text: valueText(k, w),
        color: painter.color(k),
      })),
    );
  },
  handles: (m) => [
    {
      id: 'cursor',
      label: 'μ',
      position: [m.state.mu, BOUNDS.minY],
      shape: 'diamond',
      showLabel: false,
    },
  ],
  moveHandle: (state, _id, to) => ({ ...state, mu: Math.min(1, Math.max(0, to[0])) }),
  pickAt: (m, at, tolerance) => (Math.abs(at[0] - m.state.mu) <= tolerance ? 'cursor' : null),
  hoverAt(m, at, tolerance) {
    if (at[0] < 0 || at[0] > 1) return null;
    let best: string | null = null;
    let distance = tolerance * 2;
    basisValuesAt(m.basis, at[0]).forEach((w, k) => {
      if (Math.abs(w - at[1]) < distance) {
        distance = Math.abs(w - at[1]);
        best = `H${k}`;
      }
    });
    return best;
  },
};
