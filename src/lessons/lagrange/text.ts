import { words } from '../../kit/format';

// The panel's sentences that make a claim about the maths, kept apart from the
// DOM so a unit test can hold each claim against src/math.

/**
 * How the continuation notes state Lₖ's defining property, and the property
 * itself: "Lₖ(t) is 1 if k = i" names no tᵢ (a slip; read Lₖ(tᵢ)).
 */
export const BASIS_SLIP = {
  written: '“Lₖ(t) is 1 if k = i, or it is 0 otherwise”, with t where the node tᵢ belongs',
  correct:
    'Lₖ is 1 or 0 at the nodes: Lₖ(tᵢ) = 1 if k = i and Lₖ(tᵢ) = 0 if k ≠ i. Between the nodes Lₖ(t) takes other values, some of them negative.',
} as const;

/** The lesson's symbols and how the notes write them. */
export const NOTES_KEY: readonly (readonly [string, string])[] = [
  ['Pₖ', 'xₖ in the continuation notes, which interpolate one coordinate x(t) at a time'],
  ['tₖ', 'tₖ in the continuation notes, from t₀ = 0 to tₙ = 1'],
  ['Lₖ(t)', 'Lₖ(t) in the continuation notes'],
];

/** Runge's phenomenon, and what a spline does instead, with the largest Σ|Lₖ(t)| of these points. */
export function rungeText(lebesgue: { value: number; t: number }): string {
  return [
    `With many points the weights swing far beyond 0 and 1 near the ends. Here Σ|Lₖ(t)| reaches ${words(lebesgue.value)} at t = ${words(lebesgue.t)}: moving the points by 0.01 can move the curve by up to ${words(lebesgue.value * 0.01)}.`,
    'Try the Runge scene (eleven equally spaced points on a bump): the polynomial wiggles ever wider between them towards the ends, while a natural cubic spline through the same points stays calm, because each of its pieces is only a cubic. That is the reason for splines.',
    'The natural spline is not local, though: its gradients D₀ … Dₙ solve one system for all the points together, so moving one point changes every gradient and every piece, if only a little far away (the scene “Runge vs a cubic spline” shows it at its last step). Local control, where a point moves only the pieces near it, is what piecewise Bézier curves and B-splines give.',
  ].join(' ');
}
