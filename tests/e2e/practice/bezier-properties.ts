import type { PracticeCase } from './types';

export default [
  {
    // Only P1 moves, so P(t) moves by W(5, 1, t)·ΔP1 = 5t(1 − t)⁴·ΔP1, largest at t = 1/5:
    // 5·(1/5)·(4/5)⁴ = 0.4096 of the move, times 2 = 0.8192.
    // Wrong: the whole move, 2 (no local control, but no full follow either).
    id: 'local-move',
    seed: 1,
    prompt: ['If P₁ of this curve of degree 5 moves down by 2', 'to 2 decimals'],
    answer: { numbers: [0.8192], wrong: [2] },
  },
  {
    // (0, 0), (5, 3), (1, 3) and P3 = P0 = (0, 0) at t = 0.5: weights 1/8, 3/8, 3/8, 1/8;
    // P(0.5) = ((3·5 + 3·1)/8, (3·3 + 3·3)/8) = (2.25, 2.25).
    id: 'closed-point',
    seed: 7,
    prompt: ['P₃ = P₀', 'where is P(0.5)?', 'within 0.25'],
    answer: { point: [2.25, 2.25] },
  },
  {
    // (3, 0), (5, 2), (2, 4), (1, 0), closed by P4 = P0: P′(0) = 4(P1 − P0) = (8, 8), P′(1) = 4(P0 − P3) = (8, 0).
    // C¹ needs P1 − P0 = P0 − P3 = (2, 0): P1 = (5, 0), and then both are (8, 0).
    id: 'closed-smooth',
    seed: 5,
    prompt: ['Move only P₁', 'C¹ at P₀ = P₄', 'within 0.4'],
    answer: { moves: [{ figure: 'experiment', handle: 'p1', to: [5, 0] }] },
  },
  {
    // P0 = (0, 1), P1 = (0, 3), P2 = (3, 2), P3 = (6, 0) turns one way only. With P2 at (2, 1):
    // a1 = 3(P1 − P0) = (0, 6), a2 = 3(P2 − 2P1 + P0) = (6, −12), a3 = P3 − 3P2 + 3P1 − P0 = (0, 5),
    // and P′ × P″ = 2(a1×a2) + 6(a1×a3)t + 6(a2×a3)t² = −72 + 180t² changes sign at t = √0.4 = 0.63.
    id: 'inflection',
    seed: 4,
    prompt: ['Move only P₂', 'turns both ways'],
    answer: { moves: [{ figure: 'experiment', handle: 'p2', to: [2, 1] }] },
  },
] satisfies PracticeCase[];
