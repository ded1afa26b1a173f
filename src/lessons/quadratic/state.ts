import { int, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

/** Everything the quadratic lesson shows, and all of it goes in the link. */
export interface QuadraticState {
  /** The three points P0, P1, P2. */
  p: Point[];
  /** μ1, the parameter at which the parametric quadratic passes P1 (open interval). */
  mu: number;
  /** What the figure shows: 0 the parabola y(x), 1 one parametric quadratic, 2 the family, 3 the rules for μ1. */
  step: number;
}

/** Both ends stay inside (0, 1): at μ1 = 0 or 1 the system of equation 2 is singular. */
export const MU_MIN = 0.01;
export const MU_MAX = 0.99;

export const STEP_TITLES = [
  'The parabola y(x) through three points',
  'A parametric quadratic P(μ)',
  'One set of points, many curves',
  'Choosing μ1 from the points',
] as const;

/** The members of the family drawn in Figure 2 of the notes. */
export const FAMILY = [0.2, 0.35, 0.5, 0.65, 0.8] as const;

export const DEFAULT_POINTS: Point[] = [
  [0, 0],
  [1, 2],
  [4, 1],
];

export const schema: Schema<QuadraticState> = {
  p: points({ default: DEFAULT_POINTS, min: 3, max: 3 }),
  mu: number({ default: 0.5, min: MU_MIN, max: MU_MAX }),
  step: int({ default: 0, min: 0, max: STEP_TITLES.length - 1 }),
};

/** μ1 kept inside the slider's range (the curve is undefined at 0 and 1). */
export const clampMu = (mu: number) => Math.min(MU_MAX, Math.max(MU_MIN, mu));
