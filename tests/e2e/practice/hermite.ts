import type { PracticeCase } from './types';

// One cubic patch from P0 (μ = 0) to P1 (μ = 1) with gradients D0, D1:
// P(μ) = H0 P0 + H1 P1 + H2 D0 + H3 D1 with H0 = 2μ³ − 3μ² + 1, H1 = −2μ³ + 3μ²,
// H2 = μ³ − 2μ² + μ, H3 = μ³ − μ².
type Pair = readonly [number, number];
const patch = (p0: Pair, d0: Pair, p1: Pair, d1: Pair, mu: number) => {
  const h = [
    2 * mu ** 3 - 3 * mu ** 2 + 1,
    -2 * mu ** 3 + 3 * mu ** 2,
    mu ** 3 - 2 * mu ** 2 + mu,
    mu ** 3 - mu ** 2,
  ];
  return [0, 1].map((d) => h[0] * p0[d] + h[1] * p1[d] + h[2] * d0[d] + h[3] * d1[d]) as [
    number,
    number,
  ];
};

export default [
  {
    // P0 = (0, 0), D0 = (6, 3), P1 = (6, 0), D1 = (6, −3), μ = 0.75:
    // H = 0.15625, 0.84375, 0.046875, −0.140625, so
    // P(0.75) = (6(0.84375 + 0.046875 − 0.140625), 3(0.046875 + 0.140625)) = (4.5, 0.5625).
    id: 'where',
    seed: 9,
    prompt: [
      'P₀ = (0, 0) with gradient D₀ = (6, 3)',
      'P₁ = (6, 0) with D₁ = (6, −3)',
      'Where is P(0.75)?',
    ],
    answer: { point: patch([0, 0], [6, 3], [6, 0], [6, -3], 0.75) },
  },
  {
    // Patch 2: P1 = (2, 3), D1 = (1, 2), P2 = (5, 1), D2 = (1, 1). Equation 7:
    // a2 = −3P1 − 2D1 + 3P2 − D2 = (−6 − 2 + 15 − 1, −9 − 4 + 3 − 1) = (6, −11),
    // a3 = 2P1 + D1 − 2P2 + D2 = (4 + 1 − 10 + 1, 6 + 2 − 2 + 1) = (−4, 7).
    // Wrong: a2 and a3 swapped.
    id: 'coefficients',
    seed: 9,
    prompt: ['Patch 2 runs from P₁ = (2, 3) to P₂ = (5, 1)', 'D₁ = (1, 2) and D₂ = (1, 1)'],
    answer: { numbers: [6, -11, -4, 7], wrong: [-4, 7, 6, -11] },
  },
  {
    // P0 = B0 = (0, 1), P1 = B3 = (5, 2); B1 = (1, 3), B2 = (3, 1). D0 = 3(B1 − B0) = (3, 6)
    // has its tip P0 + D0/3 at B1; D1 = 3(B3 − B2) = (6, 3) has its tip at P1 + D1/3 = (7, 3),
    // B2 mirrored through P1.
    id: 'bezier',
    seed: 9,
    prompt: ['B₁ = (1, 3) and B₂ = (3, 1), each within 0.15'],
    answer: {
      moves: [
        { figure: 'patches', handle: 'd0', to: [1, 3] },
        { figure: 'patches', handle: 'd1', to: [7, 3] },
      ],
    },
  },
] satisfies PracticeCase[];
