import { bool, choice, int, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

export type Spacing = 'uniform' | 'chord';

/** Everything the Lagrange lesson shows, and all of it goes in the link. */
export interface LagrangeState {
  /** The points P0 … Pn to interpolate. */
  p: Point[];
  /** The parameter at which the polynomial is evaluated and the basis is read. */
  t: number;
  /** Parameter values t_k: equally spaced, or by chord length. */
  spacing: Spacing;
  /** Draw the natural cubic spline through the same points as well. */
  spline: boolean;
  /** Step of the script: the points, each Lₖ in turn, the polynomial, the spline. */
  step: number;
}

export const MAX_POINTS = 16;

export const DEFAULT_POINTS: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2.5],
  [4.5, 1],
  [6, 2],
];

/**
 * Runge's phenomenon, the classic way: eleven points on the bump
 * y = 4 / (1 + x²), equally spaced in x from −5 to 5 (and so in t). The
 * polynomial through them wiggles ever wider towards the ends.
 */
export const RUNGE_POINTS: Point[] = Array.from({ length: 11 }, (_, k) => {
  const x = k - 5;
  return [x, Number((4 / (1 + x * x)).toFixed(4))];
});

export const schema: Schema<LagrangeState> = {
  p: points({ default: DEFAULT_POINTS, min: 2, max: MAX_POINTS }),
  t: number({ default: 0.4, min: 0, max: 1 }),
  spacing: choice<Spacing>({ default: 'uniform', values: ['uniform', 'chord'] }),
  spline: bool({ default: false }),
  step: int({ default: 0, min: 0, max: MAX_POINTS + 3 }),
};

export const degree = (state: LagrangeState) => state.p.length - 1;

/**
 * Steps of the script: 0 the points; 1 … n + 1 the basis polynomials L0 … Ln
 * one by one; then the polynomial Σ Lₖ(t) Pₖ and P(t); then the spline, when
 * it is compared.
 */
export const stepCount = (state: LagrangeState) => degree(state) + 2 + (state.spline ? 1 : 0);

/** What step `step` shows. */
export interface Revealed {
  /** L0 … L(basis − 1) are shown. */
  basis: number;
  curve: boolean;
  spline: boolean;
}

export function revealed(state: LagrangeState): Revealed {
  const n = degree(state);
  return {
    basis: Math.min(state.step, n + 1),
    curve: state.step >= n + 2,
    spline: state.spline && state.step >= n + 3,
  };
}
