import { dataTable, h, setText } from '../../../app/dom';
import { LiveRows } from '../../../app/liveTable';
import { LiveFormula, formula } from '../../../render/formula';
import { type ExperimentPanel, arrangements, coords, slotPoint } from '../experimentPanel';
import { smallNumber } from '../../../kit/format';
import type { ModelOf } from '../model';
import { DEVIATION_SAMPLES } from './model';

/** The last elevation's Q1, from degree m. */
const lastStepShape = (m: number) =>
  `\\text{last step } (N = ${m}):\\ Q_1 = \\tfrac{1}{${m + 1}}P_0 + \\tfrac{${m}}{${m + 1}}P_1 = ${slotPoint()}`;

export const elevatePanel: ExperimentPanel<ModelOf<'elevate'>> = {
  number: 5,
  title: 'Degree elevation',
  sentence:
    'Raising the degree replaces N + 1 control points by N + 2 on the same curve; repeat it and the control polygon closes in on the curve.',
  build() {
    const rule = formula(
      '\\begin{aligned}Q_0 &= P_0,\\qquad Q_{N+1} = P_N\\\\ Q_i &= \\tfrac{i}{N+1}P_{i-1} + \\bigl(1 - \\tfrac{i}{N+1}\\bigr)P_i\\end{aligned}',
      true,
    );
    const degree = h('p', {});
    const deviation = h('p', {});
    const lastStep = new LiveFormula(true);
    const body = h('tbody', {});
    const rows = new LiveRows(body);
    const table = dataTable(
      'Distance from polygon to curve',
      ['Degree', 'max |Qi − P(i/N)|'],
      body,
    );
    const note = h(
      'p',
      { class: 'note' },
      'The gap between each control point and the curve point at the matching parameter shrinks about like 1/N: the polygon converges to the curve, slowly.',
    );
    const show = arrangements();
    return {
      update(m) {
        const raised = m.polygons.length - 1;
        setText(
          degree,
          raised === 0
            ? `Degree ${m.originalDegree}, not raised yet. Press "Raise the degree" (or step forward).`
            : `Degree ${m.originalDegree} raised ${raised} time${raised === 1 ? '' : 's'}: degree ${m.n}, ${m.n + 1} control points (solid), the original polygon dashed.`,
        );
        deviation.dataset.deviation = String(m.deviation);
        setText(
          deviation,
          `Largest distance between this curve and the original, over ${DEVIATION_SAMPLES + 1} samples: ${smallNumber(m.deviation)} — the same curve, up to rounding.`,
        );
        if (m.lastStep) lastStep.set(lastStepShape(m.lastStep.from), coords(m.lastStep.q1, 3));
        rows.set(
          m.polygons.map((polygon, j) => ({
            className: j === raised ? 'current' : '',
            cells: [String(polygon.length - 1), m.gaps[j].toFixed(4)],
          })),
        );
        return show(m.lastStep ? 'raised' : 'original', () => [
          rule,
          degree,
          deviation,
          ...(m.lastStep ? [lastStep.element] : []),
          table,
          note,
        ]);
      },
    };
  },
};
