import type { PracticeCase } from './types';

// The cubic's derivatives and its signed curvature written out here (nothing
// imported from src/), so the answers stand on their own:
// P′(t) = 3[(1 − t)²(P1 − P0) + 2t(1 − t)(P2 − P1) + t²(P3 − P2)],
// P″(t) = 6[(1 − t)(P2 − 2P1 + P0) + t(P3 − 2P2 + P1)], κ = (x′y″ − y′x″)/|P′|³.
type Pair = readonly [number, number];
const cubic = (p: readonly Pair[], t: number) => {
  const s = 1 - t;
  const at = (d: number) =>
    s ** 3 * p[0][d] + 3 * t * s ** 2 * p[1][d] + 3 * t ** 2 * s * p[2][d] + t ** 3 * p[3][d];
  const first = (d: number) =>
    3 *
    (s ** 2 * (p[1][d] - p[0][d]) + 2 * t * s * (p[2][d] - p[1][d]) + t ** 2 * (p[3][d] - p[2][d]));
  const second = (d: number) =>
    6 * (s * (p[2][d] - 2 * p[1][d] + p[0][d]) + t * (p[3][d] - 2 * p[2][d] + p[1][d]));
  const speed = Math.hypot(first(0), first(1));
  const kappa = (first(0) * second(1) - first(1) * second(0)) / speed ** 3;
  // The centre of the osculating circle: P + (1/κ)·(T turned left), T = P′/|P′|.
  const centre: Pair = [at(0) - first(1) / speed / kappa, at(1) + first(0) / speed / kappa];
  return { kappa, centre };
};

export default [
  {
    // Seed 1: P0 … P3 = (1, 2), (1, 5), (4, 5), (5, 2), t = 0.5. P(½) = (21, 34)/8 = (2.625, 4.25),
    // P′ = (5.25, 0), P″ = (3, −18): κ = −94.5/5.25³ = −32/49, so R = 1.53125 below P:
    // centre (2.625, 2.71875).
    id: 'circle-centre',
    seed: 1,
    prompt: ['osculating circle at P(0.5)', 'within 0.2'],
    answer: {
      point: cubic(
        [
          [1, 2],
          [1, 5],
          [4, 5],
          [5, 2],
        ],
        0.5,
      ).centre,
    },
  },
  {
    // Seed 2: P′(1) = 3(P3 − P2) = (3, 12), P″(1) = 6(P3 − 2P2 + P1) = (−18, 18):
    // κ(1) = (3·18 + 12·18)/153^{3/2} = 270/1892.5 ≈ 0.1427.
    // Wrong (t and 1 − t swapped): κ(0) = (2/3)·((0, −5) × (4, 1))/5³ = (2/3)·20/125 ≈ 0.1067.
    id: 'curvature-value',
    seed: 2,
    prompt: ['P₀ = (1, 1), P₁ = (1, −4), P₂ = (5, −3), P₃ = (6, 1)', 'κ at t = 1', 'within 0.001'],
    answer: {
      numbers: [270 / 153 ** 1.5],
      wrong: [
        cubic(
          [
            [1, 1],
            [1, -4],
            [5, -3],
            [6, 1],
          ],
          0,
        ).kappa,
      ],
    },
  },
  {
    // Seed 1: P0 … P6 = (0, 4), (3, 5), (4, 3), (6, 3), (8, 3), (10, 6), (12, 5); P2, P3, P4 on y = 3.
    // κ before P3 = (2/3)·((1, −2) × (2, 0))/2³ = 1/3; after = (2/3)·((2, 0) × (2, 3))/2³ = 1/2.
    // P5 at the height of P1 over the line (2 above it) gives (2/3)·((2, 0) × (2, 2))/8 = 1/3.
    id: 'smooth-join',
    seed: 1,
    prompt: ['Move P₅', 'within 0.03'],
    answer: { moves: [{ figure: 'curve', handle: 'p5', to: [10, 5] }] },
  },
] satisfies PracticeCase[];
