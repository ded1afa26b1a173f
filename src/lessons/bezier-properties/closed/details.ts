import { h, setText } from '../../../app/dom';
import { LiveFormula } from '../../../render/formula';
import { type ExperimentPanel, arrangements } from '../experimentPanel';
import type { ModelOf } from '../model';

export const closedPanel: ExperimentPanel<ModelOf<'closed'>> = {
  number: 4,
  title: 'A closed curve',
  sentence:
    'Repeat the first point at the end, P0 = PN, and the curve closes; it is smooth there only if PN−1, P0 and P1 lie on one line.',
  build() {
    const unmeasurable = h(
      'p',
      {},
      'A neighbour of P0 sits on it, so one end tangent is zero and the corner cannot be measured: move P1 or the last point away from P0.',
    );
    const tangents = new LiveFormula(true);
    const verdict = h('p', {});
    const show = arrangements();
    return {
      update(m) {
        const { n, corner } = m;
        if (corner === null) return show('unmeasurable', () => [unmeasurable]);
        tangents.set(`P'(0) = ${n}(P_1 - P_0),\\qquad P'(1) = ${n}(P_0 - P_{${n - 1}})`, []);
        setText(
          verdict,
          m.smooth
            ? `The end tangents agree in direction (within ${corner.toFixed(2)}°): the closed curve is smooth at P0.`
            : `The arriving and the leaving tangent (arrows, shortened to fit the figure; their directions are true) meet at ${corner.toFixed(1)}°: the curve closes with a corner at P0. Drag P1 or P${n - 1} in line with P0 to smooth it.`,
        );
        return show('measured', () => [tangents.element, verdict]);
      },
    };
  },
};
