import { h, liveText, setText } from '../../../app/dom';
import { LiveFormula, SLOT } from '../../../render/formula';
import { texT } from '../../../kit/format';
import { type ExperimentPanel, arrangements, coords, slotPoint } from '../experimentPanel';
import type { ModelOf } from '../model';

const valuesShape = (n: number) =>
  `\\begin{aligned}P(0) &= P_0 = ${slotPoint()}\\\\ P(1) &= P_{${n}} = ${slotPoint()}\\\\ P'(0) &= ${n}(P_1 - P_0) = ${slotPoint()}\\\\ P'(1) &= ${n}(P_{${n}} - P_{${n - 1}}) = ${slotPoint()}\\\\ P'(${SLOT}) &= ${slotPoint()}\\end{aligned}`;

export const endsPanel: ExperimentPanel<ModelOf<'ends'>> = {
  number: 1,
  title: 'End points and end tangents',
  sentence:
    'The curve starts at P0 and ends at PN, leaving along the first leg of the polygon and arriving along the last, with speed N times the leg: P′(0) = N(P1 − P0), P′(1) = N(PN − PN−1).',
  build() {
    const values = new LiveFormula(true);
    const speeds = liveText(h('p', {}));
    const note = h(
      'p',
      { class: 'note' },
      'The arrows are drawn at half their true length, in the units of the grid: a speed, not just a direction. For a cubic, half of 3(P1 − P0) still reaches past P1. Drag P1 along the first leg: the start tangent keeps its direction and changes its length.',
    );
    const stillAtStart = h(
      'p',
      {},
      'P1 sits on P0, so P′(0) = 0: the curve starts with zero speed, and leaves toward the next distinct control point instead (its direction comes from a higher derivative).',
    );
    const stillAtEnd = h('p', {});
    const show = arrangements();
    return {
      update(m) {
        const [start, end, at] = m.tangents;
        const { controls, n } = m;
        values.set(valuesShape(n), [
          ...coords(controls[0]),
          ...coords(controls[n]),
          ...coords(start.vector),
          ...coords(end.vector),
          texT(m.state.t),
          ...coords(at.vector),
        ]);
        setText(
          speeds,
          `Speeds: |P′(0)| = ${start.speed.toFixed(3)}, |P′(1)| = ${end.speed.toFixed(3)}, |P′(t)| = ${at.speed.toFixed(3)}.`,
        );
        setText(
          stillAtEnd,
          `P${n - 1} sits on P${n}, so P′(1) = 0: the curve arrives with zero speed.`,
        );
        return show(`${m.stillAtStart} ${m.stillAtEnd}`, () => [
          values.element,
          speeds,
          note,
          ...(m.stillAtStart ? [stillAtStart] : []),
          ...(m.stillAtEnd ? [stillAtEnd] : []),
        ]);
      },
    };
  },
};
