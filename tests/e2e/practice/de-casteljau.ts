import type { PracticeCase } from './types';

// The cubic Bézier point (1 − t)³P0 + 3t(1 − t)²P1 + 3t²(1 − t)P2 + t³P3, written
// out here (not imported) so the answers stand on their own.
type Pair = readonly [number, number];
const cubic = (p: readonly Pair[], t: number): Pair => {
  const w = [(1 - t) ** 3, 3 * t * (1 - t) ** 2, 3 * t ** 2 * (1 - t), t ** 3];
  return [0, 1].map((d) => w.reduce((sum, wi, i) => sum + wi * p[i][d], 0)) as unknown as Pair;
};

export default [
  {
    // P0 = (0, 0), P1 = (0, 3), P2 = (5, 3), P3 = (5, 0), t = 0.75: weights 1/64, 9/64, 27/64, 27/64;
    // P(0.75) = ((27·5 + 27·5)/64, (9·3 + 27·3)/64) = (4.21875, 1.6875).
    id: 'where-is-p',
    seed: 2,
    prompt: ['Where is P(0.75)', 'within 0.2'],
    answer: {
      point: cubic(
        [
          [0, 0],
          [0, 3],
          [5, 3],
          [5, 0],
        ],
        0.75,
      ),
    },
  },
  {
    // t = 0.3. Level 1: P₁,₀ = 0.7·(0, 1) + 0.3·(0, 2) = (0, 1.3); P₁,₁ = 0.7·(0, 2) + 0.3·(4, 4) = (1.2, 2.6).
    // Level 2: P₂,₀ = 0.7·(0, 1.3) + 0.3·(1.2, 2.6) = (0.36, 1.69).
    // Wrong: t and 1 − t swapped gives P₁,₀ = (0, 1.7), P₁,₁ = (2.8, 3.4), P₂,₀ = (1.96, 2.89).
    id: 'level-point',
    seed: 2,
    prompt: [
      'P₀ = (0, 1), P₁ = (0, 2), P₂ = (4, 4), P₃ = (6, 0)',
      't = 0.3',
      'P₂,₀',
      'to 2 decimals',
    ],
    answer: { numbers: [0.36, 1.69], wrong: [1.96, 2.89] },
  },
  {
    // Split at t = 0.3; the right half runs P₃,₀, P₂,₁, P₁,₂, P₃, so its second point is P₂,₁.
    // Level 1: P₁,₁ = 0.7·(0, 2) + 0.3·(4, 4) = (1.2, 2.6), P₁,₂ = 0.7·(4, 4) + 0.3·(6, 0) = (4.6, 2.8).
    // Level 2: P₂,₁ = 0.7·(1.2, 2.6) + 0.3·(4.6, 2.8) = (2.22, 2.66).
    // Wrong: P₁ itself, (0, 2).
    id: 'split-half',
    seed: 2,
    prompt: ['at t = 0.3', 'second control point of the right half', 'to 2 decimals'],
    answer: { numbers: [2.22, 2.66], wrong: [0, 2] },
  },
  {
    // P0 = (0, 1), P1 = (2, 2), P2 = (4, 2), P3 = (6, 1): P(0.5) = (P0 + 3P1 + 3P2 + P3)/8 = (3, 1.75).
    // X = (3.7, 1.8) is (0.7, 0.05) away, and P(0.5) moves by W(3, 2, 0.5) = 3/8 of P2's move:
    // P2 goes to (4 + 0.7·8/3, 2 + 0.05·8/3) = (5.8667, 2.1333).
    id: 'through-point',
    seed: 5,
    prompt: ['Move only P₂', 'X = (3.7, 1.8)', 't = 0.5', 'within 0.08'],
    answer: {
      moves: [
        {
          figure: 'construction',
          handle: 'p2',
          to: [4 + (0.7 * 8) / 3, 2 + (0.05 * 8) / 3],
        },
      ],
    },
  },
] satisfies PracticeCase[];
