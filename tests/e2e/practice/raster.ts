import type { PracticeCase } from './types';

export default [
  {
    // P₀ (4, 14), P₁ (14, 5), P₂ (30, 18). Off the chord the curve is 2t(1 − t)(P₁ − M),
    // largest at t = ½: P(½) = (P₀ + 2P₁ + P₂)/4 = (62/4, 42/4) = (15.5, 10.5).
    id: 'farthest-point',
    seed: 1,
    prompt: ['P₀ (4, 14), P₁ (14, 5) and P₂ (30, 18)', 'one segment'],
    answer: { point: [(4 + 2 * 14 + 30) / 4, (14 + 2 * 5 + 18) / 4] },
  },
  {
    // From pixel (22, 8) to (31, 7): x changes by 9, y by −1, so one pixel per step in x.
    // At x = 29 the ideal line is at y = 8 − 7/9 = 7.22, nearest row 7: (29, 7).
    // Wrong: 7.22 cut off towards the start, row 8.
    id: 'next-pixel',
    seed: 1,
    prompt: ['from pixel (22, 8) to pixel (31, 7)', 'after (28, 7)'],
    answer: { numbers: [29, 7], wrong: [29, 8] },
  },
  {
    // P₀ (9, 8), P₁ (12, 9), P₂ (19, 10), P₃ (23, 15):
    // P₂ − 2P₁ + P₀ = (19 − 24 + 9, 10 − 18 + 8) = (4, 0), length 4;
    // P₃ − 2P₂ + P₁ = (23 − 38 + 12, 15 − 20 + 9) = (−3, 4), length 5.
    // Flatness 3·2/8 · 5 = 3.75. Wrong: 5, the factor n(n − 1)/8 left out.
    id: 'flatness',
    seed: 42,
    prompt: ['P₀ (9, 8), P₁ (12, 9), P₂ (19, 10) and P₃ (23, 15)', 'to 2 decimals'],
    answer: { numbers: [3.75], wrong: [5] },
  },
  {
    // P₀ (10, 7), P₂ (26, 13), M = (18, 10). A quadratic's flatness is 2·1/8·‖P₀ − 2P₁ + P₂‖ = ½‖P₁ − M‖,
    // each half's a quarter of it. Two segments: ½‖P₁ − M‖ > 0.5 and ⅛‖P₁ − M‖ ≤ 0.5, 1 < ‖P₁ − M‖ ≤ 4.
    // P₁ = (17, 7): ‖(−1, −3)‖ = 3.16.
    id: 'two-segments',
    seed: 1,
    prompt: ['Keep P₀ (10, 7) and P₂ (26, 13)', 'τ = 0.5 px'],
    answer: { moves: [{ figure: 'curve', handle: 'p1', to: [17, 7] }] },
  },
] satisfies PracticeCase[];
