import { notesKey, notesSlip } from '../../kit/notes';

// Where the course notes write the construction another way, or slip.

/** The lecture notes' pseudocode (Bézier curves, after Figure 5), as they print it. */
export const LECTURE_PSEUDOCODE = `Point casteljau (knots P[ ] ; int k, int r, float μ)
begin
  if (r > 0)
    then casteljau = (1 − μ) * casteljau(P, k, r − 1, μ) + μ * casteljau(P, k + 1, r − 1, μ)
    else casteljau = (1 − μ) * P[k] + μ * P[k + 1]
  end

void drawCurve (knots knotArray[], int L)
for j=0 to L
begin
  let μ = j/L
  point = casteljau(knotArray, 0, 3, μ)
  plot(point.x, point.y)
end`;

/**
 * The recursion's base case already mixes two knots, so casteljau(P, k, r, μ)
 * is P_{r+1,k}: the call with r = 3 is level 4, which reads P[4].
 */
export const RECURSION_SLIP = {
  written:
    'casteljau(knotArray, 0, 3, μ) for the four knots of a cubic, while the branch for r = 0 already mixes P[k] and P[k + 1]',
  correct:
    'With that branch casteljau(P, k, r, μ) is point k of level r + 1, so r = 3 asks for P[4], a fifth knot. For the knots P[0] … P[3] call casteljau(P, 0, 2, μ), or let r = 0 return P[k]: then casteljau(P, 0, 3, μ) is P₃,₀ = P(μ), as in the loops above.',
} as const;

export const recursionSlip = () =>
  notesSlip('lecture', RECURSION_SLIP.written, RECURSION_SLIP.correct);

/** How the lesson's symbols read in the notes: (here, in the notes). */
export const NOTES_SYMBOLS: readonly (readonly [string, string])[] = [
  [
    't',
    'μ in the lecture notes, u in the lecture slides, t in the continuation notes and the practical (TP2)',
  ],
  [
    'Pᵣ,ᵢ: point i of level r',
    'the same in the lecture notes (P₀,ᵢ are the knots); xᵢ⁽ʳ⁾(t) in the continuation notes; a₀, a₁, a₂ and b₀, b₁ for levels 1 and 2 in the lecture slides',
  ],
  [
    'the loops over r and i',
    'a recursive function in the lecture notes, casteljau(P, k, r, μ); the continuation notes list the levels xᵢ⁽¹⁾, xᵢ⁽²⁾, xᵢ⁽³⁾ in this order; the practical (TP2) leaves its code to TP2.h',
  ],
  [
    'W(n, i, t)',
    'W(N, i, μ) in the lecture notes, fₙ(u) in the lecture slides, Bᵢ(t) in the continuation notes',
  ],
];

export const notesSymbols = () => notesKey(NOTES_SYMBOLS);
