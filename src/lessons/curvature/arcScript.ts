import { script, step } from '../../kit/script';
import type { CurvatureModel } from './model';
import type { CurvatureState } from './state';
import { texNumber } from '../../kit/format';
import { parameter, value } from './tex';

/** What the steps of arc length against parameter reveal, by name. */
export type ArcReveal = 'curve' | 'ticks' | 'arcLength' | 'table' | 'equalLength' | 'both';

/** s_i = iL/n, and t read back from the table: the same at the step that shows both sets of ticks. */
const equalLength = ({ state, model }: { state: CurvatureState; model: CurvatureModel }) => {
  const arc = model.arc!;
  const n = state.equalSteps;
  return `s_i = \\frac{i L}{${n}} = i \\cdot ${value(arc.length / n)},\\quad t(s_1) = ${texNumber(arc.equal[1].t, 4)}`;
};

/**
 * Arc length against parameter: equal steps of t, the arc length s(t), its
 * table, and equal steps of length read back from it.
 */
export const arcScript = script<CurvatureState, CurvatureModel, ArcReveal>(
  step('curve', 'The curve and its parameter t', () => `P(t),\\quad t \\in [0, 1]`),
  step(
    'ticks',
    'Ticks at equal steps of t: they bunch where the curve is slow',
    ({ state: { equalSteps: n } }) => `t_i = \\frac{i}{${n}},\\quad i = 0, \\dots, ${n}`,
  ),
  step(
    'arcLength',
    'The arc length s(t) = ∫ |P′(ξ)| dξ from 0 to t, against t',
    ({ state, model }) =>
      `s(${parameter(state.t)}) = \\int_0^{${parameter(state.t)}} |P'(\\xi)|\\,d\\xi = ${value(model.arc!.sAtT)}`,
  ),
  step(
    'table',
    'The arc length table: s at equal steps of t',
    ({ model: { arc } }) =>
      `L = s(1) = ${value(arc!.length)},\\quad s(t_1) = ${value(arc!.table[1].s)}`,
  ),
  step('equalLength', 'Equal steps of arc length: t read back from the table', equalLength),
  step('both', 'Both sets of ticks: equal t against equal s', equalLength),
);
