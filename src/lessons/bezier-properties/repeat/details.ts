import { h, setText } from '../../../app/dom';
import { LiveFormula, SLOT, texNumber } from '../../../render/formula';
import { texT } from '../../../kit/format';
import { type ExperimentPanel } from '../experimentPanel';
import type { ModelOf } from '../model';

/** The weight of P_r: the sum of the Bernstein weights of its copies, r … r + copies − 1. */
const weightShape = (r: number, copies: number, n: number) =>
  `\\begin{aligned}&\\text{weight of } P_{${r}} \\text{ at } t = ${SLOT}:\\\\ &\\sum_{j=${r}}^{${r + copies - 1}} W(${n},j,t) = ${SLOT}\\quad(\\text{once: }{}${SLOT})\\end{aligned}`;

export const repeatPanel: ExperimentPanel<ModelOf<'repeat'>> = {
  number: 4,
  title: 'Repeated control points',
  sentence:
    'A control point listed several times gets the sum of their weights, so the curve is pulled toward it; press "Add a copy" (or step forward) and watch.',
  build() {
    const summary = h('p', {});
    const weight = new LiveFormula(true);
    const nodes = [summary, weight.element];
    return {
      update(m) {
        const { repeated: r, t } = m.state;
        const { copies, n } = m;
        setText(
          summary,
          `P${r} appears ${copies} time${copies === 1 ? '' : 's'}: the curve has ${n + 1} control points, degree ${n}. Dashed: the curve with P${r} once.`,
        );
        weight.set(weightShape(r, copies, n), [
          texT(t),
          texNumber(m.weight, 4),
          texNumber(m.weightOnce, 4),
        ]);
        return nodes;
      },
    };
  },
};
