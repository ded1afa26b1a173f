import { words } from '../../../kit/format';
import { script, step } from '../../../kit/script';
import { pointsCaption } from '../captions';
import type { ModelOf } from '../model';
import type { PropertiesState } from '../state';

export type CubicReveal = 'points' | 'polygon' | 'curve' | 'turning' | 'marks' | 'point';

/** Property 8: a cubic turns both ways (an inflection) or crosses itself (a loop). */
export const cubicScript = script<PropertiesState, ModelOf<'cubic'>, CubicReveal>(
  step('points', ({ state }) => pointsCaption(state.points)),
  step('polygon', 'Join them: the control polygon'),
  step('curve', 'The cubic Bézier curve'),
  step(
    'turning',
    'Coloured by the way it turns: to the left in one colour, to the right in another',
  ),
  step(
    'marks',
    'Where it changes its turning (inflections) or crosses itself (a loop), with their t',
    ({ model: { inflections, loop } }) => {
      const parts = inflections.map(({ t }) => `t = ${t.toFixed(3)}`);
      if (loop)
        parts.push(
          `\\text{crossing at } t = ${loop.t[0].toFixed(3)} \\text{ and } ${loop.t[1].toFixed(3)}`,
        );
      return parts.length ? parts.join(',\\quad ') : '\\text{no inflection, no loop}';
    },
  ),
  step('point', ({ state }) => `P(t) at t = ${words(state.t)}`),
);
