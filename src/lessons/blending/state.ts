import { choice, stepField, linkKey, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

/**
 * A basis drawn on the same axes as the Bernstein functions, for comparison;
 * or the Bernstein functions' own mirror image under μ → 1 − μ; or the
 * Lagrange and the Bézier curve of the same points, each asked whether it
 * passes through them (interpolating or approximating).
 */
export type Comparison = 'none' | 'hermite' | 'bspline' | 'lagrange' | 'mirror' | 'interpolating';

/** Everything the blending lesson shows, and all of it goes in the link. */
export interface BlendingState {
  /** Control points P0 … PN (the lecture's P_i). */
  p: Point[];
  /** The parameter μ of the point P(μ) and of the plot's cursor. */
  mu: number;
  /** Another basis to compare with (in the link as `b=lagrange`). */
  comparison: Comparison;
  /** Step of the script (see `blendingScript` in script.ts for what each reveals). */
  step: number;
}

/** N runs from 1 to 12: thirteen colours are about as many as one can still tell apart. */
export const MAX_POINTS = 13;

/** The lecture's cubic. */
export const LECTURE_CUBIC: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2],
  [4, 0],
];

// The link's keys are written in this order: p, mu, b, step.
export const schema: Schema<BlendingState> = {
  p: points({ default: LECTURE_CUBIC, min: 2, max: MAX_POINTS }),
  mu: number({ default: 0.5, min: 0, max: 1 }),
  comparison: linkKey(
    choice<Comparison>({
      default: 'none',
      values: ['none', 'hermite', 'bspline', 'lagrange', 'mirror', 'interpolating'],
    }),
    'b',
  ),
  step: stepField(),
};

/** The degree N of the curve. */
export const degree = (state: BlendingState) => state.p.length - 1;
