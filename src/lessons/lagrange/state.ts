import { bool, choice, stepField, linkKey, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

export type Spacing = 'uniform' | 'chord';

/** Everything the Lagrange lesson shows, and all of it goes in the link. */
export interface LagrangeState {
  /** The points P0 … Pn to interpolate (`p` in the link). */
  points: Point[];
  /** The parameter at which the polynomial is evaluated and the basis is read. */
  t: number;
  /** Parameter values t_k: equally spaced, or by chord length. */
  spacing: Spacing;
  /** Draw the natural cubic spline through the same points as well. */
  spline: boolean;
  /** Step of the script (see `interpolation` in script.ts for what each reveals). */
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

// The link's keys and their order are the ones links were made with: p, t, spacing, spline, step.
export const schema: Schema<LagrangeState> = {
  points: linkKey(points({ default: DEFAULT_POINTS, min: 2, max: MAX_POINTS }), 'p'),
  t: number({ default: 0.4, min: 0, max: 1 }),
  spacing: choice<Spacing>({ default: 'uniform', values: ['uniform', 'chord'] }),
  spline: bool({ default: false }),
  step: stepField(),
};

export const degree = (state: LagrangeState) => state.points.length - 1;
