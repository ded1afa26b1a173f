import type { FigureSpec } from '../../app/lesson';
import { hermiteBasis } from '../../math';
import type { Bounds } from '../../render/viewport';
import type { HermiteState } from './state';

const BOUNDS: Bounds = { minX: 0, maxX: 1, minY: -0.25, maxY: 1.1 };
/** What each basis function weighs: H0 P_i, H1 P_i+1, H2 D_i, H3 D_i+1. */
const WEIGHS = ['P_i', 'P_{i+1}', 'D_i', 'D_{i+1}'];

/** H0 … H3 sampled over [0, 1]. */
function sampleBasis(count = 200): Float64Array[] {
  const curves = [0, 1, 2, 3].map(() => new Float64Array(2 * (count + 1)));
  for (let i = 0; i <= count; i++) {
    const mu = i / count;
    hermiteBasis(mu).forEach((value, k) => {
      curves[k][2 * i] = mu;
      curves[k][2 * i + 1] = value;
    });
  }
  return curves;
}

export const basisFigure: FigureSpec<HermiteState> = {
  id: 'basis',
  title: 'The Hermite basis functions H0 to H3, with the cursor at μ',
  kind: 'plot',
  bounds: () => BOUNDS,
  draw(painter, state, info) {
    const theme = painter.theme;
    painter.plotAxes(BOUNDS, 0.1, 0.25, 'μ', info.thumbnail ? '' : 'H_k(μ)');
    sampleBasis().forEach((curve, k) =>
      painter.polylineFlat(curve, {
        color: painter.color(k),
        width: info.hover === `H${k}` ? theme.sizes.curve * 1.6 : theme.sizes.line * 1.4,
      }),
    );
    painter.segment([state.mu, BOUNDS.minY], [state.mu, BOUNDS.maxY], {
      color: theme.accent,
      width: theme.sizes.line,
    });
    const weights = hermiteBasis(state.mu);
    weights.forEach((w, k) => painter.dot([state.mu, w], painter.color(k), theme.sizes.point));
    if (info.thumbnail) return;
    painter.cursorLabels(
      state.mu,
      weights.map((w, k) => ({
        y: w,
        text: `H_${k} = ${w.toFixed(3)} (× ${WEIGHS[k]})`,
        color: painter.color(k),
      })),
    );
  },
  handles: (state) => [
    {
      id: 'cursor',
      label: 'μ',
      position: [state.mu, BOUNDS.minY],
      shape: 'diamond',
      showLabel: false,
    },
  ],
  moveHandle: (state, _id, to) => ({ ...state, mu: Math.min(1, Math.max(0, to[0])) }),
  pickAt: (state, at, tolerance) => (Math.abs(at[0] - state.mu) <= tolerance ? 'cursor' : null),
  hoverAt(_state, at, tolerance) {
    if (at[0] < 0 || at[0] > 1) return null;
    let best: string | null = null;
    let distance = tolerance * 2;
    hermiteBasis(at[0]).forEach((w, k) => {
      if (Math.abs(w - at[1]) < distance) {
        distance = Math.abs(w - at[1]);
        best = `H${k}`;
      }
    });
    return best;
  },
};
