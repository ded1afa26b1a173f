import { h, setText } from '../../../app/dom';
import { notesSlip } from '../../../kit/notes';
import { LiveFormula, SLOT } from '../../../render/formula';
import { texT } from '../../../kit/format';
import { type ExperimentPanel, coords, slotPoint } from '../experimentPanel';
import { smallNumber } from '../../../kit/format';
import type { ModelOf } from '../model';

const P = slotPoint();

/** The derivative's control points, as many rows as it has (the shape changes with the degree). */
const controlsShape = (n: number) =>
  `\\begin{aligned}${Array.from(
    { length: n },
    (_, i) => `${n}(P_{${i + 1}} - P_{${i}}) &= ${P}`,
  ).join('\\\\ ')}\\end{aligned}`;
const AT_T = `P'(${SLOT}) = ${P}`;

export const hodographPanel: ExperimentPanel<ModelOf<'hodograph'>> = {
  number: 1,
  title: 'The derivative is a Bézier curve (the hodograph)',
  sentence:
    'The derivative P′(t) of a Bézier curve of degree n is a Bézier curve of degree n − 1 whose control points are the legs of the polygon times n, n(Pᵢ₊₁ − Pᵢ). Drawn from one point O it is the hodograph: its ends are the end tangents of property 1, and at every t it gives the tangent P′(t).',
  build() {
    const controls = new LiveFormula(true);
    const atT = new LiveFormula(true);
    const agreement = h('p', {});
    const nodes = [
      h('p', {}, h('strong', {}, 'Control points of the derivative')),
      controls.element,
      atT.element,
      agreement,
      h(
        'p',
        { class: 'note' },
        'The lecture notes differentiate the cubic (“The gradients at the spline ends”) to P′(μ) = 3(P1 − P0)(1 − μ)² + 6(P2 − P1)μ(1 − μ) + 3(P3 − P2)μ²: this curve, with 6(P2 − P1) = 3(P2 − P1) times the 2 of W(2, 1, μ) = 2μ(1 − μ).',
      ),
      notesSlip(
        'practical',
        'that the quadratic’s first derivative ẋ “is also a Bézier curve, of degree n − 1”, writing ẋ as d²/dt² x',
        'The first derivative is ẋ = dx/dt; d²x/dt² is the second.',
      ),
    ];
    return {
      update(m) {
        controls.set(
          controlsShape(m.n),
          m.hodograph.flatMap((v) => coords(v, 3)),
        );
        atT.set(AT_T, [texT(m.state.t), ...coords(m.derivative, 4)]);
        setText(
          agreement,
          `From the derivative curve, from the construction’s last edge ${m.n}(P${m.n - 1},1 − P${m.n - 1},0) and from the tangent computed apart, P′(t) agrees to ${smallNumber(m.disagreement)}.`,
        );
        return nodes;
      },
    };
  },
};
