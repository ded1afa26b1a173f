import { sub, texNumber, texT } from '../../../kit/format';
import { repeat, script, step } from '../../../kit/script';
import { pointsCaption } from '../captions';
import type { ModelOf } from '../model';
import { MAX_COPIES, type PropertiesState } from '../state';

export type RepeatReveal = 'points' | 'curve' | 'copy';

/** The weight of P_r with its copies, beside its weight listed once. */
const weights = ({ model }: { model: ModelOf<'repeat'> }) => {
  const { repeated: r, t } = model.state;
  return `\\text{weight of } P_{${r}} \\text{ at } t = ${texT(t)}:\\ ${texNumber(model.weight, 4)}\\quad(\\text{once: } ${texNumber(model.weightOnce, 4)})`;
};

/** Property 4: a point listed again gets the sum of the weights, and pulls the curve. */
export const repeatScript = script<PropertiesState, ModelOf<'repeat'>, RepeatReveal>(
  step('points', ({ state }) => pointsCaption(state.points)),
  step(
    'curve',
    ({ state }) =>
      `The curve with every control point once; P${sub(state.repeated)} will be repeated`,
    weights,
  ),
  repeat(
    'copy',
    () => MAX_COPIES,
    ({ state, index }) =>
      `P${sub(state.repeated)} listed ${index + 1} times: its weights add up and pull the curve towards it`,
    weights,
  ),
);
