import { dataTable, fmt, h, liveText, setHidden, setText } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { checkbox, radioGroup } from '../../app/panelControls';
import { LiveFormula, SLOT, formula, slotPoint, texNumber } from '../../render/formula';
import { type LagrangeModel, basisId } from './model';
import { interpolatedPoints } from './points';
import { keepShownToEnd } from './script';
import { BASIS_SLIP, NOTES_KEY, rungeText } from './text';
import { words } from '../../kit/format';
import { notesKey, notesSlip } from '../../kit/notes';
import type { LagrangeState, Spacing } from './state';
import { gestures } from '../../kit/gestures';

const SPACINGS: [Spacing, string][] = [
  ['uniform', 'Equally spaced: tₖ = k / n'],
  ['chord', 'Chord length: gaps in t proportional to |Pₖ₊₁ − Pₖ|'],
];

/** P(t) = Σ L_k(t) P_k = (x, y): the degree is part of the shape, t and the point are numbers. */
const pointShape = (n: number) =>
  `P(${SLOT}) = \\sum_{k=0}^{${n}} L_k(${SLOT})\\,P_k = ${slotPoint()}`;

export function lagrangePanel(
  api: LessonApi<LagrangeState, LagrangeModel>,
): LessonPanel<LagrangeState, LagrangeModel> {
  const spacing = radioGroup(api, {
    name: 'spacing',
    choices: SPACINGS.map(([value, label]) => ({ value, label })),
    get: (s) => s.spacing,
    set: (s, value) => ({ ...s, spacing: value }),
  });
  const spline = checkbox(api, {
    id: 'lagrange-spline',
    label: 'Compare with a natural cubic spline through the same points',
    get: (s) => s.spline,
    set: (s, on) => keepShownToEnd(s, { ...s, spline: on }),
  });
  const pointCount = interpolatedPoints.buttons(api);
  const heading = liveText(h('h2', {}));
  const warning = h('p', { class: 'warning', role: 'note' });
  const pointFormula = new LiveFormula(true);
  const tableBody = h('tbody', {});
  const table = new LiveRows(tableBody);
  const sumLine = h('p', {});
  const rungeParagraph = h('p', {});
  let hovered: string | null = null;

  const element = h(
    'div',
    { class: 'lesson-text' },
    h(
      'p',
      {},
      'Through n + 1 points there is exactly one polynomial curve of degree n, once we say at which parameter value tₖ it passes each point Pₖ. Lagrange wrote it down directly: each point gets a weight Lₖ(t), a polynomial that is 1 at its own tₖ and 0 at every other one. In this lesson the parameter is t, from 0 to 1.',
    ),
    formula(
      'P(t) = \\sum_{k=0}^{n} L_k(t)\\,P_k,\\qquad L_k(t) = \\prod_{j \\ne k} \\frac{t - t_j}{t_k - t_j}',
      true,
    ),
    notesSlip('continuation', BASIS_SLIP.written, BASIS_SLIP.correct),
    notesKey(NOTES_KEY),
    h('fieldset', { class: 'choices' }, h('legend', {}, 'Parameter values tₖ'), spacing.labels),
    warning,
    spline.element,
    pointCount.element,
    h(
      'p',
      { class: 'note' },
      `To move a point, ${gestures().move}; to add one after the last, ${gestures().add}; to remove one, ${gestures().remove}. Drag the cursor in the lower plot to move t.`,
    ),
    heading,
    pointFormula.element,
    dataTable('Weights at t', ['k', 'tₖ', 'Lₖ(t)', 'Pₖ'], tableBody),
    sumLine,
    h('h2', {}, "Runge's phenomenon"),
    rungeParagraph,
  );

  /** The row of the basis curve under the pointer is marked, in whichever figure. */
  const markHovered = () => {
    [...tableBody.rows].forEach((row, k) =>
      row.classList.toggle('current', hovered === basisId(k)),
    );
  };

  return {
    element,
    update(m, state) {
      const { n, ts, weights, at, lebesgue } = m;
      const palette = api.theme().palette;
      spacing.update(state);
      spline.update(state);
      pointCount.update(state);
      setHidden(warning, m.collapsedWarning === null);
      if (m.collapsedWarning) setText(warning, m.collapsedWarning);
      setText(heading, `Degree ${n}, at t = ${fmt(state.t, 3)}`);
      const t = texNumber(state.t, 3);
      pointFormula.set(pointShape(n), [t, t, ...at.map((v) => texNumber(v, 3))]);
      table.set(
        state.points.map((point, k) => ({
          cells: [
            { text: `L${k}`, swatch: palette[k % palette.length] },
            fmt(ts[k], 4),
            fmt(weights[k], 4),
            `(${fmt(point[0], 2)}, ${fmt(point[1], 2)})`,
          ],
        })),
      );
      // Rows added for new points are marked too.
      markHovered();
      setText(
        sumLine,
        `The weights add up to ${words(m.weightSum)} at every t, so the curve does not depend on where the origin is. But they are not all between 0 and 1: a negative weight pushes the curve away from its point.`,
      );
      setText(rungeParagraph, rungeText(lebesgue));
    },
    hover(id) {
      hovered = id;
      markHovered();
    },
  };
}
