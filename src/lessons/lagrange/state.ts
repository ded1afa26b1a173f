import { bool, choice, number, points } from '../../app/fields';
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
}

export const MAX_POINTS = 16;

export const DEFAULT_POINTS: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2.5],
  [4.5, 1],
  [6, 2],
];

/** Runge's phenomenon: twelve nearly collinear, unevenly spaced points. */
export const RUNGE_POINTS: Point[] = [
  [0, 0],
  [1, 0.2],
  [1.6, 0.1],
  [3, 0.3],
  [4.2, 0.2],
  [5, 0.4],
  [6.5, 0.3],
  [7, 0.5],
  [8.1, 0.4],
  [9.5, 0.6],
  [10, 0.5],
  [11, 0.7],
];

export const schema: Schema<LagrangeState> = {
  p: points({ default: DEFAULT_POINTS, min: 2, max: MAX_POINTS }),
  t: number({ default: 0.4, min: 0, max: 1 }),
  spacing: choice<Spacing>({ default: 'uniform', values: ['uniform', 'chord'] }),
  spline: bool({ default: false }),
};

export const degree = (state: LagrangeState) => state.p.length - 1;
