import { texResidue, texPoint, texT, words } from '../../../kit/format';
import { script, step } from '../../../kit/script';
import { pointsCaption } from '../captions';
import type { ModelOf } from '../model';
import type { PropertiesState } from '../state';

export type HermiteReveal = 'points' | 'curve' | 'tangents' | 'hermite' | 'point';

/** Property 9: a Bézier cubic is the Hermite patch of its end points and end tangents. */
export const hermiteScript = script<PropertiesState, ModelOf<'hermite'>, HermiteReveal>(
  step('points', ({ state }) => pointsCaption(state.points)),
  step('curve', 'The Bézier cubic and its polygon'),
  step(
    'tangents',
    'Its Hermite data: the end points and the end tangents x₀′ = 3(P₁ − P₀), x₁′ = 3(P₃ − P₂), drawn at half length',
    ({ model: { d0, d1 } }) =>
      `x_0' = 3(P_1 - P_0) = ${texPoint(d0, 3)},\\quad x_1' = 3(P_3 - P_2) = ${texPoint(d1, 3)}`,
  ),
  step(
    'hermite',
    'The Hermite curve of that data, dashed: the same curve',
    ({ model }) => `\\max_t |\\text{Bézier} - \\text{Hermite}| = ${texResidue(model.deviation)}`,
  ),
  step(
    'point',
    ({ state }) => `P(t) at t = ${words(state.t)}, the same from both forms`,
    ({ state, model }) => `P(${texT(state.t)}) = ${texPoint(model.point, 3)}`,
  ),
);
