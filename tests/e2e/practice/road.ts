import type { PracticeCase } from './types';

// The Hermite road at the middle of segment i, with the parabola gradients
// Dᵢ = (Pᵢ₊₁ − Pᵢ₋₁)/2: P(½) = ½(Pᵢ + Pᵢ₊₁) + ⅛(Dᵢ − Dᵢ₊₁) (the Hermite
// weights at p = ½ are ½, ⅛, ½, −⅛).
type Pair = readonly [number, number];
const hermiteHalfway = (before: Pair, from: Pair, to: Pair, after: Pair): Pair => {
  const d0 = [0, 1].map((k) => (to[k] - before[k]) / 2);
  const d1 = [0, 1].map((k) => (after[k] - from[k]) / 2);
  return [0, 1].map((k) => (from[k] + to[k]) / 2 + (d0[k] - d1[k]) / 8) as unknown as Pair;
};

export default [
  {
    // Villages P₀ (0, 40), P₁ (26, 48), P₂ (42, 4), P₃ (58, 12), P₄ (80, 48); p̄ = 2.5 is segment 2 at p = ½.
    // D₂ = (P₃ − P₁)/2 = (16, −18), D₃ = (P₄ − P₂)/2 = (19, 22):
    // P = (50, 8) + ⅛(−3, −40) = (49.625, 3).
    id: 'hermite-midpoint',
    seed: 1,
    prompt: ['P₀ (0, 40)', 'P₂ (42, 4)', 'P₄ (80, 48)', 'p̄ = 2.5'],
    answer: { point: hermiteHalfway([26, 48], [42, 4], [58, 12], [80, 48]) },
  },
  {
    // x = 0, 14, 46, 56. Row 0 [2 1 | 3·14 = 42]: Γ₀ = 42/2 = 21.
    // Row 1 [1 4 1 | 3·46 = 138]: Γ₁ = (138 − 1·21)/(4 − 1·½) = 117/3.5 = 33.43.
    // Wrong: the pivot taken as 4, Γ₁ = 117/4 = 29.25.
    id: 'thomas-sweep',
    seed: 1,
    prompt: ['x = 0, 14, 46, 56', 'Γ₀ and Γ₁', 'to 2 decimals'],
    answer: { numbers: [21, 33.43], wrong: [21, 29.25] },
  },
  {
    // P₀ (0, 6), P₁ (14, 22), P₂ (46, 40), P₃ (56, 34); D₃ = (−36, −24) asked.
    // Back from the end: B₂ = P₃ − D₃/2 = (56 + 18, 34 + 12) = (74, 46),
    // B₁ = 2P₂ − B₂ = (92 − 74, 80 − 46) = (18, 34), B₀ = 2P₁ − B₁ = (28 − 18, 44 − 34) = (10, 10).
    id: 'quadratic-arrival',
    seed: 1,
    prompt: ['P₁ (14, 22)', 'P₃ (56, 34)', 'D₃ = (−36, −24)'],
    answer: { moves: [{ figure: 'map', handle: 'q', to: [10, 10] }] },
  },
] satisfies PracticeCase[];
