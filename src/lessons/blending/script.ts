import { bernstein } from '../../math';
import type { BlendingModel } from './model';
import { filled } from '../../kit/format';
import { type BlendingState, type Comparison, degree, revealed } from './state';
import { expansionTex, pointFormula, weightFormula } from './tex';

// The clicker's script: the points, each weight in turn, their weighted sum
// P(μ), the curve it traces, and the basis compared with.

const COMPARED: Record<Exclude<Comparison, 'none'>, string> = {
  hermite:
    'Compared, dashed: the Hermite functions H0 … H3; only H3 goes below zero, and they weight tangents too',
  bspline:
    'Compared, dashed: the uniform cubic B-spline functions; never negative, but none reaches 1',
  lagrange:
    'Compared, dashed: Lagrange functions on equally spaced nodes; some go negative, and the curve leaves the hull',
};

const COMPARED_TEX: Record<Exclude<Comparison, 'none'>, string> = {
  hermite: "x(\\mu) = H_0\\,x_0 + H_1\\,x_1 + H_2\\,x_0' + H_3\\,x_1'",
  bspline: 'B(\\mu) = B_0 P_i + B_1 P_{i+1} + B_2 P_{i+2} + B_3 P_{i+3}',
  lagrange: 'L(\\mu) = \\sum_i L_i(\\mu)\\,P_i,\\qquad L_i(\\tfrac{j}{N}) = [\\,i = j\\,]',
};

export function describeStep(state: BlendingState, k: number): string {
  const n = degree(state);
  const shown = revealed({ ...state, step: k });
  if (k === 0) return `The control points P0 … P${n} and their polygon`;
  if (!shown.point) {
    const i = k - 1;
    const peak = i === 0 ? '0' : i === n ? '1' : `${i}/${n}`;
    return `The weight of P${i}: W(${n}, ${i}, μ), largest at μ = ${peak}`;
  }
  if (!shown.curve) return 'P(μ): the control points averaged with these weights';
  if (!shown.compared) return 'As μ runs from 0 to 1, P(μ) traces the Bézier curve';
  return COMPARED[state.b as Exclude<Comparison, 'none'>];
}

export function stepFormula(m: BlendingModel, state: BlendingState): string | null {
  const { n, shown } = m;
  const mu = state.mu;
  if (state.step === 0) return `P(\\mu) = \\sum_{i=0}^{${n}} W(${n},i,\\mu)\\,P_i`;
  if (!shown.point) {
    const i = state.step - 1;
    return `${filled(weightFormula(n, i, mu))} = ${bernstein(n, i, mu).toFixed(4)}`;
  }
  if (!shown.curve) return filled(pointFormula(mu, m.weights, state.p, m.point));
  if (!shown.compared) return expansionTex(n, 4);
  return COMPARED_TEX[state.b as Exclude<Comparison, 'none'>];
}
