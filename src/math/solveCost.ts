import { checkInteger } from './validate';

// Why the spline's system is solved by the Thomas algorithm and not by a dense
// method (lecture notes, "solving the tridiagonal system"): arithmetic
// operations (+ − × ÷, each counted once) of each algorithm as implemented.

/**
 * Operations of the Thomas algorithm (see tridiagonal.ts) on n unknowns with
 * `rightHandSides` right-hand sides sharing the matrix (x and y: 2). Forward
 * sweep: the pivot `bi − ai γ(i−1)` (2 ops) and `γi = ci / pivot` (1) for rows
 * 1 … n−2, plus γ0 (1) and the last pivot (2); each Γi costs 3 (Γ0: 1). Back
 * substitution: `xi = Γi − γi x(i+1)`, 2 per row above the last.
 */
export function thomasOperationCount(n: number, rightHandSides = 1): number {
  checkInteger('thomasOperationCount', 'n', n, 1);
  checkInteger('thomasOperationCount', 'rightHandSides', rightHandSides, 1);
  if (n === 1) return rightHandSides;
  const matrix = 1 + 3 * (n - 2) + 2;
  const perRightHandSide = 1 + 3 * (n - 1) + 2 * (n - 1);
  return matrix + rightHandSides * perRightHandSide;
}

/**
 * Operations of textbook Gaussian elimination without pivoting on a dense
 * N × N matrix with `rightHandSides` right-hand sides: for each pivot k and each
 * row below it, one division for the multiplier and a multiply-subtract for each
 * of the N−k remaining entries and each right-hand side; then back substitution,
 * N² per right-hand side. With N right-hand sides (the columns of I) it computes
 * the inverse. About 2N³/3 for one right-hand side.
 */
export function gaussianEliminationOperationCount(size: number, rightHandSides = 1): number {
  checkInteger('gaussianEliminationOperationCount', 'size', size, 1);
  checkInteger('gaussianEliminationOperationCount', 'rightHandSides', rightHandSides, 1);
  const N = size;
  // Σ over j = N−k = 1 … N−1 of j·(1 + 2j + 2r).
  const sumJ = ((N - 1) * N) / 2;
  const sumJ2 = ((N - 1) * N * (2 * N - 1)) / 6;
  return (1 + 2 * rightHandSides) * sumJ + 2 * sumJ2 + rightHandSides * N * N;
}

/** The counting argument for one piecewise curve, per coordinate. */
export interface ConstraintCount {
  segments: number;
  unknowns: number;
  /** Conditions at the points where two segments meet (positions twice, plus one per derivative). */
  inner: number;
  /** Positions at the two ends of an open curve. */
  ends: number;
  /** Conditions still needed, to be chosen: the end conditions. */
  free: number;
}

/**
 * The counting argument for a piecewise curve of `degree` through m + 1 points
 * (m segments; a closed curve has m + 1): per coordinate, how many unknown
 * coefficients and how many conditions fix them. `continuity` is the order of
 * the joins (1: C¹, 2: C²). Open curves get `2` end positions and whatever end
 * conditions remain; a closed curve has every point as an inner join.
 */
export function constraintCount(
  points: number,
  degree: number,
  continuity: number,
  closed = false,
): ConstraintCount {
  checkInteger('constraintCount', 'points', points, 2);
  checkInteger('constraintCount', 'degree', degree, 1);
  checkInteger('constraintCount', 'continuity', continuity, 0);
  const segments = closed ? points : points - 1;
  const joins = closed ? points : points - 2;
  const unknowns = (degree + 1) * segments;
  const inner = (2 + continuity) * joins;
  const ends = closed ? 0 : 2;
  return { segments, unknowns, inner, ends, free: unknowns - inner - ends };
}
