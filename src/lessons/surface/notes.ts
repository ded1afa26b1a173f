import { notesKey, notesSlip } from '../../kit/notes';

// Where the course notes write the patch another way, or slip.

/** How the lesson's symbols read in the notes: (here, in the notes). */
export const NOTES_SYMBOLS: readonly (readonly [string, string])[] = [
  [
    'Pₘ,ₙ: m runs along u, n along v',
    'xₘ,ₙ in the lecture slides; pᵢⱼ (and xᵢⱼ for its x coordinates) in the continuation notes',
  ],
  [
    'P(u, v): the point of the patch',
    'x(u, v) in the lecture slides; p(u, v) in the continuation notes, whose x(u, v) is its x coordinate',
  ],
  [
    'fₘ(u): the cubic Bernstein polynomials',
    'fₙ(u) in the lecture slides; Bᵢ(u) in the continuation notes; B(k,n)(u) in the “Splines” slides',
  ],
  [
    'x(u, v) = U·M·B·Mᵀ·Vᵀ: one coordinate of P(u, v) (or y, z), B that coordinate of the net',
    'x(u, v) = U·M·B·Mᵀ·Vᵀ for the whole point in the lecture slides, B the net’s points; M(u)ᵀ·B_Bezierᵀ·Gˣ·B_Bezier·M(v) for the x coordinate in the continuation notes',
  ],
  [
    'Qₘ,ₙ: the second patch’s net, beside Pₘ,ₙ (Q₀,ₙ = P₃,ₙ where they join)',
    'not in the notes, which join no two patches',
  ],
];

/** The lesson's key to the notes' symbols. */
export const notesSymbols = () => notesKey(NOTES_SYMBOLS);

/** The slides' “for 0 ≤ v ≤ 1” where the curve through the four row points runs in u. */
export const ROWS_SLIP = {
  written:
    'the curve through the four points at the chosen v as built “for 0 ≤ v ≤ 1” (“Then construct a Bezier curve out of these for 0 ≤ v ≤ 1”)',
  correct:
    'What is meant is u: v was chosen just before and stays fixed, and the new Bézier curve Σ fₘ(u) rₘ(v) runs in u, for 0 ≤ u ≤ 1; choosing u then picks the point, as the slides go on to say. (Their first “for 0 ≤ v ≤ 1”, for the four row curves, is right.)',
} as const;

export const rowsSlip = () => notesSlip('slides', ROWS_SLIP.written, ROWS_SLIP.correct);
