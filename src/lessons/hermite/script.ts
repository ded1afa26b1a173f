import { filled } from '../../kit/format';
import { basisOneLine, bezierPoints, patchMatrixLine } from './formulas';
import type { HermiteModel } from './model';
import { type HermiteState, patchCount, revealed } from './state';

// The clicker's script: the points, their gradients, the basis functions,
// each patch solved through the patch matrix, P(μ), and the Bézier view.

export function describeStep(state: HermiteState, k: number): string {
  const m = patchCount(state);
  const shown = revealed({ ...state, step: k });
  if (k === 0) return `The points P0 … P${m}: where the curve must pass`;
  if (k === 1)
    return state.mode === 'hand'
      ? `The gradients D0 … D${m}, set by hand (arrows drawn a third as long)`
      : `The gradients D0 … D${m} from the neighbours: Dₖ = (Pₖ₊₁ − Pₖ₋₁)/2, zero at both ends`;
  if (k === 2) return 'H0 and H1 weight the end points: H0 + H1 = 1';
  if (k === 3) return 'H2 and H3 weight the end gradients: H2 is never negative, H3 never positive';
  if (shown.building !== null) {
    const i = shown.building;
    return `Patch ${i + 1} of ${m}, from P${i} to P${i + 1}: the patch matrix turns its four conditions into a0 … a3`;
  }
  if (!shown.bezier) return `P(μ) on patch ${state.patch + 1}: H0 P + H1 P + H2 D + H3 D`;
  return 'The same patch as a Bézier curve: its inner control points are the arrow tips, P ± D/3';
}

export function stepFormula(model: HermiteModel, state: HermiteState): string | null {
  const { patch, shown } = model;
  const i = patch.index;
  switch (state.step) {
    case 0:
      return 'P(\\mu) = a_3\\mu^3 + a_2\\mu^2 + a_1\\mu + a_0,\\quad P(0) = P_i,\\ P(1) = P_{i+1}';
    case 1:
      return "P'(0) = D_i,\\qquad P'(1) = D_{i+1}";
    case 2:
      return 'H_0 = 2\\mu^3 - 3\\mu^2 + 1,\\qquad H_1 = -2\\mu^3 + 3\\mu^2';
    case 3:
      return 'H_2 = \\mu^3 - 2\\mu^2 + \\mu,\\qquad H_3 = \\mu^3 - \\mu^2';
  }
  if (shown.building !== null)
    return filled(patchMatrixLine([patch.p0, patch.p1, patch.d0, patch.d1], patch.coefficients));
  if (!shown.bezier) return filled(basisOneLine(i, state.mu, patch.weights, patch.point));
  return filled(bezierPoints(patch.bezier, true));
}
