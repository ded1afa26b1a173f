import type { Point } from '../../math';
import { memoOn } from '../../kit/memoOn';
import type { Revealed } from '../../kit/script';
import { type Bounds, boundsOf, unionBounds } from '../../render/projection';
import { type Explicit, deriveExplicit } from './explicit';
import {
  type Parametric,
  type ParametricCurves,
  parametricCurves,
  shownCurves,
} from './parametric';
import type { Reveal } from './script';
import type { QuadraticState } from './state';

export type { Parabola } from './explicit';
export type { Member, MuRule } from './parametric';

/** Everything the figure and the panel show, computed once per state. */
export interface QuadraticModel {
  state: QuadraticState;
  /** What the steps so far reveal: the parabola, the parametric curve, its dots, the family, the rules. */
  shown: Revealed<Reveal>;
  /** The parabola y(x). */
  explicit: Explicit;
  /** The parametric quadratic, its coefficients and the curves of the step. */
  parametric: Parametric;
  /** What "fit view" shows: the points and every step's curves, apex included. */
  bounds: Bounds;
}

/** y(x) reads only the points: moving the μ1 slider does not solve it again. */
const explicitOf = memoOn<Pick<QuadraticState, 'points'>, 'points', Explicit>(
  ['points'],
  ({ points }) => deriveExplicit(points),
);

/** Every curve of the construction reads only the points and μ1, so a step costs no new work. */
const curvesOf = memoOn<
  QuadraticState,
  'points' | 'mu',
  { curves: ParametricCurves; bounds: Bounds }
>(['points', 'mu'], ({ points, mu }) => {
  const curves = parametricCurves(points, mu);
  return { curves, bounds: fitBounds(points, explicitOf({ points }), curves) };
});

export function derive(state: QuadraticState, shown: Revealed<Reveal>): QuadraticModel {
  const explicit = explicitOf(state);
  const { curves, bounds } = curvesOf(state);
  return { state, shown, explicit, parametric: shownCurves(curves, shown), bounds };
}

/**
 * What "fit view" shows: the points and every curve of every step (apex
 * included), so that stepping through the construction never needs a new view.
 */
function fitBounds(points: readonly Point[], explicit: Explicit, curves: ParametricCurves): Bounds {
  // Box by box: the curves' thousand points are not copied into one list on every drag frame.
  return [...curves.all, ...(explicit.apex ? [[explicit.apex]] : [])]
    .map(boundsOf)
    .reduce(unionBounds, boundsOf(points));
}
