import { projectiveMap } from './projectiveMap';
import { checkNumbers, checkSameLength } from './validate';
import type { Point } from './vec';

// A NURBS curve is a polynomial B-spline in homogeneous coordinates
// (wᵢxᵢ, wᵢyᵢ, wᵢ) (Piegl & Tiller, The NURBS Book, §4.2). A projective map H
// is linear on those coordinates, so it commutes with the sum Σ Nᵢ(t)·(wᵢxᵢ,
// wᵢyᵢ, wᵢ): mapping the control points and multiplying each weight by the new
// homogeneous coordinate h₂·(xᵢ, yᵢ, 1) maps the whole curve exactly.

/**
 * The control points and weights of the image of a rational curve under the
 * plane map `matrix` (3×3, rows): `P′ᵢ = H(Pᵢ)` and `w′ᵢ = wᵢ·(h₂₀xᵢ + h₂₁yᵢ +
 * h₂₂)`. With the same knots and degree, the NURBS of (P′, w′) is H applied to
 * the NURBS of (P, w). Throws as `projectiveMap` does for a point on or beyond
 * the vanishing line.
 */
export function projectiveMapWeighted(
  matrix: readonly (readonly number[])[],
  points: readonly Point[],
  weights: readonly number[],
): { points: Point[]; weights: number[] } {
  const caller = 'projectiveMapWeighted';
  checkNumbers(caller, 'weights', weights, 1);
  checkSameLength(caller, 'weights', weights, 'points', points);
  const mapped = projectiveMap(matrix, points);
  const [h0, h1, h2] = matrix[2];
  return {
    points: mapped,
    weights: points.map(([x, y], i) => weights[i] * (h0 * x + h1 * y + h2)),
  };
}
