import { fillNaturalDerivatives, naturalForwardSweep, naturalGammaAt } from './naturalCubic';
import { checkCoordinateArrays, nonFiniteError } from './validate';

// The natural cubic spline for very many points (10^5 – 10^6): typed arrays
// in, typed arrays out, no per-point objects. The same Thomas sweep as
// naturalCubicDerivatives. Input checks are folded into the solve: a NaN or
// ±Infinity anywhere makes the last gradient non-finite, so the happy path
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
  if (out.length < values.length || out === values) {
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
 * as `cubicSplineC2`, for 10^6 points.
 */
export function naturalCubicBezierBatch(coordinates: readonly Float64Array[]): CubicBezierControls {
  const caller = 'naturalCubicBezierBatch';
  const n = checkCoordinateArrays(caller, coordinates, 1);
  const m = n - 1;
  const firstControl = coordinates.map(() => new Float64Array(m));
  const secondControl = coordinates.map(() => new Float64Array(m));
  if (m === 0) {
    for (let c = 0; c < coordinates.length; c++) {
      if (!Number.isFinite(coordinates[c][0]))
        throw nonFiniteError(caller, `coordinates[${c}]`, coordinates[c]);
    }
    return { firstControl, secondControl };
  }
  for (let c = 0; c < coordinates.length; c++) {
    controlPoints(caller, coordinates[c], firstControl[c], secondControl[c], `coordinates[${c}]`);
  }
  return { firstControl, secondControl };
}

/**
 * One coordinate: the forward sweep leaves Γ0 … Γ(m−1) in `first`, then a single
 * backward pass turns each Γi into Di and writes both control points, so no
 * scratch array is needed.
 */
function controlPoints(
  caller: string,
  ys: Float64Array,
  first: Float64Array,
  second: Float64Array,
  name: string,
): void {
  const m = ys.length - 1;
  let next = naturalForwardSweep(ys, first); // Dm = Γm
  if (!Number.isFinite(next)) throw nonFiniteError(caller, name, ys);
  const third = 1 / 3;
  for (let i = m - 1; i >= 0; i--) {
    second[i] = ys[i + 1] - next * third;
    next = first[i] - naturalGammaAt(i) * next;
    first[i] = ys[i] + next * third;
  }
  if (!Number.isFinite(next)) throw nonFiniteError(caller, name, ys);
}
