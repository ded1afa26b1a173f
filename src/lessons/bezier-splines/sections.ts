import { h } from '../../app/dom';
import { notesKey, notesSlip } from '../../kit/notes';
import { formula } from '../../render/formula';
import type { Part } from './state';

// The panel's text of each part: what a student reads beside the figure.

const link = (href: string, text: string) => h('a', { href }, text);

export function introductions(): Record<Part, HTMLElement> {
  return {
    why: h(
      'div',
      {},
      h('h2', {}, 'Why pieces'),
      h(
        'p',
        {},
        'One Bézier curve for many points has a degree as high as the number of points minus one, and every control point pulls on every part of it: move one and the whole curve moves (see ',
        link('#/bezier-properties', 'Bézier properties'),
        '). Low-degree pieces joined end to end fix both: each piece stays simple, and a point mainly moves the pieces near it. The question becomes how smoothly the pieces join.',
      ),
      notesSlip(
        'spline slides',
        'that “the curve fragments are always smoothly joined”',
        'Pieces that share an end point only meet (C⁰); they join smoothly only when the control points either side of the joint are chosen so (on one line through it for G¹, at equal distances for C¹), as the next scenes do. The continuity inspector shows a sharp corner between two Bézier pieces.',
      ),
    ),
    quadratic: h(
      'div',
      {},
      h('h2', {}, 'A C¹ quadratic spline through the points'),
      h(
        'p',
        {},
        'Piece i is the quadratic Bézier [pᵢ, bᵢ, pᵢ₊₁]. At pᵢ the left piece leaves along 2(pᵢ − bᵢ₋₁) and the right one along 2(bᵢ − pᵢ): they agree (C¹) exactly when pᵢ is the midpoint of bᵢ₋₁ and bᵢ. So b₀ is a free choice and every other bᵢ follows from it.',
      ),
      formula('b_{i} = 2p_{i} - b_{i-1},\\quad i = 1,\\dots,n-1', true),
      h(
        'p',
        { class: 'note' },
        'Drag b₀ (the diamond): the whole spline swings, to the very last piece. A change δ of b₀ becomes ±δ at every bᵢ, alternating in sign and never smaller — the reason for cubic pieces and a linear system.',
      ),
    ),
    system: h(
      'div',
      {},
      h('h2', {}, 'A C² cubic spline from a linear system'),
      h(
        'p',
        {},
        'Cubic pieces [c₃ᵢ, c₃ᵢ₊₁, c₃ᵢ₊₂, c₃ᵢ₊₃] through p₀ … pₙ have 3n + 1 control points. For four points A, D, G, J (the practical’s computeSplineC2) the unknowns are A … J: 4 interpolation, 2 C¹ and 2 C² equations are 8, and the natural ends (P″ = 0) give the last 2.',
      ),
      formula(
        '\\begin{aligned}&\\text{C}^1 \\text{ at } c_{3i}: & c_{3i-1} - 2c_{3i} + c_{3i+1} &= 0\\\\ &\\text{C}^2 \\text{ at } c_{3i}: & c_{3i-2} - 2c_{3i-1} + 2c_{3i+1} - c_{3i+2} &= 0\\\\ &\\text{natural ends:} & c_0 - 2c_1 + c_2 = c_{3n-2} - 2c_{3n-1} + c_{3n} &= 0\\end{aligned}',
        true,
      ),
      h(
        'p',
        {},
        'The solution is the natural cubic spline of the ',
        link('#/road', 'road lesson'),
        ', written as Bézier pieces: its tridiagonal system for the gradients Dᵢ is this system with the inner control points eliminated (c₃ᵢ₊₁ = pᵢ + Dᵢ/3).',
      ),
    ),
    grid: h(
      'div',
      {},
      h('h2', {}, 'C⁰, C¹ and C² side by side'),
      h(
        'p',
        {},
        'The practical’s figure: each dataset (rows) drawn as a C⁰ spline (straight pieces), a C¹ quadratic spline (b₀ the midpoint of p₀p₁) and a C² cubic spline (columns). Drag a point in any cell: the other cells of its row follow.',
      ),
      h(
        'p',
        { class: 'note' },
        'The C¹ column shows the quadratic spline’s weakness: b₀ on the chord makes the first piece straight, and that one choice at the start sets how every later piece bulges, to the end of the curve.',
      ),
    ),
    inspector: h(
      'div',
      {},
      h('h2', {}, 'A continuity inspector'),
      h(
        'p',
        {},
        'Drag any control point of the three cubic pieces (a joint carries its two neighbours). At each joint: C⁰ the pieces meet; G¹ the tangents point the same way (angle 0°); C¹ also equal length (ratio 1); G² also the same curvature; C² equal second derivatives too.',
      ),
      h(
        'p',
        { class: 'note' },
        'A control point on the joint makes a sharp corner, as fonts do: the velocity is zero there, so the derivatives “agree” (both zero) while the curve turns — only C⁰.',
      ),
    ),
    catmull: h(
      'div',
      {},
      h('h2', {}, 'Points and tangents, then Catmull-Rom'),
      h(
        'p',
        {},
        'A Hermite piece needs the two points and the two tangents; its Bézier control points are pᵢ + Tᵢ/3 and pᵢ₊₁ − Tᵢ₊₁/3. Catmull-Rom takes the tangents from the neighbours. A Hermite spline with tangents set by hand is C¹ too, but it is not a Catmull-Rom spline: its tangents are free choices, not (pᵢ₊₁ − pᵢ₋₁)/2.',
      ),
      formula('T_i = \\tfrac{1}{2}(p_{i+1} - p_{i-1}),\\qquad T_0 = T_n = 0', true),
      h(
        'p',
        {},
        'With knot gaps Δᵢ = |pᵢ₊₁ − pᵢ|^α, α = 0 is uniform, ½ centripetal, 1 chordal. Centripetal Catmull-Rom never forms a cusp or a loop inside a piece (Yuksel, Schaefer & Keyser 2011); the uniform one does at this hairpin.',
      ),
    ),
    worked: h(
      'div',
      {},
      h('h2', {}, 'computeSplineC1 and computeSplineC2 by hand'),
      h(
        'p',
        {},
        'The practical’s two functions, worked on paper through the same points (the practical calls four points A, D, G, J; these coordinates are the lesson’s own). C¹: b₀ is chosen, and each further bᵢ is the mirror image of bᵢ₋₁ through pᵢ. C²: keep B unknown, walk the practical’s equations from the start (each gives the next control point in terms of B), and the natural end, the last equation, fixes B.',
      ),
      formula(
        '\\begin{aligned}\\text{C}^1:&\\ b_i = 2p_i - b_{i-1}\\\\ \\text{C}^2:&\\ C = 2B - A,\\ E = 2D - C,\\ F = B - 2C + 2E,\\ \\dots,\\ H - 2I + J = 0\\end{aligned}',
        true,
      ),
      h(
        'p',
        { class: 'note' },
        'Each function returns its control points in order, one row each: computeSplineC1 2n + 1 rows (p₀, b₀, p₁, b₁, …, pₙ), computeSplineC2 3n + 1 rows (c₀ … c₃ₙ, a point every third). In the figure each point carries its row’s name: p₀, b₀, p₁, … for computeSplineC1, the practical’s letters A, B, C, … for computeSplineC2.',
      ),
      notesSlip(
        'practical',
        'the first derivative as ẋ = d²/dt² x',
        'The first derivative is ẋ = d/dt x; for a quadratic piece it is 2(b₁ − b₀)B₀¹(t) + 2(b₂ − b₁)B₁¹(t), a Bézier curve of degree 1, which is where the C¹ condition comes from.',
      ),
      notesKey([
        [
          'bᵢ',
          'b₁ⁱ in the practical: the inner control point of piece i (the upper index is the piece)',
        ],
        ['c₀ … c₃ₙ', 'A … J in the practical, for four points'],
      ]),
    ),
    degree: h(
      'div',
      {},
      h('h2', {}, 'Degree d, continuity up to Cᵈ⁻¹'),
      h(
        'p',
        {},
        'The continuation notes: “splines of degree n can guarantee Cⁿ⁻¹ continuity”. Here n counts the pieces, so the degree is d. A piece of degree d has d + 1 coefficients, or d + 1 control points: its order is d + 1 (the continuation notes: “degree is n, and order is n + 1”). That order is a count of coefficients; the order of continuity, the k of Cᵏ, is another thing.',
      ),
      formula(
        '\\underbrace{dn + 1}_{\\text{control points}} - \\underbrace{(n + 1)}_{\\text{points}} - \\underbrace{(d - 1)(n - 1)}_{\\text{C}^1 \\dots \\text{C}^{d-1}} = d - 1',
        true,
      ),
      h(
        'p',
        {},
        'n pieces of degree d share their joints: dn + 1 control points. The points fix n + 1 of them, and C¹ … Cᵈ⁻¹ at the n − 1 inner joints give d − 1 equations each. d − 1 are left to choose: none for straight pieces, b₀ for quadratics (the practical’s computeSplineC1), the two natural ends for cubics (computeSplineC2).',
      ),
      h(
        'p',
        { class: 'note' },
        'The continuation notes count the cubic case piece by piece: 4n control points and 4n − 2 equations (2n end points, n − 1 tangents, n − 1 second derivatives). The practical shares the joints: 3n + 1 control points and 3n − 1 equations. Both leave 2. And Cᵈ is too much: two pieces of degree d with the same value and d derivatives at a joint are one polynomial, the second the first continued.',
      ),
      notesKey([
        [
          'd (the degree)',
          'n in the continuation notes’ “degree n, Cⁿ⁻¹”; here n counts the pieces',
        ],
      ]),
    ),
  };
}
