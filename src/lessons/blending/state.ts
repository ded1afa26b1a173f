import { choice, int, number, points } from '../../app/fields';
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
  /** Step of the script: the points, each weight in turn, P(μ), the curve, the comparison. */
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

export const schema: Schema<BlendingState> = {
  p: points({ default: LECTURE_CUBIC, min: 2, max: MAX_POINTS }),
  mu: number({ default: 0.5, min: 0, max: 1 }),
  b: choice<Comparison>({ default: 'none', values: ['none', 'hermite', 'bspline', 'lagrange'] }),
  step: int({ default: 0, min: 0, max: MAX_POINTS + 4 }),
};

/** The degree N of the curve. */
export const degree = (state: BlendingState) => state.p.length - 1;

/**
 * Steps of the script: 0 the control points; 1 … N + 1 the weights W(N, 0, μ)
 * … W(N, N, μ) one by one; then P(μ), their weighted sum; then the curve it
 * traces; then, when one is chosen, the basis compared with.
 */
export const stepCount = (state: BlendingState) => degree(state) + 3 + (state.b === 'none' ? 0 : 1);

/** What step `step` shows. */
export interface Revealed {
  /** W(N, i, μ) are shown for i < weights. */
  weights: number;
  point: boolean;
  curve: boolean;
  compared: boolean;
}

export function revealed(state: BlendingState): Revealed {
  const n = degree(state);
  const k = state.step;
  return {
    weights: Math.min(k, n + 1),
    point: k >= n + 2,
    curve: k >= n + 3,
    compared: k >= n + 4,
  };
}
