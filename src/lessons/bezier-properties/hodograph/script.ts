import { pointWords, sub, texPoint, texT, words } from '../../../kit/format';
import { script, step } from '../../../kit/script';
import type { Point } from '../../../math';
import { pointsCaption } from '../captions';
import type { ModelOf } from '../model';
import type { PropertiesState } from '../state';

export type HodographReveal =
  'points' | 'curve' | 'differences' | 'times' | 'hodograph' | 'derivative' | 'tangent';

type Model = ModelOf<'hodograph'>;

const degree = (state: PropertiesState) => state.points.length - 1;
const point = (p: readonly number[]) => texPoint(p, 3);

/** "P_1 - P_0 = (1, 2),\ …" for every leg, or the first two and the last around \dots. */
function legsTex(vectors: readonly Point[], factor: string): string {
  const difference = (i: number) => `P_{${i + 1}} - P_{${i}}`;
  const leg = (i: number) =>
    `${factor ? `${factor}(${difference(i)})` : difference(i)} = ${point(vectors[i])}`;
  const last = vectors.length - 1;
  const shown = last > 3 ? [leg(0), leg(1), '\\dots', leg(last)] : vectors.map((_, i) => leg(i));
  return shown.join(',\\ ');
}

/** P′(t) from the derivative's control points, with the weights W(n − 1, i, t). */
function derivativeTex({ state, weights, hodograph, derivative }: Model): string {
  const terms = weights.map((w, i) => `${texT(w)}\\cdot${point(hodograph[i])}`);
  const shown = terms.length > 4 ? [terms[0], terms[1], '\\dots', terms[terms.length - 1]] : terms;
  return `P'(${texT(state.t)}) = ${shown.join(' + ')} = ${point(derivative)}`;
}

/**
 * The derivative of a Bézier curve is a Bézier curve of degree n − 1 with
 * control points n(P_{i+1} − P_i) (the hodograph): the legs, times n, the
 * curve they make drawn from a point O, its value at t, and that vector
 * moved to P(t), along the construction's last edge.
 */
export const hodographScript = script<PropertiesState, Model, HodographReveal>(
  step('points', ({ state }) => pointsCaption(state.points)),
  step('curve', 'The curve and its control polygon'),
  step(
    'differences',
    ({ state }) =>
      `The legs as vectors, P₁ − P₀ … P${sub(degree(state))} − P${sub(degree(state) - 1)}, drawn again from a point O`,
    ({ model }) => legsTex(model.differences, ''),
  ),
  step(
    'times',
    ({ state }) =>
      `Times n = ${degree(state)}: the control points of the derivative, ${degree(state)}(Pᵢ₊₁ − Pᵢ)`,
    ({ model }) => legsTex(model.hodograph, String(model.n)),
  ),
  step(
    'hodograph',
    ({ state }) =>
      `They make a Bézier curve of degree ${degree(state) - 1}, drawn from O: the derivative P′(t)`,
    ({ model: { n } }) => `P'(t) = \\sum_{i=0}^{${n - 1}} W(${n - 1},i,t)\\,${n}(P_{i+1} - P_i)`,
  ),
  step(
    'derivative',
    ({ state, model }) =>
      `At t = ${words(state.t)} the derivative curve gives P′(t) = ${pointWords(model.derivative)}`,
    ({ model }) => derivativeTex(model),
  ),
  step(
    'tangent',
    'Moved to P(t), the same vector lies along the tangent there, the last edge of the construction',
    ({ state, model: { n, edge, fromEdge } }) =>
      `${n}(P_{${n - 1},1} - P_{${n - 1},0}) = ${n}(${point(edge[1])} - ${point(edge[0])}) = ${point(fromEdge)} = P'(${texT(state.t)})`,
  ),
);
