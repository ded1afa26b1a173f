import { stepField, linkKey, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

/** Everything the quadratic lesson shows, and all of it goes in the link. */
export interface QuadraticState {
  /** The three points P0, P1, P2 (`p` in the link). */
  points: Point[];
  /** μ1, the parameter at which the parametric quadratic passes P1 (open interval). */
  mu: number;
  /** The step of the construction shown (see `construction` in script.ts for what each reveals). */
  step: number;
}

/** Both ends stay inside (0, 1): at μ1 = 0 or 1 the system of equation 2 is singular. */
export const MU_MIN = 0.01;
export const MU_MAX = 0.99;

/** The script's last step: its six steps, none repeated (script.test.ts checks it). */
export const LAST_STEP = 5;

/** Figure 1 of the lecture: the first scene. */
export const DEFAULT_POINTS: Point[] = [
  [0, 1],
  [2, 3],
  [4, 2],
];

export const schema: Schema<QuadraticState> = {
  points: linkKey(points({ default: DEFAULT_POINTS, min: 3, max: 3 }), 'p'),
  mu: number({ default: 0.5, min: MU_MIN, max: MU_MAX }),
  // Every lesson opens at its first scene's step 0: the first clicker press is the first step.
  step: stepField(),
};

/** μ1 kept inside the slider's range (the curve is undefined at 0 and 1). */
export const clampMu = (mu: number) => Math.min(MU_MAX, Math.max(MU_MIN, mu));
