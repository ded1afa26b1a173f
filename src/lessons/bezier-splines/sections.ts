import { h } from '../../app/dom';
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
  };
}
