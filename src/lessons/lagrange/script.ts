import { texNumber } from '../../render/formula';
import type { LagrangeModel } from './model';
import { type LagrangeState, degree, revealed } from './state';

// The clicker's script: the points, each basis polynomial Lₖ in turn, the
// polynomial they blend, and the spline compared with.

export function describeStep(state: LagrangeState, k: number): string {
  const n = degree(state);
  const shown = revealed({ ...state, step: k });
  if (k === 0) return `The ${n + 1} points P0 … P${n} to pass through, in order`;
  if (!shown.curve) {
    const i = k - 1;
    return `L${i}(t): 1 at its own t${i}, 0 at every other tₖ`;
  }
  if (!shown.spline)
    return `The polynomial of degree ${n}: P(t) = Σ Lₖ(t) Pₖ passes through every point`;
  return 'Compared: the natural cubic spline through the same points, each piece listening only to its neighbours';
}

export function stepFormula(m: LagrangeModel, state: LagrangeState): string | null {
  const { n, ts, shown } = m;
  if (state.step === 0) {
    const values = ts.map((t) => texNumber(t, 3)).join(',\\ ');
    return ts.length <= 6
      ? `t_k = ${values}`
      : `t_k = ${texNumber(ts[0], 3)},\\ \\dots,\\ ${texNumber(ts[n], 3)}`;
  }
  if (!shown.curve) {
    const i = state.step - 1;
    const w = texNumber(m.weights[i], 4);
    return `L_{${i}}(t) = \\prod_{j \\ne ${i}} \\frac{t - t_j}{t_{${i}} - t_j},\\qquad L_{${i}}(${texNumber(state.t, 2)}) = ${w}`;
  }
  const point = `(${texNumber(m.at[0], 3)},\\ ${texNumber(m.at[1], 3)})`;
  if (!shown.spline)
    return `P(${texNumber(state.t, 2)}) = \\sum_{k=0}^{${n}} L_k(${texNumber(state.t, 2)})\\,P_k = ${point}`;
  return `\\text{largest } \\textstyle\\sum_k |L_k(t)| = ${texNumber(m.lebesgue.value, 1)}`;
}
