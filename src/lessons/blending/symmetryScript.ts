import { bernstein, binomial } from '../../math';
import { texT, words } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import { texPoint } from '../../render/formula';
import type { BlendingModel } from './model';
import type { BlendingScript, Reveal } from './reveals';
import { type BlendingState, degree } from './state';

// The symmetry of the Bernstein functions under μ → 1 − μ, walked when the
// mirror is chosen: the pairs of weights it swaps, and the curve reversed.

/** W(N, i, μ) = C(N, i) μⁱ (1 − μ)ᴺ⁻ⁱ at these numbers, and the same with μ and 1 − μ swapped. */
function pairFormula(n: number, i: number, mu: number): string {
  const a = texT(mu);
  const b = texT(1 - mu);
  const j = n - i;
  const value = bernstein(n, i, mu).toFixed(4);
  return `W(${n},${i},${a}) = ${binomial(n, i)}\\cdot ${a}^{${i}}\\,${b}^{${j}} = ${binomial(n, j)}\\cdot ${b}^{${j}}\\,${a}^{${i}} = W(${n},${j},${b}) = ${value}`;
}

/** The pairs (i, N − i) with i ≤ N − i: one press each. */
export const pairCount = (state: BlendingState) => Math.floor(degree(state) / 2) + 1;

/**
 * The symmetry of the blending functions under μ → 1 − μ (the lecture
 * slides: "symmetric under u → (1 − u)"): the functions, the mirrored
 * cursor, each pair W(N, i, μ) = W(N, N − i, 1 − μ) with the numbers of μ,
 * and what it means for the curve: reversed points, the same curve backwards.
 */
export const symmetryScript: BlendingScript = script<BlendingState, BlendingModel, Reveal>(
  step(
    'functions',
    ({ state }) =>
      `The ${degree(state) + 1} blending functions of degree ${degree(state)}, with the cursor at μ = ${texT(state.mu)}`,
    ({ state }) =>
      `W(${degree(state)},i,\\mu) = \\binom{${degree(state)}}{i}\\mu^{i}(1-\\mu)^{${degree(state)}-i}`,
  ),
  step(
    'mirror',
    ({ state }) => `Mirror μ in ½: a second cursor at 1 − μ = ${texT(1 - state.mu)}`,
    ({ state }) => `1 - \\mu = 1 - ${texT(state.mu)} = ${texT(1 - state.mu)}`,
  ),
  repeat(
    'pair',
    pairCount,
    ({ state, index }) => {
      const n = degree(state);
      const i = index - 1;
      const value = words(bernstein(n, i, state.mu));
      return i === n - i
        ? `W(${n}, ${i}, μ) = W(${n}, ${i}, 1 − μ) = ${value}: the middle function is its own mirror image`
        : `W(${n}, ${i}, μ) = W(${n}, ${n - i}, 1 − μ) = ${value}: swapping μ and 1 − μ swaps P${i}'s weight and P${n - i}'s`;
    },
    ({ state, index }) => pairFormula(degree(state), index - 1, state.mu),
  ),
  step(
    'reversed',
    'So P(1 − μ) weights the points in reverse order: reversed control points trace the same curve backwards',
    ({ state, model }) => {
      const n = degree(state);
      return `P(${texT(1 - state.mu)}) = \\sum_{i=0}^{${n}} W(${n},i,${texT(state.mu)})\\,P_{${n}-i} = ${texPoint(model.mirrored, 3)}`;
    },
  ),
);
