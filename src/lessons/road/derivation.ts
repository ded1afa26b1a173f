import { cubicSplineCoefficients } from '../../math';
import type { RoadSolve } from './solve';

// The natural spline's system derived at one join, as the lecture slides do
// it ("Computing natural cubic splines"), with the numbers of the villages on
// the map: each piece y = a + b p + c p² + d p³ in its local parameter p; a … d
// in the heights y and gradients D at its ends; y″ = 2c + 6dp equal from both
// sides of the join; hence the row D(i−1) + 4Di + D(i+1) = 3(y(i+1) − y(i−1)).

/** a, b, c, d of one piece in one coordinate. */
export type Coefficients = readonly [number, number, number, number];

/** One coordinate (x or y) of the derivation: its values, gradients and pieces. */
export interface CoordinateWork {
  /** The villages' values y0 … ym (or x0 … xm). */
  values: readonly number[];
  /** The gradients D0 … Dm the system gives. */
  gradients: readonly number[];
  /** a, b, c, d of every segment, from y and D (src/math's cubicSplineCoefficients). */
  pieces: readonly Coefficients[];
  /** y″ of every segment at its start (p = 0) and its end (p = 1): 2c and 2c + 6d. */
  curvature: readonly (readonly [number, number])[];
  /** The system's right-hand side, 3(y1 − y0), 3(y(i+1) − y(i−1)), …, 3(ym − y(m−1)). */
  rhs: readonly number[];
}

export interface Derivation {
  /** The last village's index m (segments 0 … m − 1). */
  m: number;
  /**
   * The join the steps work at: inner village j, where segments j − 1 and j
   * meet; the village nearest the marker p̄ (null with two villages: no inner join).
   */
  join: number | null;
  /** x, then y. */
  coordinates: [CoordinateWork, CoordinateWork];
}

/** The inner village nearest p̄: 1 … m − 1, or null when there is none. */
export function joinNear(pBar: number, m: number): number | null {
  if (m < 2) return null;
  return Math.max(1, Math.min(m - 1, Math.round(pBar)));
}

/** The derivation for the natural road's solve through `villages`, at the join nearest p̄. */
export function deriveSystem(
  villages: readonly (readonly number[])[],
  solve: RoadSolve,
  pBar: number,
): Derivation {
  const m = solve.n - 1;
  const coordinate = (k: 0 | 1): CoordinateWork => {
    const values = villages.map((p) => p[k]);
    const gradients = solve.trace[k].solution;
    const pieces = cubicSplineCoefficients(values, gradients);
    return {
      values,
      gradients,
      pieces,
      curvature: pieces.map(([, , c, d]) => [2 * c, 2 * c + 6 * d] as const),
      rhs: solve.rhs[k],
    };
  };
  return { m, join: joinNear(pBar, m), coordinates: [coordinate(0), coordinate(1)] };
}
