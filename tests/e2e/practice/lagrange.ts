import type { PracticeCase } from './types';

// Five points at t = 0, 0.25, 0.5, 0.75, 1: Lₖ(t) = Π over j ≠ k of (t − tⱼ)/(tₖ − tⱼ),
// and P(t) = Σ Lₖ(t) Pₖ, one coordinate at a time.
const NODES = [0, 0.25, 0.5, 0.75, 1];
const weight = (k: number, t: number) =>
  NODES.reduce(
    (product, node, j) => (j === k ? product : (product * (t - node)) / (NODES[k] - node)),
    1,
  );
const polynomial = (points: readonly (readonly [number, number])[], t: number) =>
  [0, 1].map((d) => points.reduce((sum, p, k) => sum + weight(k, t) * p[d], 0)) as [number, number];

export default [
  {
    // Points (0, 0), (2, 2), (3, 0), (5, 2), (6, 2); at t = 0.4 the weights are
    // −0.0336, 0.3584, 0.8064, −0.1536, 0.0224, so
    // P(0.4) = (0.7168 + 2.4192 − 0.768 + 0.1344, 0.7168 − 0.3072 + 0.0448) = (2.5024, 0.4544).
    id: 'where',
    seed: 5,
    prompt: ['at t = 0, 0.25, 0.5, 0.75, 1', 'Where is P(0.4)?'],
    answer: {
      point: polynomial(
        [
          [0, 0],
          [2, 2],
          [3, 0],
          [5, 2],
          [6, 2],
        ],
        0.4,
      ),
    },
  },
  {
    // L₂(0.9) = (0.9)(0.65)(0.15)(−0.1) / ((0.5)(0.25)(−0.25)(−0.5)) = −0.008775 / 0.015625 = −0.5616.
    // Wrong: the sign dropped.
    id: 'weight',
    seed: 5,
    prompt: ['Compute L₂(0.9) to 3 decimals'],
    answer: { numbers: [weight(2, 0.9)], wrong: [0.5616] },
  },
  {
    // The goal (0, 0), (2, 2), (3, 0), (5, 2), (6, 2) gives P(0.4) = (2.5024, 0.4544), the
    // target (2.5, 0.45) to 2 decimals; P₃ opens at (5, 4), two above its place.
    id: 'steer',
    seed: 5,
    prompt: ['Drag P₃ alone', 'P(0.4) sits at (2.5, 0.45), within 0.1'],
    answer: { moves: [{ figure: 'curve', handle: 'p3', to: [5, 2] }] },
  },
] satisfies PracticeCase[];
