import type { PracticeCase } from './types';

// The patch P(u, v) = Σm Σn fm(u) fn(v) P(m,n) written out here (nothing
// imported from src/), with fk the cubic Bernstein functions.
// The patch figure is in space: its points here are x and y on the plane z = 0
// (the flat net lies there; the moved point of the join keeps its z, which is 0).
type Triple = readonly [number, number, number];
const bernstein = (t: number) => [(1 - t) ** 3, 3 * t * (1 - t) ** 2, 3 * t ** 2 * (1 - t), t ** 3];
const patch = (net: readonly (readonly Triple[])[], u: number, v: number) => {
  const [fu, fv] = [bernstein(u), bernstein(v)];
  return [0, 1, 2].map((d) =>
    net.reduce((sum, row, m) => sum + row.reduce((s, p, n) => s + fu[m] * fv[n] * p[d], 0), 0),
  );
};

/** Seed 1's flat net (rows m = 0 … 3, columns n = 0 … 3). */
const FLAT: Triple[][] = [
  [
    [0, -1, 0],
    [0, 4, 0],
    [1, 5, 0],
    [0, 10, 0],
  ],
  [
    [3, 1, 0],
    [3, 3, 0],
    [2, 6, 0],
    [2, 8, 0],
  ],
  [
    [6, -1, 0],
    [6, 4, 0],
    [5, 5, 0],
    [5, 9, 0],
  ],
  [
    [9, 1, 0],
    [8, 2, 0],
    [9, 6, 0],
    [10, 8, 0],
  ],
];

/** Seed 1's heights: 0 but at the inner points P₁,₁ = 2, P₁,₂ = 1, P₂,₁ = 2, P₂,₂ = 3. */
const RAISED: Triple[][] = [0, 1, 2, 3].map((m) =>
  [0, 1, 2, 3].map((n): Triple => [
    m,
    n,
    [
      [0, 0, 0, 0],
      [0, 2, 1, 0],
      [0, 2, 3, 0],
      [0, 0, 0, 0],
    ][m][n],
  ]),
);

const [x, y] = patch(FLAT, 0.75, 0.5);

export default [
  {
    // Seed 1: rows at v = ½ by (1, 3, 3, 1)/8: r0 … r3 = (3, 36)/8, (20, 36)/8, (44, 35)/8, (70, 33)/8;
    // at u = ¾ by (1, 9, 27, 27)/64: P(0.75, 0.5) = (3261, 2196)/512 ≈ (6.369, 4.289).
    id: 'patch-point',
    seed: 1,
    prompt: ['flat in the plane z = 0', 'P(0.75, 0.5)', 'within 0.3'],
    answer: { point: [x, y] },
  },
  {
    // Seed 1: f₁(¾) = 9/64, f₂(¾) = 27/64, f₁(0.4) = 0.432, f₂(0.4) = 0.288:
    // z = 9/64·(2·0.432 + 0.288) + 27/64·(2·0.432 + 3·0.288) = 0.162 + 0.729 = 0.891.
    // Wrong (u and v swapped): z(0.4, 0.75) = 0.30375 + 0.4455 = 0.74925.
    id: 'patch-height',
    seed: 1,
    prompt: [
      'P₁,₁ at z = 2, P₁,₂ at z = 1, P₂,₁ at z = 2, P₂,₂ at z = 3',
      'z(0.75, 0.4)',
      'within 0.001',
    ],
    answer: { numbers: [patch(RAISED, 0.75, 0.4)[2]], wrong: [patch(RAISED, 0.4, 0.75)[2]] },
  },
  {
    // Seed 1: P₂,₃ = (2, 3, 0) and P₃,₃ = Q₀,₃ = (3, 3, 0), so C¹ needs Q₁,₃ = 2P₃,₃ − P₂,₃ = (4, 3, 0);
    // it is posed at (4, 2.5, 0). Its handle is y3 (Q's rows 1 … 3 in order: Q₁,₃ is the fourth).
    id: 'smooth-join',
    seed: 1,
    prompt: ['Q₁,₀ … Q₁,₃', 'join C¹', 'within 0.1'],
    answer: { moves: [{ figure: 'patch', handle: 'y3', to: [2 * 3 - 2, 2 * 3 - 3] }] },
  },
] satisfies PracticeCase[];
