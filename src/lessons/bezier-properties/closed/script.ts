import { sub, words } from '../../../kit/format';
import { script, step } from '../../../kit/script';
import { pointsCaption } from '../captions';
import type { ModelOf } from '../model';
import type { PropertiesState } from '../state';

export type ClosedReveal = 'points' | 'polygon' | 'curve' | 'tangents' | 'point';

/** Property 4: P₀ repeated at the end closes the curve, smooth there only in line. */
export const closedScript = script<PropertiesState, ModelOf<'closed'>, ClosedReveal>(
  step('points', ({ state }) => `${pointsCaption(state.points)}; P₀ will be repeated at the end`),
  step('polygon', ({ state }) => {
    const n = state.points.length;
    return `The closed polygon P₀ … P${sub(n - 1)}, P${sub(n)} = P₀`;
  }),
  step('curve', 'The closed Bézier curve: it ends where it starts'),
  step(
    'tangents',
    ({ state }) =>
      `At P₀ it leaves along P₁ − P₀ and arrives along P₀ − P${sub(state.points.length - 1)}`,
    ({ model: { n, corner } }) => {
      const angle = corner === null ? '' : `,\\quad \\text{angle } ${corner.toFixed(1)}^\\circ`;
      return `P'(0) = ${n}(P_1 - P_0),\\quad P'(1) = ${n}(P_0 - P_{${n - 1}})${angle}`;
    },
  ),
  step('point', ({ state }) => `P(t) runs once round the closed curve; here t = ${words(state.t)}`),
);
