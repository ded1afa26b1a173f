import { sub, texNumber } from '../../../kit/format';
import { type StepAt, script, step } from '../../../kit/script';
import { distance } from '../../../math';
import { pointsCaption } from '../captions';
import type { ModelOf } from '../model';
import type { PropertiesState } from '../state';

export type LocalReveal = 'points' | 'before' | 'moved' | 'curve' | 'largest';

type At = StepAt<PropertiesState, ModelOf<'local'>>;

/** Indices of the points the user moved from the "before" curve. */
const movedPoints = (state: PropertiesState) =>
  state.points.flatMap((q, i) => (state.before[i] && distance(q, state.before[i]) > 0 ? [i] : []));

/** A step's formula when exactly one point moved (of Pi, by its shift); none otherwise. */
const ofOnePoint =
  (tex: (i: number, shift: string, m: ModelOf<'local'>) => string) =>
  ({ model }: At) =>
    model.single ? tex(model.single.index, texNumber(model.single.shift, 3), model) : null;

/** Property 3: moving one control point moves the whole curve, an inner one barely. */
export const localScript = script<PropertiesState, ModelOf<'local'>, LocalReveal>(
  step('points', ({ state }) => `${pointsCaption(state.points)}, as they are now`),
  step('before', 'Before: the curve of the points as they were, dashed'),
  step(
    'moved',
    ({ state }) => {
      const moved = movedPoints(state);
      const which = moved.length ? moved.map((i) => `P${sub(i)}`).join(', ') : 'no point';
      return `${which} moved; every other control point stayed`;
    },
    ofOnePoint((i, shift) => `|\\Delta P_{${i}}| = ${shift}`),
  ),
  step(
    'curve',
    'After: the new curve. All of it moved, not just the part near the moved point',
    ofOnePoint(
      (i, _shift, m) =>
        `P_{\\text{after}}(t) - P_{\\text{before}}(t) = W(${m.n},${i},t)\\,\\Delta P_{${i}}`,
    ),
  ),
  step(
    'largest',
    'The largest move of the curve, marked',
    ofOnePoint(
      (i, shift, m) =>
        `\\max_t |\\Delta P(t)| = W(${m.n},${i},\\tfrac{${i}}{${m.n}})\\cdot ${shift} = ${texNumber(m.single!.peak * m.single!.shift, 3)}`,
    ),
  ),
);
