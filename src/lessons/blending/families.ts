import {
  type BasisSamples,
  bernsteinBasis,
  hermiteBasis,
  lagrangeBasis,
  sampleBasis,
  uniformBSplineBasis,
} from '../../math';
import type { Comparison } from './state';

/** Samples of each family on [0, 1]: the plot, its range, its lowest value and the hover read them. */
export const SAMPLES = 400;

/** A family of blending functions on μ ∈ [0, 1], as the plot and the panel show them. */
export interface Family {
  /** Lecture names with subscripts, one per function: `H_0`, `W_{3,1}`, `L_{2}`. */
  labels: string[];
  /** The family's name on the plot's axis: `W(N, i, μ)`, `B_{i}(μ)`. */
  name: string;
  /** What each function weights: `P_{0}`, `D_0`. */
  weights: string[];
  /** Palette index of each function. */
  colors: number[];
  values(mu: number): readonly number[];
  samples: BasisSamples;
  /** Sample index where each function is largest in size: its label goes there. */
  peaks: number[];
}

/** Equally spaced nodes 0, 1/N, …, 1: the Lagrange basis of the comparison. */
export const equallySpacedNodes = (n: number) =>
  Array.from({ length: n + 1 }, (_, i) => (n === 0 ? 0 : i / n));

/** H0 weights P0, H1 weights PN: they share those points' colours; H2, H3 follow. */
const hermiteColors = (n: number) => [0, n, 1, Math.max(2, n - 1)];

type FamilySpec = Omit<Family, 'samples' | 'peaks'>;

function spec(kind: Comparison | 'bernstein', n: number): FamilySpec | null {
  const each = (name: (i: number) => string) => Array.from({ length: n + 1 }, (_, i) => name(i));
  const indices = (count: number) => Array.from({ length: count }, (_, i) => i);
  switch (kind) {
    case 'none':
    case 'mirror':
      return null;
    case 'bernstein':
      return {
        labels: each((i) => `W_{${n},${i}}`),
        name: 'W(N, i, μ)',
        weights: each((i) => `P_{${i}}`),
        colors: indices(n + 1),
        values: (mu) => bernsteinBasis(n, mu),
      };
    case 'hermite':
      // The patch's data: its end points and their gradients D, as the Hermite lesson names them.
      return {
        labels: ['H_0', 'H_1', 'H_2', 'H_3'],
        name: 'H_{i}(μ)',
        weights: ['P_0', `P_{${n}}`, 'D_0', `D_{${n}}`],
        colors: hermiteColors(n),
        values: hermiteBasis,
      };
    case 'bspline':
      return {
        labels: ['B_0', 'B_1', 'B_2', 'B_3'],
        name: 'B_{i}(μ)',
        weights: ['P_i', 'P_{i+1}', 'P_{i+2}', 'P_{i+3}'],
        colors: indices(4),
        values: uniformBSplineBasis,
      };
    // Interpolating or approximating: the Lagrange curve is the interpolating one.
    case 'lagrange':
    case 'interpolating': {
      const nodes = equallySpacedNodes(n);
      return {
        labels: each((i) => `L_{${i}}`),
        name: 'L_{i}(μ)',
        weights: each((i) => `P_{${i}}`),
        colors: indices(n + 1),
        values: (mu) => lagrangeBasis(nodes, mu),
      };
    }
  }
}

function sampled(made: FamilySpec): Family {
  const samples = sampleBasis(made.values, SAMPLES);
  // Where each function is largest in size (W(N, i, μ) peaks at μ = i/N).
  const peaks = samples.curves.map((curve) => {
    let peak = 0;
    for (let k = 1; 2 * k < curve.length; k++)
      if (Math.abs(curve[2 * k + 1]) > Math.abs(curve[2 * peak + 1])) peak = k;
    return peak;
  });
  return { ...made, samples, peaks };
}

// A family depends only on its kind and N: dragging a point or μ samples nothing again.
const cache = new Map<string, Family | null>();

/** The family of a kind for a curve of degree n (sampled once), or null for none. */
export function family(kind: Comparison | 'bernstein', n: number): Family | null {
  const key = `${kind}:${n}`;
  if (!cache.has(key)) {
    const made = spec(kind, n);
    cache.set(key, made && sampled(made));
  }
  return cache.get(key) ?? null;
}
