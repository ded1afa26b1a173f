import { filled } from '../../kit/format';
import { repeat, script, step, type StepAt } from '../../kit/script';
import { basisOneLine, bezierPoints, patchMatrixLine } from './formulas';
import type { HermiteModel } from './model';
import { type HermiteState, patchCount } from './state';

/** What the steps reveal, by name: the figures and the panel ask for these. */
export type Reveal =
  'points' | 'gradients' | 'pointWeights' | 'gradientWeights' | 'patch' | 'pointAtMu' | 'bezier';

type At = StepAt<HermiteState, HermiteModel>;

/** A step the script has only when the state asks for it (a step repeated once or not at all). */
const stepIf = (
  name: Reveal,
  when: (state: HermiteState) => boolean,
  caption: string,
  formula: (at: At) => string | null,
) => repeat<HermiteState, HermiteModel, Reveal>(name, (s) => (when(s) ? 1 : 0), caption, formula);

/**
 * The clicker's script: the points, their gradients, the basis functions
 * that weight the points and then the gradients, each patch solved through
 * the patch matrix (one press per patch), P(μ) on the chosen patch, and,
 * with the Bézier view on, its control points.
 */
export const construction = script<HermiteState, HermiteModel, Reveal>(
  step(
    'points',
    ({ state }) => `The points P0 … P${patchCount(state)}: where the curve must pass`,
    () => 'P(\\mu) = a_3\\mu^3 + a_2\\mu^2 + a_1\\mu + a_0,\\quad P(0) = P_i,\\ P(1) = P_{i+1}',
  ),
  step(
    'gradients',
    ({ state }) =>
      state.mode === 'hand'
        ? `The gradients D0 … D${patchCount(state)}, set by hand (arrows drawn a third as long)`
        : `The gradients D0 … D${patchCount(state)} from the neighbours: Dₖ = (Pₖ₊₁ − Pₖ₋₁)/2, zero at both ends`,
    () => "P'(0) = D_i,\\qquad P'(1) = D_{i+1}",
  ),
  step(
    'pointWeights',
    'H0 and H1 weight the end points: H0 + H1 = 1',
    () => 'H_0 = 2\\mu^3 - 3\\mu^2 + 1,\\qquad H_1 = -2\\mu^3 + 3\\mu^2',
  ),
  step(
    'gradientWeights',
    'H2 and H3 weight the end gradients: H2 is never negative, H3 never positive',
    () => 'H_2 = \\mu^3 - 2\\mu^2 + \\mu,\\qquad H_3 = \\mu^3 - \\mu^2',
  ),
  // While the patches are built, the model's patch is the one this press solves.
  repeat(
    'patch',
    patchCount,
    ({ index, times }) =>
      `Patch ${index} of ${times}, from P${index - 1} to P${index}: the patch matrix turns its four conditions into a0 … a3`,
    ({ model: { patch } }) =>
      filled(patchMatrixLine([patch.p0, patch.p1, patch.d0, patch.d1], patch.coefficients)),
  ),
  step(
    'pointAtMu',
    ({ state }) => `P(μ) on patch ${state.patch + 1}: H0 P + H1 P + H2 D + H3 D`,
    ({ state, model: { patch } }) =>
      filled(basisOneLine(patch.index, state.mu, patch.weights, patch.point)),
  ),
  stepIf(
    'bezier',
    (state) => state.bezier,
    'The same patch as a Bézier curve: its inner control points are the arrow tips, P ± D/3',
    ({ model: { patch } }) => filled(bezierPoints(patch.bezier, true)),
  ),
);
