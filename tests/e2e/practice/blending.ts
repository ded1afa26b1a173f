import type { PracticeCase } from './types';

export default [
  {
    // W(5, 2, 0.25) = C(5, 2)·0.25²·0.75³ = 10·0.0625·0.421875 = 270/1024 = 0.263671875.
    // Wrong: μ and 1 − μ swapped, 10·0.75²·0.25³ = 90/1024 = 0.087890625.
    id: 'weight',
    seed: 4,
    prompt: ['W(5, 2, 0.25)', 'weight of P₂', 'N = 5', 'to 3 decimals'],
    answer: { numbers: [270 / 1024], wrong: [90 / 1024] },
  },
  {
    // P0 = (0, 0), P1 = (2, 4), P2 = (4, 1), μ = 0.5: weights (1 − μ)² = 1/4, 2μ(1 − μ) = 1/2, μ² = 1/4;
    // P(0.5) = (2·1/2 + 4·1/4, 4·1/2 + 1·1/4) = (2, 2.25).
    id: 'blend',
    seed: 8,
    prompt: ['Where is P(0.5)', 'W(2, i, 0.5)', 'within 0.2'],
    answer: { point: [2, 2.25] },
  },
  {
    // W(4, 1, μ) = 4μ(1 − μ)³ is largest where its derivative 4(1 − μ)²(1 − 4μ) is 0: μ = 1/4,
    // where it is 4·(1/4)·(3/4)³ = 27/64 = 0.421875 (on the plot of μ against W).
    id: 'peak',
    seed: 6,
    prompt: ['top of the blending function W(4, 1, μ)', 'within 0.05'],
    answer: { point: [0.25, 27 / 64] },
  },
  {
    // W(4, 0, μ) = W(4, 1, μ): (1 − μ)⁴ = 4μ(1 − μ)³, so 1 − μ = 4μ and μ = 0.2 (the cursor opens at 0.9).
    // The cursor's handle moves along μ only: its height does not matter.
    id: 'crossing',
    seed: 6,
    prompt: ['P₀ and P₁ pull equally hard', 'W(4, 0, μ) = W(4, 1, μ)', 'within 5%'],
    answer: { moves: [{ figure: 'blending', handle: 'mu', to: [0.2, 0.9] }] },
  },
] satisfies PracticeCase[];
