import { notesKey, notesSlip } from '../../kit/notes';

// Where the course notes write the lesson's things another way, or slip.

/** How the lesson's symbols read in the notes: (here, in the notes). */
export const NOTES_SYMBOLS: readonly (readonly [string, string])[] = [
  [
    'P0 … Pm: m + 1 control points, m ≥ 3',
    'x0 … xm in the lecture slides (“Example – a cubic B-spline”); p0, p1, … in the continuation notes',
  ],
  [
    'P(u): the whole curve (P(s) in the uniform cubic)',
    'the lecture slides write it only segment by segment, as xᵢ(u); the continuation notes write P(t) for a segment’s formula (their t counting segments, s here) and p(t) for a NURBS curve',
  ],
  [
    'Qi: the segment of P(i−3) … Pi, i = 3 … m',
    'cᵢ in the lecture slides (c3 … cm), each written there as xᵢ(u), of x(i−3) … xi; P(t) in the continuation notes, of p0 … p3',
  ],
  [
    'B0(t) … B3(t): the weights of a segment’s four points',
    'the continuation notes’ uniform cubic B-spline bases, the same four cubics; the columns of the slides’ matrix B',
  ],
  [
    'N(i,p): the basis function of Pᵢ over the whole curve',
    'not named in the notes; the B(k,n) of the “Splines” slides is a Bézier (Bernstein) blending function of degree n, not a B-spline basis function',
  ],
  [
    'knots u0 ≤ u1 ≤ …: parameter values where segments meet',
    'as in the continuation notes (“knots are equally spaced”); the lecture notes and the “Splines” slides say “knots” for the control points themselves',
  ],
  [
    'degree p, order p + 1 (the cubic: degree 3, order 4)',
    'as in the continuation notes (“degree is n, and order is n + 1”); the lecture slides and notes say “order” for the degree (“for order 3” of the cubic Bézier matrix)',
  ],
  [
    't: the slider, 0 … 1 along the whole curve; s = (m − 2)·t',
    'the continuation notes’ t, “changed when t becomes an integer”, is s here',
  ],
];

/** The lesson's key to the notes' symbols. */
export const notesSymbols = () => notesKey(NOTES_SYMBOLS);

/** The slides' closed spline, said kindly beside the lesson's three repeated points. */
export const CLOSED_SLIP = {
  written: 'that a closed spline has the same matrix B for all segments and x₀ = xₘ',
  correct:
    'The matrix is the same everywhere, but one repeated point does not close the curve: a segment reads four points, so closing it takes three, P(m+1) = P0, P(m+2) = P1 and P(m+3) = P2. With only the last point on the first, Pm = P0, the curve’s ends (P0 + 4P1 + P2)/6 and (P(m−2) + 4P(m−1) + Pm)/6 do not meet.',
} as const;

export const closedSlip = () => notesSlip('slides', CLOSED_SLIP.written, CLOSED_SLIP.correct);

/**
 * How the documents use “knots”, in their own words: the lecture notes for the
 * points where patches join and for the points a curve is made from, the
 * “Splines” slides for control points, the continuation notes for parameter
 * values (as this app). The lecture slides never use the word.
 */
export const KNOT_WORDS = {
  lectureJoin: 'each pair of adjacent knots is joined by a different curve',
  lectureControl: 'a small set of control points (knots)',
  lectureBezier: 'has four knots: P₀, P₁, P₂, P₃',
  splineSlides: 'user-specified control points (knots)',
  continuation: 'knots are equally spaced',
  continuationNurbs: 'non-uniform location of knots',
} as const;

/** What the notes say of a spline's continuity, in their own words. */
export const CONTINUITY_WORDS = {
  slides: 'cubic B-splines are C², or can be made to be less: C¹ or C⁰',
  continuation: 'splines of degree n can guarantee Cⁿ⁻¹ continuity',
  bezier: 'three control points are on a straight line, and the distance is the same',
} as const;
