import { bool, int, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

/** Everything the de Casteljau lesson shows, and all of it goes in the link. */
export interface DeCasteljauState {
  /** Control points P0 … Pn. */
  p: Point[];
  t: number;
  /** The step of the construction shown (see `construction` in script.ts for what each reveals). */
  step: number;
  /** Show the two control polygons that subdivision at t produces. */
  split: boolean;
}

export const MAX_POINTS = 16;

/** The lecture's cubic. */
export const LECTURE_CUBIC: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2],
  [4, 0],
];

export const schema: Schema<DeCasteljauState> = {
  p: points({ default: LECTURE_CUBIC, min: 2, max: MAX_POINTS }),
  t: number({ default: 0.4, min: 0, max: 1 }),
  // Every lesson opens at its first scene's step 0: the first clicker press is the first step.
  step: int({ default: 0, min: 0, max: MAX_POINTS + 1 }),
  split: bool({ default: false }),
};

/** Degree of the curve. */
export const degree = (state: DeCasteljauState) => state.p.length - 1;
