/**
 * The Lagrange polynomial through the points: the basis L_k sampled once, the
 * curve Σ L_k(t) P_k at the same t's, and what the figures read from them.
 * It depends on the points and the spacing only.
 */
import { clipToBand, lagrangeBasis, lebesgueConstant, type Point, sampleBasis } from '../../math';
import { memoOn } from '../../kit/memoOn';
import { CLIP, basisBounds, curveBounds } from './bounds';
import type { LagrangeModel } from './model';
import { collapsedNotes, noteFor } from './notes';
import { type Nodes, parameters } from './parameters';

/**
 * The basis is sampled at t = i / SAMPLES, once: the plot, the curve
 * Σ L_k(t) P_k, the largest Σ|L_k(t)| and the hover over a basis curve all
 * read these numbers.
 */
export const SAMPLES = 800;

/** What depends on the points and the spacing only. */
export type Polynomial = Omit<
  LagrangeModel,
  'state' | 'shown' | 'weights' | 'weightSum' | 'at' | 'comparison'
>;

/**
 * The basis and the polynomial: they read only the points and the spacing, so
 * a step, a moved t or the spline switched costs no new sampling.
 */
export const polynomial = memoOn<Nodes, 'points' | 'spacing', Polynomial>(
  ['points', 'spacing'],
  (fields) => {
    const { points } = fields;
    const { ts, collapsed } = parameters(fields);
    const basis = sampleBasis((at) => lagrangeBasis(ts, at), SAMPLES);
    const curves = basis.curves;
    const curve = combine(curves, points);
    const plotBounds = basisBounds(basis);
    const note = noteFor(points, collapsed !== null);
    return {
      n: points.length - 1,
      note,
      ts,
      collapsed,
      ...collapsedNotes(collapsed),
      basis,
      curve,
      lebesgue: lebesgueConstant(curves),
      curveBounds: curveBounds(points, curve, collapsed !== null || note !== null),
      plotBounds,
      basisPieces: curves.map((c) => clipToBand(c, plotBounds.minY, plotBounds.maxY)),
      basisCut: basis.lowest.value < -CLIP || basis.highest.value > CLIP,
    };
  },
);

/** P(t_i) = Σ_k L_k(t_i) P_k at every sampled t_i, interleaved [x, y, …]. */
function combine(basis: readonly Float64Array[], p: readonly Point[]): Float64Array {
  const out = new Float64Array(basis[0].length);
  basis.forEach((curve, k) => {
    for (let i = 1; i < curve.length; i += 2) {
      out[i - 1] += curve[i] * p[k][0];
      out[i] += curve[i] * p[k][1];
    }
  });
  return out;
}
