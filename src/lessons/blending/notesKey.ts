/**
 * The lesson's symbols and how the course's other documents write them. The
 * lesson follows the lecture notes (μ, Pᵢ, W(N, i, μ)) throughout.
 */
export const NOTES_KEY: readonly (readonly [string, string])[] = [
  ['μ', 'u in the lecture slides; t in the practical (TP2) and the continuation notes'],
  ['Pᵢ', 'xₙ in the lecture slides, xᵢ in the continuation notes'],
  ['W(N, i, μ)', 'fₙ(u) in the lecture slides, Bᵢ(t) in the continuation notes'],
  ['P(μ) = U M P', 'x(u) = U M_Bezier X in the lecture slides'],
  ['P′₀, P′₃ (Hermite)', 'x′₀, x′₁ in the continuation notes'],
];
