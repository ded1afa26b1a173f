import { type Point, bezierCurvature, bezierTangent, norm } from '../../math';

// dκ/ds, the rate at which the curvature changes along the curve, at an end of
// a Bézier piece. src/math gives κ (bezierCurvature) but not its derivative,
// so it is taken here by a one-sided finite difference of κ in the piece's own
// parameter p, of second order (Fornberg's one-sided stencil):
//   dκ/dp(0) ≈ (−3κ(0) + 4κ(h) − κ(2h)) / 2h,  dκ/dp(1) ≈ (3κ(1) − 4κ(1 − h) + κ(1 − 2h)) / 2h,
// then dκ/ds = (dκ/dp) / |P′|, since ds = |P′| dp. The error is of order h²κ‴
// (2·10⁻⁸ at the joins of the lesson's spline with h = 10⁻⁵; 2·10⁻⁶ with 10⁻⁴),
// rounding of order 10⁻¹⁶κ/h (10⁻¹⁰).

/** The step h in the piece's parameter p. */
export const SLOPE_STEP = 1e-5;

/** The slope of κ at an end of a piece: per unit of the parameter p, and per unit of arc length s. */
export interface CurvatureSlope {
  perParameter: number;
  perLength: number;
}

/**
 * dκ/dp and dκ/ds at the start (end 0) or the finish (end 1) of a Bézier
 * piece, from inside the piece only; null where κ or the speed is undefined
 * (P′ = 0) within the stencil.
 */
export function curvatureSlope(
  piece: readonly Point[],
  end: 0 | 1,
  h = SLOPE_STEP,
): CurvatureSlope | null {
  try {
    const kappa = (p: number) => bezierCurvature(piece, p);
    const perParameter =
      end === 0
        ? (-3 * kappa(0) + 4 * kappa(h) - kappa(2 * h)) / (2 * h)
        : (3 * kappa(1) - 4 * kappa(1 - h) + kappa(1 - 2 * h)) / (2 * h);
    return { perParameter, perLength: perParameter / norm(bezierTangent(piece, end)) };
  } catch {
    return null;
  }
}
