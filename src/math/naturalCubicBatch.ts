import { checkCoordinateArrays, nonFiniteError } from './checkCoordinateArrays';
import {
  fillNaturalDerivatives,
  naturalBackSubstitution,
  naturalForwardSweep,
} from './naturalSolver';

// The natural cubic spline for very many points (10^5 – 10^6): typed arrays
// in, typed arrays out, no per-point objects; the same solver as
// naturalCubicDerivatives. Input checks are folded into the solve: a NaN or
// ±Infinity anywhere makes the end gradients non-finite, so the happy path
// pays nothing extra and only a failing call scans the input to name the culprit.

/** Bézier control points of every segment, one Float64Array per coordinate. */
export interface CubicBezierControls {
  /** `firstControl[c][i]`: coordinate c of Bi = Pi + Di/3, for segments i = 0 … m−1. */
  readonly firstControl: Float64Array[];
  /** `secondControl[c][i]`: coordinate c of Ci = P(i+1) − D(i+1)/3. */
  readonly secondControl: Float64Array[];
}

/**
 * The natural-spline gradients `D0 … Dm` of one coordinate's values, into `out`
 * (a new array unless given; it must not be `values` itself).
 */
export function naturalCubicDerivativesBatch(
  values: Float64Array,
  out: Float64Array = new Float64Array(values.length),
): Float64Array {
  const caller = 'naturalCubicDerivativesBatch';
  checkCoordinateArrays(caller, [values], 1);
  if (!(out instanceof Float64Array) || out.length < values.length || out === values) {
    throw new RangeError(
      `${caller}: out must be a separate Float64Array with at least ${values.length} entries.`,
    );
  }
  fillNaturalDerivatives(values, out);
  if (!Number.isFinite(out[0]) || !Number.isFinite(out[values.length - 1])) {
    throw nonFiniteError(caller, 'values', values);
  }
  return out;
}

/**
 * The natural C² cubic spline through the points whose coordinates are given as
 * parallel arrays (`[xs, ys]` or `[xs, ys, zs]`), as Bézier control points of
 * each of the m segments: segment i is `[Pi, Bi, Ci, P(i+1)]`. The same curve
 * as `cubicSplineC2`, for 10^6 points. Pass `out` (arrays of at least m
 * entries) to reuse buffers from frame to frame.
 */
export function naturalCubicBezierBatch(
  coordinates: readonly Float64Array[],
  out?: CubicBezierControls,
): CubicBezierControls {
  const caller = 'naturalCubicBezierBatch';
  const n = checkCoordinateArrays(caller, coordinates, 1);
  const m = n - 1;
  const result = out ?? {
    firstControl: coordinates.map(() => new Float64Array(m)),
    secondControl: coordinates.map(() => new Float64Array(m)),
  };
  checkOutput(caller, result, coordinates.length, m);
  const failed = fillNaturalBezierControls(coordinates, result);
  if (failed >= 0) throw nonFiniteError(caller, `coordinates[${failed}]`, coordinates[failed]);
  return result;
}

/**
 * naturalCubicBezierBatch without its checks, for callers that have checked the
 * arrays (n ≥ 1 points, `out` long enough). Returns the index of the first
 * coordinate whose values are or overflow to NaN or ±Infinity, or −1. Internal.
 */
export function fillNaturalBezierControls(
  coordinates: readonly Float64Array[],
  out: CubicBezierControls,
): number {
  const m = coordinates[0].length - 1;
  for (let c = 0; c < coordinates.length; c++) {
    const values = coordinates[c];
    if (m === 0) {
      if (!Number.isFinite(values[0])) return c;
      continue;
    }
    const first = out.firstControl[c];
    const second = out.secondControl[c];
    // Γ0 … Γ(m−1) then D0 … D(m−1) live in `first`, Dm in a local: no scratch array.
    const last = naturalForwardSweep(values, first);
    naturalBackSubstitution(first, m, last);
    if (!Number.isFinite(first[0]) || !Number.isFinite(last)) return c;
    const third = 1 / 3;
    for (let i = 0; i < m - 1; i++) {
      second[i] = values[i + 1] - first[i + 1] * third;
      first[i] = values[i] + first[i] * third;
    }
    second[m - 1] = values[m] - last * third;
    first[m - 1] = values[m - 1] + first[m - 1] * third;
  }
  return -1;
}

function checkOutput(caller: string, out: CubicBezierControls, dimension: number, m: number): void {
  for (const arrays of [out.firstControl, out.secondControl]) {
    if (
      !Array.isArray(arrays) ||
      arrays.length !== dimension ||
      arrays.some((array) => !(array instanceof Float64Array) || array.length < m)
    ) {
      throw new RangeError(
        `${caller}: out must hold ${dimension} Float64Arrays of at least ${m} entries in firstControl and in secondControl.`,
      );
    }
  }
}
