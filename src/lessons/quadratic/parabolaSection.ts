import { fmt, h, setChildren, setText } from '../../app/dom';
import { LiveFormula, SLOT, texNumber } from '../../render/formula';
import type { QuadraticModel } from './model';

/** Up to three decimals, trailing zeros dropped: for the matrix of the system. */
const texShort = (v: number) => fmt(Number(v.toFixed(3)), 3).replace(/\.?0+$/, '');

/** The three equations y_i = a0 + a1 x_i + a2 x_i² as a matrix: one shape, nine numbers. */
const SYSTEM = `\\begin{pmatrix}${[0, 1, 2].map(() => `1 & ${SLOT} & ${SLOT}`).join('\\\\')}\\end{pmatrix}\\begin{pmatrix}a_0\\\\a_1\\\\a_2\\end{pmatrix} = \\begin{pmatrix}${[SLOT, SLOT, SLOT].join('\\\\')}\\end{pmatrix}`;

/** y = a2 x² ± a1 x ± a0: the signs are part of the shape, the sizes are numbers. */
const sign = (v: number) => (v < 0 ? '-' : '+');
const equation = (a1: number, a0: number) =>
  `y = ${SLOT}\\,x^2 ${sign(a1)} ${SLOT}\\,x ${sign(a0)} ${SLOT}`;

/** "The parabola y(x)": the system with the numbers, its solution, or why there is none. */
export function parabolaSection() {
  const warning = h('p', { class: 'warning', role: 'note' });
  const system = new LiveFormula(true);
  const solution = new LiveFormula(true);
  const box = h('div', {});
  let shownKind = '';
  return {
    element: h('section', {}, h('h2', {}, 'The parabola y(x)'), box),
    update(m: QuadraticModel) {
      const { parabola, panelWarning } = m.explicit;
      const p = m.state.points;
      if (parabola.kind !== shownKind) {
        shownKind = parabola.kind;
        setChildren(
          box,
          panelWarning === null ? null : warning,
          system.element,
          parabola.kind === 'same-x' ? null : solution.element,
        );
      }
      if (panelWarning !== null) setText(warning, panelWarning);
      system.set(SYSTEM, [
        ...p.flatMap((q) => [texShort(q[0]), texShort(q[0] * q[0])]),
        ...p.map((q) => texShort(q[1])),
      ]);
      if (parabola.kind === 'same-x') return;
      const [a0, a1, a2] = parabola.coefficients;
      solution.set(equation(a1, a0), [
        texNumber(a2, 4),
        texNumber(Math.abs(a1), 4),
        texNumber(Math.abs(a0), 4),
      ]);
    },
  };
}
