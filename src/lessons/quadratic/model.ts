import type { Point } from '../../math';
import { type Bounds, boundsOf } from '../../render/projection';
import { type Explicit, deriveExplicit } from './explicit';
import { type Parametric, deriveParametric } from './parametric';
import type { QuadraticState } from './state';

export type { Parabola } from './explicit';
export type { Member, MuRule } from './parametric';

/** Everything the figure and the panel show, computed once per state. */
export interface QuadraticModel {
  state: QuadraticState;
  /** The parabola y(x) (step 0, and faintly under step 1). */
  explicit: Explicit;
  /** The parametric quadratic, its coefficients and the curves of the step. */
  parametric: Parametric;
  /** What "fit view" shows: the points and the step's main curves, apex included. */
  bounds: Bounds;
}

export function derive(state: QuadraticState): QuadraticModel {
  const explicit = deriveExplicit(state.p);
  const parametric = deriveParametric(state);
  return { state, explicit, parametric, bounds: fitBounds(state, explicit, parametric) };
}

/**
 * What "fit view" shows: the points and every curve of every step (apex
 * included), so that stepping through the construction never needs a new view.
 */
function fitBounds(state: QuadraticState, explicit: Explicit, parametric: Parametric): Bounds {
  const shown: Point[] = [...state.p, ...parametric.all];
  if (explicit.apex) shown.push(explicit.apex);
  const bounds = boundsOf(shown);
  if (explicit.parabola.kind === 'ok') return bounds;
  // Room above the points for the note that says why there is no parabola.
  const height = Math.max(bounds.maxY - bounds.minY, (bounds.maxX - bounds.minX) * 0.3, 1);
  return { ...bounds, maxY: bounds.maxY + 0.6 * height };
}
