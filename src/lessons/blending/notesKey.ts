import { notesSlip } from '../../kit/notes';

/**
 * The lesson's symbols and how the course's other documents write them. The
 * lesson follows the lecture notes (μ, Pᵢ, W(N, i, μ)) throughout.
 */
export const NOTES_KEY: readonly (readonly [string, string])[] = [
  ['Pᵢ', 'xₙ in the lecture slides, xᵢ in the continuation notes'],
  ['W(N, i, μ)', 'fₙ(u) in the lecture slides, Bᵢ(t) in the continuation notes'],
  ['P(μ) = U M P', 'x(u) = U M_Bezier X in the lecture slides'],
  [
    'D₀, D₃: the gradients at P₀ and P₃ (Hermite), as in the Hermite lesson',
    'P′₀, P′₁ in the lecture notes (equations 6 and 7); Dᵢ in the lecture slides; x′₀, x′₁ in the continuation notes',
  ],
];

/**
 * The “Splines” slides give the two words each other's meaning; the lecture
 * slides (“interpolating splines, because they actually go through the
 * points”) and the lesson use them the usual way round.
 */
export const WORDS_SLIP = {
  written:
    'that spline curves can “interpolate control points (the curve does not have to pass through them)” or “approximate control points (the curve passes through the points)”',
  correct:
    'The two explanations have swapped places: an interpolating curve passes through its points, as the lecture slides say of the road through the villages (“they actually go through the points”); an approximating curve’s control points shape it but need not lie on it, as the Bézier curve’s inner points do not.',
} as const;

/** The slip, said kindly beside the interpolating or approximating scene. */
export const wordsSlip = () => notesSlip('spline slides', WORDS_SLIP.written, WORDS_SLIP.correct);
