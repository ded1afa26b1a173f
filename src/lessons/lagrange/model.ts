/**
 * The Lagrange lesson's model: everything the two figures and the panel show,
 * derived once per state from the polynomial (points and spacing), the weights
 * at the slider's t and, when asked for, the spline it is compared with.
 */
import { type BasisSamples, lagrangeBasis, type Point } from '../../math';
import { type Bounds, boundsOf, unionBounds } from '../../render/projection';
import type { Revealed } from '../../kit/script';
import { polynomial } from './polynomial';
import type { Reveal } from './script';
import { type SplineComparison, splineThrough } from './splineComparison';
import type { LagrangeState } from './state';

// The sampling and the cut the model's arrays are made with, for the figures and tests that read them.
export { SAMPLES } from './polynomial';
export { CLIP } from './bounds';

/** Everything the two figures and the panel show, computed once per state. */
export interface LagrangeModel {
  state: LagrangeState;
  /** Degree n = number of points − 1. */
  n: number;
  /** What the steps so far reveal: how many Lₖ, the polynomial, the spline. */
  shown: Revealed<Reveal>;
  /** Points on one spot or one line, and what the polynomial does then; or null. */
  note: string | null;
  /** The parameter values t_k actually used. */
  ts: number[];
  /** Chord length was asked for but two neighbours coincide: which ones (then ts are uniform). */
  collapsed: [number, number] | null;
  /** Why the values are uniform after all: on the figure, and in the panel. */
  collapsedNote: string | null;
  collapsedWarning: string | null;
  /** Each L_k at t = i / SAMPLES (`basis.curves[k]`, interleaved [t, L_k(t), …]), and their extremes. */
  basis: BasisSamples;
  /** The polynomial at the same t's, interleaved [x, y, …]. */
  curve: Float64Array;
  /** The weights L_k(t) at the slider's t, their sum, and the point they give. */
  weights: number[];
  weightSum: number;
  at: Point;
  /** The natural cubic spline through the same points, compared with the polynomial (when asked for). */
  comparison: SplineComparison | null;
  /** The largest Σ|L_k(t)| (the Lebesgue constant, sampled) and where it is reached. */
  lebesgue: { value: number; t: number };
  /** "Fit view" of the curve figure: the points, and the polynomial's swings up to a point. */
  curveBounds: Bounds;
  /** The basis plot's range, and each L_k cut to it. */
  plotBounds: Bounds;
  basisPieces: Float64Array[][];
  /** Some L_k leaves ±CLIP. */
  basisCut: boolean;
}

/** The id under the pointer when it is over L_k's curve (the panel marks L_k's row). */
export const basisId = (k: number) => `L${k}`;

export function derive(state: LagrangeState, shown: Revealed<Reveal>): LagrangeModel {
  const { points, t } = state;
  const geometry = polynomial(state);
  const weights = lagrangeBasis(geometry.ts, t);
  const comparison = splineThrough(state);
  return {
    ...geometry,
    // Beside the spline, its gradients' arrows (drawn at true length) stay on the figure too.
    curveBounds: comparison
      ? unionBounds(
          geometry.curveBounds,
          boundsOf(
            points.map((p, k) => [
              p[0] + comparison.gradients[k][0],
              p[1] + comparison.gradients[k][1],
            ]),
          ),
        )
      : geometry.curveBounds,
    state,
    shown,
    weights,
    weightSum: weights.reduce((a, b) => a + b, 0),
    at: [0, 1].map((d) => weights.reduce((sum, w, k) => sum + w * points[k][d], 0)),
    comparison,
  };
}
