import type { Part } from './state';
import { capital, gestures } from '../../kit/gestures';
import { AGREE } from './continuityGeometry';
import { CONTINUITY_WORDS, KNOT_WORDS } from './notes';

/** The panel's words for each part of the lesson: a heading and what to look at. */
export const TEXTS: Record<Part, { title: string; text: string }> = {
  uniform: {
    title: 'The uniform cubic B-spline',
    text:
      'm + 1 control points P0 … Pm (m ≥ 3) give m − 2 cubic segments Q3 … Qm. Segment Qi blends the four points P(i−3) … Pi with the matrix below, at its local parameter t ∈ [0, 1]: the four weights are the columns of the matrix, the bases B0(t) = (1 − t)³/6, B1(t) = (3t³ − 6t² + 4)/6, B2(t) = (−3t³ + 3t² + 3t + 1)/6 and B3(t) = t³/6. They are never negative and sum to 1, so the curve follows the polygon without passing through its points, and neighbouring segments join with C² continuity. The slider t runs along the whole curve P(s): s = (m − 2)·t counts segments, Qi being s from i − 3 to i − 2. ' +
      `${capital(gestures().point)} a segment (or Tab to its button) to see its four points; ${gestures().point} a point to see the segments it moves.`,
  },
  closed: {
    title: 'The closed uniform B-spline',
    text: 'Use the first three points again after the last: P(m+1) = P0, P(m+2) = P1, P(m+3) = P2. Every segment reads four points, so three repeated points are what closing takes: the same matrix then gives m + 1 segments, one for each point, and the curve closes on itself with C² continuity everywhere — there is no special end.',
  },
  local: {
    title: 'Local control',
    text: 'A control point of the cubic B-spline acts on four segments only: move it, and the rest of the curve does not change at all (the changed part is highlighted against the curve before). The Bézier curve through the same points changes along its whole length, because every Bernstein polynomial is non-zero on all of [0, 1]. The plot of the basis functions shows why: each B-spline basis function is zero outside four segments.',
  },
  convert: {
    title: 'B-spline ↔ Bézier, segment by segment',
    text: 'Each segment is a cubic, so it is also a Bézier curve: its four B-spline points, multiplied by the B-spline matrix and then by the inverse of the Bézier matrix, give its four Bézier points, and the inverse product gives them back. The end point of a segment, (P(i−1) + 4Pi + P(i+1))/6, is shared with the next one.',
  },
  properties: {
    title: 'Properties',
    text: 'Convex hull: each segment stays in the convex hull of its four control points (narrower than the hull of all of them). Variation diminishing: drag the line by its two square handles; it never crosses the curve more often than the polygon. Affine invariance: mapping the control points by an affine map A and building the curve gives the mapped curve (the rings are mapped curve points).',
  },
  knots: {
    title: 'Knots and the Cox–de Boor recursion',
    text: 'In general a B-spline of degree p — of order p + 1: the cubic has degree 3 and order 4 — has m + 1 control points P0 … Pm and a knot vector u₀ ≤ u₁ ≤ … ≤ uₘ₊ₚ₊₁ of m + p + 2 numbers. Its basis functions come from the Cox–de Boor recursion, row by row: N(i,0) is 1 on [uᵢ, uᵢ₊₁) and 0 elsewhere, and each N(i,r) blends N(i,r−1) and N(i+1,r−1). On equally spaced knots every span gets the same pieces in its local t, and row 3 derives the uniform cubic bases B0(t) … B3(t) of the matrix form. The curve P(u) lives on [uₚ, uₘ₊₁] (the strip’s thick part). Drag the knots on the strip; drop one on another to repeat it.',
  },
  clamped: {
    title: 'Clamped ends',
    text: 'With p + 1 equal knots at each end, only N(0,p) is non-zero at the start and only N(m,p) at the end: the curve starts at P0 and ends at Pm, tangent to the polygon there. This is how “open” splines interpolate their end control points, as the slides say the matrices can be modified at the curve ends to do.',
  },
  repeated: {
    title: 'Repeated knots',
    text: 'A knot of multiplicity k lowers the continuity there from Cᵖ⁻¹ to Cᵖ⁻ᵏ. With k = p the curve is only C⁰ and passes through a control point, with a kink; with k = p + 1 it breaks apart. Drag the stacked knots apart (right and left pick different ones) to smooth the curve again.',
  },
  nurbs: {
    title: 'NURBS: a weight per control point',
    text: 'A rational B-spline gives each control point a weight wi: P(u) = Σ wi Ni(u) Pi / Σ wi Ni(u). With every weight 1 it is the plain B-spline (dashed). Raising a weight pulls the curve towards that point; lowering it lets the curve go. Change the weights with the sliders.',
  },
  circle: {
    title: 'The exact circle',
    text: 'No polynomial curve is a circle, but a rational quadratic is: nine points on the square around the circle, weight 1 at the edge midpoints and √2/2 at the corners, knots 0,0,0, ¼,¼, ½,½, ¾,¾, 1,1,1 — four quarter arcs, each a rational quadratic Bézier curve. The dots are sampled curve points: they lie on the circle to rounding.',
  },
  projective: {
    title: 'A projective map keeps the curve',
    text: 'Map the control points with a perspective map H and multiply each weight by the new homogeneous coordinate w′ = h20 x + h21 y + h22: the NURBS of the new points and weights is exactly the image of the curve (the rings are mapped curve points). Keeping the old weights, as a plain B-spline must, gives a different curve (dashed).',
  },
  meanings: {
    title: 'Two meanings of “knots”',
    text:
      `The course’s documents use the word for two different things. In the continuation notes, as in this app, a knot is a parameter value: the knot vector u0 ≤ u1 ≤ … on the strip (“${KNOT_WORDS.continuation}” in a uniform B-spline, NURBS allow “${KNOT_WORDS.continuationNurbs}”). The curve’s points at those values, P(uj), are where its pieces join. ` +
      `The lecture notes call knots the points a spline is made from, “${KNOT_WORDS.lectureControl}”: their spline patches join at them (“${KNOT_WORDS.lectureJoin}”), and a cubic Bézier curve “${KNOT_WORDS.lectureBezier}”, its control points. The “Splines” slides speak of “${KNOT_WORDS.splineSlides}”. ` +
      'The lecture slides do not use the word: their road’s pieces meet at parameter values p̄i, “xi(p̄i) = xi+1(p̄i)”, knots in the first sense. ' +
      'On a B-spline the two are different points, except where the knots make one the other: at clamped ends, or at a knot repeated p times. Drag the knots on the strip: the joins slide along the curve while the control points stay.',
  },
  continuity: {
    title: 'Degree p ⇒ Cᵖ⁻¹',
    text:
      `Between two knots a B-spline of degree p is one polynomial of degree p. At a simple knot the pieces either side share the point and the derivatives up to the (p − 1)th: the curve is Cᵖ⁻¹ there; a knot of multiplicity k lowers that to Cᵖ⁻ᵏ, and k = p leaves C⁰, through a control point. The steps draw the same control points with degree 1, 2 and 3 on uniform knots, then the cubic with a second and a third knot stacked on the watched one; at each, the piece before the knot and the piece after it are each the polynomial through p + 1 of their own points, differentiated at the knot, and two sides count as equal within ${AGREE} of their size. ` +
      `The lecture slides say it of the cubic: “${CONTINUITY_WORDS.slides}”. ` +
      `The continuation notes say it of any spline, “${CONTINUITY_WORDS.continuation}” (their n is the degree p), and show joined cubic Bézier curves reaching C¹ only where their control points are placed for it, when “${CONTINUITY_WORDS.bezier}”, whereas a B-spline is Cᵖ⁻¹ at every simple knot wherever its control points are.`,
  },
};
