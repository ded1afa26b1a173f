import type { PracticeCase } from './types';

// The answers worked here on their own (nothing imported from src/): the uniform
// cubic's bases, one Cox–de Boor step, and the knots that repeat.

type Pair = readonly [number, number];
/** B0(t) … B3(t) of the uniform cubic: (1 − t)³/6, (3t³ − 6t² + 4)/6, (−3t³ + 3t² + 3t + 1)/6, t³/6. */
const bases = (t: number) => [
  (1 - t) ** 3 / 6,
  (3 * t ** 3 - 6 * t ** 2 + 4) / 6,
  (-3 * t ** 3 + 3 * t ** 2 + 3 * t + 1) / 6,
  t ** 3 / 6,
];
const blend = (p: readonly Pair[], t: number): Pair => {
  const w = bases(t);
  return [0, 1].map((d) => w.reduce((sum, wi, i) => sum + wi * p[i][d], 0)) as unknown as Pair;
};

export default [
  {
    // Seed 1: P0 … P3 = (0, 4), (3, 1), (4, 4), (7, 0); B(0.5) = (1, 23, 23, 1)/48:
    // Q₃(0.5) = ((0 + 69 + 92 + 7)/48, (4 + 23 + 92 + 0)/48) = (3.5, 119/48) ≈ (3.5, 2.479).
    id: 'segment-point',
    seed: 1,
    prompt: ['Segment Q₃ blends P₀ … P₃', 'Q₃(0.5)', 'within 0.3'],
    answer: {
      point: blend(
        [
          [0, 4],
          [3, 1],
          [4, 4],
          [7, 0],
        ],
        0.5,
      ),
    },
  },
  {
    // Seed 42: knots 0, 1, 2, 4, 6, 7, 8, 10, 12, 14 and u = 8.5 in [u6, u7) = [8, 10).
    // Row 1: N(5,1) = (10 − 8.5)/(10 − 8) = 0.75, N(6,1) = (8.5 − 8)/(10 − 8) = 0.25.
    // Row 2: N(5,2) = (8.5 − 7)/(10 − 7)·0.75 + (12 − 8.5)/(12 − 8)·0.25 = 0.375 + 0.21875 = 0.59375.
    // Wrong (the two factors swapped): (3.5/4)·0.75 + (1.5/3)·0.25 = 0.78125.
    id: 'cox-de-boor',
    seed: 42,
    prompt: ['u0 … u9 = 0, 1, 2, 4, 6, 7, 8, 10, 12, 14', 'N(5,2) at u = 8.5', 'within 0.001'],
    answer: {
      numbers: [(1.5 / 3) * 0.75 + (3.5 / 4) * 0.25],
      wrong: [(3.5 / 4) * 0.75 + (1.5 / 3) * 0.25],
    },
  },
  {
    // Seed 1: P3 = (6, 1) on knots 0 … 10 (cubic). u4 = u5 = u6 = 5 leaves only N(3,3) = 1 at u = 5,
    // so P(5) = P3: drag u4 onto u5 (at 5), then u6 onto them (each snaps onto its neighbour).
    id: 'through-point',
    seed: 1,
    prompt: ['passes through P₃', 'within 0.15'],
    answer: {
      moves: [
        { figure: 'knots', handle: 'u4', to: [5, 0] },
        { figure: 'knots', handle: 'u6', to: [5, 0] },
      ],
    },
  },
] satisfies PracticeCase[];
