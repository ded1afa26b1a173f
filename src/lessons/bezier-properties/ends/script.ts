import { sub, texPoint, texT, words } from '../../../kit/format';
import { script, step } from '../../../kit/script';
import type { ModelOf } from '../model';
import { pointsCaption } from '../captions';
import type { PropertiesState } from '../state';

export type EndsReveal = 'points' | 'polygon' | 'curve' | 'ends' | 'tangents' | 'point';

const degree = (state: PropertiesState) => state.points.length - 1;

/** Property 1: the curve starts at P₀, ends at Pₙ, and leaves and arrives along the end legs. */
export const endsScript = script<PropertiesState, ModelOf<'ends'>, EndsReveal>(
  step('points', ({ state }) => pointsCaption(state.points)),
  step('polygon', 'Join them: the control polygon'),
  step('curve', 'The Bézier curve of these points'),
  step(
    'ends',
    ({ state }) =>
      `It starts at P₀ and ends at P${sub(degree(state))}: P(0) = P₀, P(1) = P${sub(degree(state))}`,
    ({ model: { n, controls } }) =>
      `P(0) = P_0 = ${texPoint(controls[0], 3)},\\quad P(1) = P_{${n}} = ${texPoint(controls[n], 3)}`,
  ),
  step(
    'tangents',
    ({ state }) =>
      `It leaves along the first leg and arrives along the last, at ${degree(state)} times their length`,
    ({ model: { n, tangents } }) =>
      `P'(0) = ${n}(P_1 - P_0) = ${texPoint(tangents[0].vector, 3)},\\quad P'(1) = ${n}(P_{${n}} - P_{${n - 1}}) = ${texPoint(tangents[1].vector, 3)}`,
  ),
  step(
    'point',
    ({ state }) => `At t = ${words(state.t)}: the point P(t) and its tangent P′(t)`,
    ({ state, model }) =>
      `P(${texT(state.t)}) = ${texPoint(model.point, 3)},\\quad P'(${texT(state.t)}) = ${texPoint(model.tangents[2].vector, 3)}`,
  ),
);
