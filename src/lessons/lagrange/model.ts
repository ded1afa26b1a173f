import {
  cubicSplineSegments,
  lagrangeBasis,
  lagrangePoint,
  naturalCubicTangents,
  parameterValues,
  type Point,
} from '../../math';
import type { LagrangeState } from './state';

// What the figures and the panel share, computed once per state from src/math.

export interface Interpolant {
  /** The parameter values t_k actually used. */
  ts: number[];
  /** Chord length was asked for but two neighbours coincide: which ones (then ts are uniform). */
  collapsed: [number, number] | null;
}

/** t_k by the chosen spacing; chord length with two equal neighbours falls back to uniform. */
export function interpolant(state: LagrangeState): Interpolant {
  if (state.spacing === 'chord') {
    const ts = parameterValues(state.p, 1);
    for (let k = 1; k < ts.length; k++) {
      // Equal values: no polynomial can be at two places at one t.
      if (ts[k] === ts[k - 1]) return { ts: parameterValues(state.p, 0), collapsed: [k - 1, k] };
    }
    return { ts, collapsed: null };
  }
  return { ts: parameterValues(state.p, 0), collapsed: null };
}

/** The Lagrange polynomial sampled over t ∈ [0, 1], as a flat [x0, y0, x1, y1, …]. */
export function samplePolynomial(state: LagrangeState, ts: readonly number[], count = 600) {
  const out = new Float64Array(2 * (count + 1));
  for (let i = 0; i <= count; i++) {
    const q = lagrangePoint(ts, state.p, i / count);
    out[2 * i] = q[0];
    out[2 * i + 1] = q[1];
  }
  return out;
}

export const polynomialPoint = (state: LagrangeState, ts: readonly number[], t: number) =>
  lagrangePoint(ts, state.p, t);

/** The natural cubic spline through the same points, as cubic Bézier segments. */
export const splineSegments = (state: LagrangeState): Point[][] =>
  cubicSplineSegments(state.p, naturalCubicTangents(state.p));

/** Each L_k sampled over [0, 1]: curves[k] = [t0, L_k(t0), t1, L_k(t1), …]. */
export function sampleBasis(ts: readonly number[], count = 400): Float64Array[] {
  const curves = ts.map(() => new Float64Array(2 * (count + 1)));
  for (let i = 0; i <= count; i++) {
    const t = i / count;
    lagrangeBasis(ts, t).forEach((value, k) => {
      curves[k][2 * i] = t;
      curves[k][2 * i + 1] = value;
    });
  }
  return curves;
}

/**
 * The largest Σ|L_k(t)| over [0, 1] (the Lebesgue constant, sampled) and where:
 * moving every point by at most ε moves the curve by at most this times ε.
 */
export function amplification(ts: readonly number[], count = 800) {
  let best = { value: 0, t: 0 };
  for (let i = 0; i <= count; i++) {
    const t = i / count;
    const value = lagrangeBasis(ts, t).reduce((sum, w) => sum + Math.abs(w), 0);
    if (value > best.value) best = { value, t };
  }
  return best;
}
