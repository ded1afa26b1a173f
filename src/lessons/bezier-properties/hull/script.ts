import { words } from '../../../kit/format';
import { script, step } from '../../../kit/script';
import { pointsCaption } from '../captions';
import type { ModelOf } from '../model';
import type { PropertiesState } from '../state';

export type HullReveal = 'points' | 'polygon' | 'hull' | 'curve' | 'point';

/** Property 2: the curve never leaves the convex hull of its control points. */
export const hullScript = script<PropertiesState, ModelOf<'hull'>, HullReveal>(
  step('points', ({ state }) => pointsCaption(state.points)),
  step('polygon', 'Join them: the control polygon'),
  step('hull', 'Their convex hull: the smallest convex region that holds them all'),
  step(
    'curve',
    'The curve never leaves the hull',
    ({ model: { inside, total } }) => `\\text{${inside} of ${total} curve samples in the hull}`,
  ),
  step(
    'point',
    ({ state }) =>
      `Each P(t) is an average of the control points with weights ≥ 0; here t = ${words(state.t)}`,
    ({ model: { controls } }) => {
      const n = controls.length - 1;
      return `P(t) = \\sum_{i=0}^{${n}} W(${n},i,t)\\,P_i,\\quad W \\ge 0,\\quad \\sum_i W(${n},i,t) = 1`;
    },
  ),
);
