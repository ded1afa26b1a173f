import type { FigureSpec } from '../../app/lesson';
import { basisValuesAt } from '../../math';
import type { Bounds } from '../../render/projection';
import type { HermiteModel } from './model';
import type { HermiteState } from './state';

const BOUNDS: Bounds = { minX: 0, maxX: 1, minY: -0.25, maxY: 1.1 };
/** What each basis function weighs: H0 P_i, H1 P_i+1, H2 D_i, H3 D_i+1. */
const WEIGHS = ['P_i', 'P_{i+1}', 'D_i', 'D_{i+1}'];

export const basisFigure: FigureSpec<HermiteState, HermiteModel> = {
  id: 'basis',
  title: 'The Hermite basis functions H0 to H3, with the cursor at μ',
  kind: 'plot',
  bounds: () => BOUNDS,
  draw(painter, m, info) {
    const theme = painter.theme;
    const mu = m.state.mu;
    painter.plotAxes(BOUNDS, 0.1, 0.25, 'μ', info.thumbnail ? '' : 'H_k(μ)');
    m.basis.curves.forEach((curve, k) =>
      painter.polylineFlat(curve, {
        color: painter.color(k),
        width: info.hover === `H${k}` ? theme.sizes.curve * 1.6 : theme.sizes.line * 1.4,
      }),
    );
    painter.segment([mu, BOUNDS.minY], [mu, BOUNDS.maxY], {
      color: theme.accent,
      width: theme.sizes.line,
    });
    const weights = m.patch.weights;
    weights.forEach((w, k) => painter.dot([mu, w], painter.color(k), theme.sizes.point));
    if (info.thumbnail) return;
    painter.cursorLabels(
      mu,
      weights.map((w, k) => ({
        y: w,
        text: `H_${k} = ${w.toFixed(3)} (× ${WEIGHS[k]})`,
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
