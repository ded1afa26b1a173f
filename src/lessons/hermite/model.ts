import {
  bezierDerivative,
  bezierJointContinuity,
  cubicSplineSegments,
  hermiteBasis,
  hermiteCoefficients,
  hermitePoint,
  hermiteToBezier,
  type Continuity,
  type Point,
} from '../../math';
import { type HermiteState, gradients } from './state';

// What the figures and the panel share, computed from src/math.

/** Every patch as its cubic Bézier control points [Pi, Pi + Di/3, P(i+1) − D(i+1)/3, P(i+1)]. */
export const patchSegments = (state: HermiteState): Point[][] =>
  cubicSplineSegments(state.p, gradients(state));

/** The chosen patch: its end data, coefficients (equation 7), point and basis at μ. */
export function patchAt(state: HermiteState) {
  const i = state.patch;
  const D = gradients(state);
  const [p0, p1, d0, d1] = [state.p[i], state.p[i + 1], D[i], D[i + 1]];
  return {
    index: i,
    p0,
    p1,
    d0,
    d1,
    coefficients: hermiteCoefficients(p0, d0, p1, d1),
    point: hermitePoint(p0, d0, p1, d1, state.mu),
    weights: hermiteBasis(state.mu),
    bezier: hermiteToBezier(p0, d0, p1, d1),
  };
}

export interface Join {
  /** The point where patch k − 1 ends and patch k begins. */
  k: number;
  continuity: Continuity;
  /** dP/dμ at the end of the patch before and the start of the patch after. */
  before: Point;
  after: Point;
}

/** Continuity at every inner point, measured on the patches (not assumed). */
export function joins(state: HermiteState): Join[] {
  const segments = patchSegments(state);
  return segments.slice(1).map((right, j) => {
    const left = segments[j];
    const hodographLeft = bezierDerivative(left);
    return {
      k: j + 1,
      continuity: bezierJointContinuity(left, right),
      before: hodographLeft[hodographLeft.length - 1],
      after: bezierDerivative(right)[0],
    };
  });
}
