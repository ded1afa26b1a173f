import { bernsteinBasis, hermiteBasis, lagrangeBasis, uniformBSplineBasis } from '../../math';
import type { Comparison } from './state';

/** A family of blending functions on μ ∈ [0, 1], as the plot and the panel show them. */
export interface Basis {
  /** Lecture names with subscripts, one per function: `H_0`, `B_1`, `L_2`. */
  labels: string[];
  /** What each function weights, in words: `P_0`, `x_1′`. */
  weights: string[];
  values(mu: number): number[];
}

/** Equally spaced nodes 0, 1/N, …, 1: the Lagrange basis of the comparison. */
export const equallySpacedNodes = (n: number) =>
  Array.from({ length: n + 1 }, (_, i) => (n === 0 ? 0 : i / n));

export function bernsteinFamily(n: number): Basis {
  return {
    labels: Array.from({ length: n + 1 }, (_, i) => `W_{${n},${i}}`),
    weights: Array.from({ length: n + 1 }, (_, i) => `P_{${i}}`),
    values: (mu) => bernsteinBasis(n, mu),
  };
}

/** The basis compared with Bernstein's, for a curve of degree n; null for none. */
export function comparisonFamily(kind: Comparison, n: number): Basis | null {
  switch (kind) {
    case 'none':
      return null;
    case 'hermite':
      return {
        labels: ['H_0', 'H_1', 'H_2', 'H_3'],
        weights: ['x_0', 'x_1', "x_0'", "x_1'"],
        values: (mu) => hermiteBasis(mu),
      };
    case 'bspline':
      return {
        labels: ['B_0', 'B_1', 'B_2', 'B_3'],
        weights: ['P_i', 'P_{i+1}', 'P_{i+2}', 'P_{i+3}'],
        values: (mu) => uniformBSplineBasis(mu),
      };
    case 'lagrange': {
      const nodes = equallySpacedNodes(n);
      return {
        labels: nodes.map((_, i) => `L_{${i}}`),
        weights: nodes.map((_, i) => `P_{${i}}`),
        values: (mu) => lagrangeBasis(nodes, mu),
      };
    }
  }
}

/** Samples every function of a basis at `count + 1` equally spaced μ. */
export function sampleBasis(basis: Basis, count: number): { mu: number[]; values: number[][] } {
  const mu = Array.from({ length: count + 1 }, (_, k) => k / count);
  const rows = mu.map((m) => basis.values(m));
  const values = basis.labels.map((_, i) => rows.map((row) => row[i]));
  return { mu, values };
}

/** The smallest value any function of the basis takes on [0, 1] (sampled), and where. */
export function basisMinimum(
  basis: Basis,
  count = 400,
): { value: number; mu: number; index: number } {
  const { mu, values } = sampleBasis(basis, count);
  let best = { value: Infinity, mu: 0, index: 0 };
  values.forEach((row, index) =>
    row.forEach((value, k) => {
      if (value < best.value) best = { value, mu: mu[k], index };
    }),
  );
  return best;
}
