import { bernstein } from '../../math';
import { filled } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import type { BlendingModel } from './model';
import { type BlendingState, type Comparison, degree } from './state';
import { expansionTex, pointFormula, weightFormula } from './tex';

/** What the steps reveal, by name: the figures and the panel ask for these. */
export type Reveal = 'points' | 'weight' | 'point' | 'curve' | 'comparison';

type Compared = Exclude<Comparison, 'none'>;

const COMPARED: Record<Compared, string> = {
  hermite:
    'Compared, dashed: the Hermite functions H0 … H3; only H3 goes below zero, and they weight tangents too',
  bspline:
    'Compared, dashed: the uniform cubic B-spline functions; never negative, but none reaches 1',
  lagrange:
    'Compared, dashed: Lagrange functions on equally spaced nodes; some go negative, and the curve leaves the hull',
};

const COMPARED_TEX: Record<Compared, string> = {
  hermite: "x(\\mu) = H_0\\,x_0 + H_1\\,x_1 + H_2\\,x_0' + H_3\\,x_1'",
  bspline: 'B(\\mu) = B_0 P_i + B_1 P_{i+1} + B_2 P_{i+2} + B_3 P_{i+3}',
  lagrange: 'L(\\mu) = \\sum_i L_i(\\mu)\\,P_i,\\qquad L_i(\\tfrac{j}{N}) = [\\,i = j\\,]',
};

/** Where W(N, i, μ) is largest: μ = i/N, written as the lecture writes it. */
const peakOf = (i: number, n: number) => (i === 0 ? '0' : i === n ? '1' : `${i}/${n}`);

/**
 * The clicker's script: the points, each weight W(N, 0, μ) … W(N, N, μ) in
 * turn, their weighted sum P(μ), the curve it traces, and (when one is
 * chosen) the basis compared with.
 */
export const blendingScript = script<BlendingState, BlendingModel, Reveal>(
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
  // A step only when a basis is chosen to compare with.
  repeat(
    'comparison',
    (state) => (state.comparison === 'none' ? 0 : 1),
    ({ state }) => COMPARED[state.comparison as Compared],
    ({ state }) => COMPARED_TEX[state.comparison as Compared],
  ),
);
