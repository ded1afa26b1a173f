import { bernstein } from '../../math';
import { filled } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import type { BlendingModel } from './model';
import type { BlendingScript, Reveal } from './reveals';
import { type BlendingState, degree } from './state';
import { expansionTex, pointFormula, weightFormula } from './tex';

// Bernstein's weights one by one, the script of the first five scenes (a
// cubic, N = 1, 2, 6 and 10): what the lesson is about before it compares.

/** Where W(N, i, μ) is largest: μ = i/N, written as the lecture writes it. */
export const peakOf = (i: number, n: number) => (i === 0 ? '0' : i === n ? '1' : `${i}/${n}`);

/**
 * The clicker's script: the points, each weight W(N, 0, μ) … W(N, N, μ) in
 * turn, their weighted sum P(μ), and the curve it traces.
 */
export const blendingScript: BlendingScript = script<BlendingState, BlendingModel, Reveal>(
  step(
    'points',
    ({ state }) => `The control points P0 … P${degree(state)} and their polygon`,
    ({ state }) => {
      const n = degree(state);
      return `P(\\mu) = \\sum_{i=0}^{${n}} W(${n},i,\\mu)\\,P_i`;
    },
  ),
  // Weight i is the (i + 1)-th repeat: P0's weight first.
  repeat(
    'weight',
    (state) => degree(state) + 1,
    ({ state, index }) => {
      const n = degree(state);
      const i = index - 1;
      return `The weight of P${i}: W(${n}, ${i}, μ), largest at μ = ${peakOf(i, n)}`;
    },
    ({ state: { mu }, model: { n }, index }) => {
      const i = index - 1;
      return `${filled(weightFormula(n, i, mu))} = ${bernstein(n, i, mu).toFixed(4)}`;
    },
  ),
  step('point', 'P(μ): the control points averaged with these weights', ({ state, model }) =>
    filled(pointFormula(state.mu, model.weights, state.p, model.point)),
  ),
  step('curve', 'As μ runs from 0 to 1, P(μ) traces the Bézier curve', ({ model: { n } }) =>
    expansionTex(n, 4),
  ),
);
