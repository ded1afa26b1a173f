import { repeat, script, step } from '../../kit/script';
import { sub, words } from '../../kit/format';
import { texNumber, texPoint } from '../../render/formula';
import type { LagrangeModel } from './model';
import { type LagrangeState, degree } from './state';

/** What the steps reveal, by name: the figures and the panel ask for these. */
export type Reveal = 'points' | 'basis' | 'curve' | 'gradients' | 'piece' | 'coupled';

/** Step 0 of both scripts: the points alone, with their tₖ. */
const points = step<LagrangeState, LagrangeModel, Reveal>(
  'points',
  ({ state }) => `The ${degree(state) + 1} points P0 … P${degree(state)} to pass through, in order`,
  ({ model: { n, ts } }) => {
    const values = ts.map((t) => texNumber(t, 3)).join(',\\ ');
    return ts.length <= 6
      ? `t_k = ${values}`
      : `t_k = ${texNumber(ts[0], 3)},\\ \\dots,\\ ${texNumber(ts[n], 3)}`;
  },
);

/**
 * The clicker's script: the points, each basis polynomial Lₖ in turn (one
 * press for each of L0 … Ln), and the polynomial they blend.
 */
export const interpolation = script<LagrangeState, LagrangeModel, Reveal>(
  points,
  repeat(
    'basis',
    (state) => degree(state) + 1,
    ({ index }) => `L${index - 1}(t): 1 at its own t${sub(index - 1)}, 0 at every other tₖ`,
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
);

/**
 * The script when the spline is compared (the Runge-versus-spline scene): it
 * starts where its own idea starts. The polynomial comes at once (its basis
 * is the other scenes' subject); then the natural spline: its gradients from
 * one system, its pieces one by one with how far the polynomial strays on
 * each, and what one moved point does to every gradient.
 */
export const comparison = script<LagrangeState, LagrangeModel, Reveal>(
  points,
  step(
    'curve',
    ({ state }) => `The polynomial of degree ${degree(state)} through them, all at once`,
    ({ model }) =>
      `\\text{largest } \\textstyle\\sum_k |L_k(t)| = ${texNumber(model.lebesgue.value, 1)}`,
  ),
  step(
    'gradients',
    ({ state }) =>
      `The natural cubic spline's gradients D0 … D${degree(state)}, solved together from one system`,
    ({ model: { n } }) =>
      n === 1
        ? `2D_0 + D_1 = 3(P_1 - P_0),\\quad D_0 + 2D_1 = 3(P_1 - P_0)`
        : `\\begin{aligned}2D_0 + D_1 &= 3(P_1 - P_0)\\\\ D_{k-1} + 4D_k + D_{k+1} &= 3(P_{k+1} - P_{k-1}),\\ 0 < k < ${n}\\\\ D_{${n - 1}} + 2D_{${n}} &= 3(P_{${n}} - P_{${n - 1}})\\end{aligned}`,
  ),
  repeat(
    'piece',
    degree,
    ({ model, index: k }) =>
      `Spline piece ${k}, P${k - 1} to P${k}: the polynomial strays up to ${words(model.comparison!.gaps[k - 1])} from it here`,
    ({ model, index: k }) => {
      const d = model.comparison!.gradients;
      return `D_{${k - 1}} = ${texPoint(d[k - 1], 3)},\\qquad D_{${k}} = ${texPoint(d[k], 3)}`;
    },
  ),
  step(
    'coupled',
    ({ model }) => {
      const c = model.comparison!;
      const all = c.changed === c.gradients.length;
      const count = all ? `all ${c.gradients.length}` : `${c.changed} of the ${c.gradients.length}`;
      return `Move P${c.moved} up by ${words(c.nudge)} (dashed): ${count} gradients change, so the pieces are coupled`;
    },
    ({ model }) => {
      const c = model.comparison!;
      const smallest = Math.min(...c.gradientChange);
      const far = c.gradientChange.length - 1;
      return `P_{${c.moved}} + (0,\\ ${texNumber(c.nudge, 2)}):\\quad |\\Delta D_0| = ${texNumber(c.gradientChange[0], 4)},\\ \\dots,\\ |\\Delta D_{${far}}| = ${texNumber(c.gradientChange[far], 4)},\\quad \\min_k |\\Delta D_k| = ${texNumber(smallest, 4)}`;
    },
  ),
);

/** The script a state walks: the comparison when the spline is switched on. */
export const scriptOf = (state: LagrangeState) => (state.spline ? comparison : interpolation);

/**
 * The step after an edit that changes how many steps there are (a point
 * added or removed, the spline switched, so the other script): shown to the
 * end, it stays at the end; otherwise it stays where it was.
 */
export function keepShownToEnd(before: LagrangeState, after: LagrangeState): LagrangeState {
  const lastBefore = scriptOf(before).lastStep(before);
  const lastAfter = scriptOf(after).lastStep(after);
  const step = before.step >= lastBefore ? lastAfter : Math.min(before.step, lastAfter);
  return { ...after, step };
}
