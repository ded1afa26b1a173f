import { texNumber } from '../../../kit/format';
import { repeat, script, step } from '../../../kit/script';
import { plural, pointsCaption } from '../captions';
import type { ModelOf } from '../model';
import { MAX_ELEVATIONS, type PropertiesState } from '../state';

export type ElevateReveal = 'points' | 'curve' | 'elevation';

/** Property 5: raising the degree keeps the curve, and the polygon closes in on it. */
export const elevateScript = script<PropertiesState, ModelOf<'elevate'>, ElevateReveal>(
  step('points', ({ state }) => pointsCaption(state.points)),
  step('curve', ({ state }) => `The curve of degree ${state.points.length - 1} and its polygon`),
  repeat(
    'elevation',
    () => MAX_ELEVATIONS,
    ({ state, index: j }) =>
      `Degree raised ${plural(j, 'time')}, to ${state.points.length - 1 + j}: the same curve, a polygon closer to it`,
    ({ model: { gaps, n } }) =>
      `Q_i = \\tfrac{i}{N+1}P_{i-1} + \\bigl(1 - \\tfrac{i}{N+1}\\bigr)P_i,\\quad \\max_i |Q_i - P(\\tfrac{i}{${n}})| = ${texNumber(gaps[gaps.length - 1], 4)}`,
  ),
);
