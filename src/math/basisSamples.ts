import { checkInteger, checkNumber } from './validate';

// A family of blending functions of μ ∈ [0, 1] (Bernstein, Hermite, Lagrange,
// B-spline …) sampled once at equally spaced μ: enough to plot it, to find its
// lowest and highest values, and to read it back anywhere by interpolation.

/** The smallest or largest sampled value of a family: the value, where, and which function. */
export interface BasisExtreme {
  value: number;
  mu: number;
  /** Index of the function that takes it (the first one, on a tie). */
  index: number;
}

export interface BasisSamples {
  /** Intervals of [0, 1]: the values are at μ = k / count, k = 0 … count. */
  count: number;
  /** One array per function, interleaved μ and value: `[0, f(0), 1/count, f(1/count), …]`. */
  curves: Float64Array[];
  lowest: BasisExtreme;
  highest: BasisExtreme;
}

/**
 * Samples every function of a family at `count + 1` equally spaced μ in
 * [0, 1]. `values(μ)` returns the value of each function at μ, in order.
 */
export function sampleBasis(
  values: (mu: number) => readonly number[],
  count: number,
): BasisSamples {
  checkInteger('sampleBasis', 'count', count, 1);
  let curves: Float64Array[] = [];
  for (let k = 0; k <= count; k++) {
    const mu = k / count;
    const row = values(mu);
    if (k === 0) curves = row.map(() => new Float64Array(2 * (count + 1)));
    for (let i = 0; i < curves.length; i++) {
      curves[i][2 * k] = mu;
      curves[i][2 * k + 1] = checkNumber('sampleBasis', `values(${mu})[${i}]`, row[i]);
    }
  }
  return { count, curves, ...extremes(curves) };
}

// Function by function, then along μ: on a tie the lower index and the smaller μ win.
function extremes(curves: readonly Float64Array[]): {
  lowest: BasisExtreme;
  highest: BasisExtreme;
} {
  const lowest = { value: Infinity, mu: 0, index: 0 };
  const highest = { value: -Infinity, mu: 0, index: 0 };
  curves.forEach((curve, index) => {
    for (let k = 1; k < curve.length; k += 2) {
      const value = curve[k];
      if (value < lowest.value) Object.assign(lowest, { value, mu: curve[k - 1], index });
      if (value > highest.value) Object.assign(highest, { value, mu: curve[k - 1], index });
    }
  });
  return { lowest, highest };
}

/**
 * Every function's value at μ (clamped to [0, 1]), interpolated linearly
 * between the two nearest samples: exact at the samples, and within
 * max|f″|·h²/8 of the true value in between (h = 1/count).
 */
export function basisValuesAt(samples: BasisSamples, mu: number): number[] {
  checkNumber('basisValuesAt', 'mu', mu);
  const { count } = samples;
  const x = Math.min(1, Math.max(0, mu)) * count;
  const k = Math.min(count - 1, Math.floor(x));
  const f = x - k;
  return samples.curves.map((curve) => (1 - f) * curve[2 * k + 1] + f * curve[2 * k + 3]);
}
