import { texNumber, words } from '../../../kit/format';
import { repeat, script, step } from '../../../kit/script';
import { plural, pointsCaption } from '../captions';
import type { ModelOf } from '../model';
import { MAX_SPLITS, type PropertiesState } from '../state';

export type SplitReveal = 'points' | 'curve' | 'split';

/** Property 6: split every piece at t, again and again: the polygons close in, fast. */
export const splitScript = script<PropertiesState, ModelOf<'split'>, SplitReveal>(
  step('points', ({ state }) => pointsCaption(state.points)),
  step(
    'curve',
    ({ state }) => `The curve and its polygon; it will be split at t = ${words(state.t)}`,
  ),
  repeat(
    'split',
    () => MAX_SPLITS,
    ({ index: j }) =>
      `${plural(j, 'split')} at t: ${2 ** j} pieces, each with a polygon of its own`,
    ({ model: { gaps } }) =>
      `\\text{largest gap between a polygon and its piece: } ${texNumber(gaps[gaps.length - 1], 5)}`,
  ),
);
