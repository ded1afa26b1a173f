import type { PracticeCase } from './types';

// The parametric quadratic through P0 (μ = 0), P1 (μ = μ1) and P2 (μ = 1), in
// Lagrange form: P(μ) = w0 P0 + w1 P1 + w2 P2 with
// w0 = (μ − μ1)(μ − 1)/μ1, w1 = μ(μ − 1)/(μ1(μ1 − 1)), w2 = μ(μ − μ1)/(1 − μ1).
type Pair = readonly [number, number];
const quadratic = (p0: Pair, p1: Pair, p2: Pair, mu1: number, mu: number): Pair => {
  const w0 = ((mu - mu1) * (mu - 1)) / mu1;
  const w1 = (mu * (mu - 1)) / (mu1 * (mu1 - 1));
  const w2 = (mu * (mu - mu1)) / (1 - mu1);
  return [0, 1].map((d) => w0 * p0[d] + w1 * p1[d] + w2 * p2[d]) as unknown as Pair;
};

export default [
  {
    // P0 = (0, 0), P1 = (1, 4), P2 = (6, 1), μ1 = 0.4, μ = 0.3:
    // w0 = (−0.1)(−0.7)/0.4 = 0.175, w1 = (−0.21)/(−0.24) = 0.875, w2 = (0.3)(−0.1)/0.6 = −0.05;
    // P(0.3) = (0.875 − 0.3, 3.5 − 0.05) = (0.575, 3.45).
    id: 'where',
    seed: 7,
    prompt: ['P₀ = (0, 0)', 'P₁ = (1, 4) at μ₁ = 0.4', 'P₂ = (6, 1)', 'Where is P(0.3)?'],
    answer: { point: quadratic([0, 0], [1, 4], [6, 1], 0.4, 0.3) },
  },
  {
    // μ1 = 0.5: a0 = P0 = (0, 0), a2 = 2P0 − 4P1 + 2P2 = (8, −14), a1 = P2 − P0 − a2 = (−2, 15);
    // P(0.3) = 0.3a1 + 0.09a2 = (−0.6 + 0.72, 4.5 − 1.26) = (0.12, 3.24).
    // Wrong: a2 with its sign flipped, so a1 = P2 − P0 + a2: (0.3·14 − 0.09·8, 0.3·(−13) + 0.09·14).
    id: 'compute',
    seed: 7,
    prompt: ['P₁ = (1, 4) at μ₁ = 0.5', 'Compute P(0.3) to 2 decimals'],
    answer: { numbers: [0.12, 3.24], wrong: [3.48, -2.64] },
  },
  {
    // μ1 = 0.5, μ = 0.2: w0 = (−0.3)(−0.8)/0.5 = 0.48, w1 = (0.2)(−0.8)/(−0.25) = 0.64,
    // w2 = (0.2)(−0.3)/0.5 = −0.12. With P0 = (0, 0), P2 = (6, 1) and P1 = (1, 4):
    // (0.64 − 0.72, 2.56 − 0.12) = (−0.08, 2.44), the target; P1 opens at (2, 5).
    id: 'steer',
    seed: 7,
    prompt: ['dot for μ = 0.2 sits at (−0.08, 2.44), within 0.1'],
    answer: { moves: [{ figure: 'quadratic', handle: 'p1', to: [1, 4] }] },
  },
] satisfies PracticeCase[];
