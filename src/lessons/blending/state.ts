import { choice, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

/** A basis drawn on the same axes as the Bernstein functions, for comparison. */
export type Comparison = 'none' | 'hermite' | 'bspline' | 'lagrange';

/** Everything the blending lesson shows, and all of it goes in the link. */
export interface BlendingState {
  /** Control points P0 … PN. */
  p: Point[];
  /** The parameter μ of the point P(μ) and of the plot's cursor. */
  mu: number;
  /** Another basis to compare with (`b=lagrange`). */
  b: Comparison;
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

export const schema: Schema<BlendingState> = {
  p: points({ default: LECTURE_CUBIC, min: 2, max: MAX_POINTS }),
  mu: number({ default: 0.5, min: 0, max: 1 }),
  b: choice<Comparison>({ default: 'none', values: ['none', 'hermite', 'bspline', 'lagrange'] }),
};

/** The degree N of the curve. */
export const degree = (state: BlendingState) => state.p.length - 1;

/** μ as typed: up to four decimals, trailing zeros dropped. */
export const texMu = (mu: number) => String(Number(mu.toFixed(4)));
