import { repeat, script, step } from '../../kit/script';
import { texNumber } from '../../render/formula';
import type { LagrangeModel } from './model';
import { type LagrangeState, degree } from './state';

/** What the steps reveal, by name: the figures and the panel ask for these. */
export type Reveal = 'points' | 'basis' | 'curve' | 'spline';

/**
 * The clicker's script: the points, each basis polynomial Lₖ in turn (one
 * press for each of L0 … Ln), the polynomial they blend, and the spline
 * compared with it (only when the spline is switched on).
 */
export const interpolation = script<LagrangeState, LagrangeModel, Reveal>(
  step(
    'points',
    ({ state }) =>
      `The ${degree(state) + 1} points P0 … P${degree(state)} to pass through, in order`,
    ({ model: { n, ts } }) => {
      const values = ts.map((t) => texNumber(t, 3)).join(',\\ ');
      return ts.length <= 6
        ? `t_k = ${values}`
        : `t_k = ${texNumber(ts[0], 3)},\\ \\dots,\\ ${texNumber(ts[n], 3)}`;
    },
  ),
  repeat(
    'basis',
    (state) => degree(state) + 1,
    ({ index }) => `L${index - 1}(t): 1 at its own t${index - 1}, 0 at every other tₖ`,
    ({ state, model, index }) => {
      const k = index - 1;
      const w = texNumber(model.weights[k], 4);
      return `L_{${k}}(t) = \\prod_{j \\ne ${k}} \\frac{t - t_j}{t_{${k}} - t_j},\\qquad L_{${k}}(${texNumber(state.t, 2)}) = ${w}`;
    },
  ),
  step(
    'curve',
    ({ state }) =>
      `The polynomial of degree ${degree(state)}: P(t) = Σ Lₖ(t) Pₖ passes through every point`,
    ({ state, model: { n, at } }) => {
      const t = texNumber(state.t, 2);
      const point = `(${texNumber(at[0], 3)},\\ ${texNumber(at[1], 3)})`;
      return `P(${t}) = \\sum_{k=0}^{${n}} L_k(${t})\\,P_k = ${point}`;
    },
  ),
  repeat(
    'spline',
    (state) => (state.spline ? 1 : 0),
    'Compared: the natural cubic spline through the same points, each piece listening only to its neighbours',
    ({ model }) =>
      `\\text{largest } \\textstyle\\sum_k |L_k(t)| = ${texNumber(model.lebesgue.value, 1)}`,
  ),
);

/**
 * The step after an edit that changes how many steps there are (a point
 * added or removed, the spline switched): shown to the end, it stays at the end.
 */
export const keepShownToEnd = (before: LagrangeState, after: LagrangeState): LagrangeState =>
  interpolation.keptAtEnd(before, after, 'step');
