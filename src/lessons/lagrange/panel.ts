import { fmt, h, setChildren, dataTable } from '../../app/dom';
import { checkbox, pointButtons, radioGroup } from '../../app/panelControls';
import { extendPolygon } from '../../interact/editPoints';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { lagrangeBasis } from '../../math';
import { formula, renderFormula, texNumber, texPoint } from '../../render/formula';
import { amplification, interpolant, polynomialPoint } from './model';
import { type LagrangeState, MAX_POINTS, type Spacing, degree } from './state';

const SPACINGS: [Spacing, string][] = [
  ['uniform', 'Equally spaced: tₖ = k / n'],
  ['chord', 'Chord length: gaps in t proportional to |Pₖ₊₁ − Pₖ|'],
];

export function lagrangePanel(api: LessonApi<LagrangeState>): LessonPanel<LagrangeState> {
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
    set: (s, on) => ({ ...s, spline: on }),
  });
  const pointCount = pointButtons(api, {
    addLabel: 'Add a point',
    removeLabel: 'Remove the last point',
    count: (s) => s.p.length,
    min: 2,
    max: MAX_POINTS,
    add: (s) => ({ ...s, p: [...s.p, extendPolygon(s.p)] }),
    remove: (s) => ({ ...s, p: s.p.slice(0, -1) }),
  });
  const heading = h('h2', {});
  const warning = h('p', { class: 'warning', role: 'note' });
  const pointFormula = h('div', { class: 'formula display' });
  const tableBody = h('tbody', {});
  const sumLine = h('p', {});
  const rungeText = h('p', {});

  const element = h(
    'div',
    { class: 'lesson-text' },
    h(
      'p',
      {},
      'Through n + 1 points there is exactly one polynomial curve of degree n, once we say at which parameter value tₖ it passes each point Pₖ. Lagrange wrote it down directly: each point gets a weight Lₖ(t), a polynomial that is 1 at its own tₖ and 0 at every other one.',
    ),
    formula(
      'P(t) = \\sum_{k=0}^{n} L_k(t)\\,P_k,\\qquad L_k(t) = \\prod_{j \\ne k} \\frac{t - t_j}{t_k - t_j}',
      true,
    ),
    h('fieldset', { class: 'choices' }, h('legend', {}, 'Parameter values tₖ'), spacing.labels),
    warning,
    spline.element,
    pointCount.element,
    h(
      'p',
      { class: 'note' },
      'Drag a point or move it with Tab and the arrow keys; double-click to add one after the last, Delete to remove one. Drag the cursor in the lower plot (or Tab to it) to move t.',
    ),
    heading,
    pointFormula,
    dataTable('Weights at t', ['k', 'tₖ', 'Lₖ(t)', 'Pₖ'], tableBody),
    sumLine,
    h('h2', {}, "Runge's phenomenon"),
    rungeText,
  );

  return {
    element,
    update(state, info) {
      const n = degree(state);
      const { ts, collapsed } = interpolant(state);
      const weights = lagrangeBasis(ts, state.t);
      const at = polynomialPoint(state, ts, state.t);
      const palette = api.theme().palette;
      spacing.update(state);
      spline.update(state);
      pointCount.update(state);
      warning.hidden = !collapsed;
      if (collapsed) {
        warning.textContent = `P${collapsed[0]} and P${collapsed[1]} are the same point, so chord length gives them the same parameter value and no polynomial can pass both "at once". The curve uses equally spaced values until you move one of them.`;
      }
      heading.textContent = `Degree ${n}, at t = ${fmt(state.t, 3)}`;
      renderFormula(
        pointFormula,
        `P(${texNumber(state.t, 3)}) = \\sum_{k=0}^{${n}} L_k(${texNumber(state.t, 3)})\\,P_k = ${texPoint(at, 3)}`,
        true,
      );
      setChildren(
        tableBody,
        state.p.map((point, k) =>
          h(
            'tr',
            { class: info.hover === `L${k}` ? 'current' : '' },
            h(
              'td',
              {},
              h('span', { class: 'swatch', style: `background:${palette[k % palette.length]}` }),
              `L${k}`,
            ),
            h('td', {}, fmt(ts[k], 4)),
            h('td', {}, fmt(weights[k], 4)),
            h('td', {}, `(${fmt(point[0], 2)}, ${fmt(point[1], 2)})`),
          ),
        ),
      );
      sumLine.textContent = `The weights add up to ${fmt(
        weights.reduce((a, b) => a + b, 0),
        6,
      )} at every t, so the curve does not depend on where the origin is. But they are not all between 0 and 1: a negative weight pushes the curve away from its point.`;
      const worst = amplification(ts);
      rungeText.textContent = `With many points the weights swing far beyond 0 and 1 near the ends. Here Σ|Lₖ(t)| reaches ${fmt(worst.value, 1)} at t = ${fmt(worst.t, 2)}: moving the points by 0.01 can move the curve by up to ${fmt(worst.value * 0.01, 2)}. Try the Runge preset (twelve nearly collinear points): the polynomial oscillates wildly between them, while a cubic spline through the same points stays calm, because each of its pieces only listens to nearby points. That is the reason for splines.`;
    },
  };
}
