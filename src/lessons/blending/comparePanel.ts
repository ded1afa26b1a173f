import { fmt, h, setChildren, dataTable } from '../../app/dom';
import type { DrawInfo, LessonApi } from '../../app/lesson';
import { convexHull, convexHullContains, lagrangePoint } from '../../math';
import { formula } from '../../render/formula';
import { basisMinimum, comparisonFamily, equallySpacedNodes } from './bases';
import { hermiteColorIndex } from './plotFigure';
import { type BlendingState, type Comparison, degree, texMu } from './state';
import { radioGroup } from '../../app/panelControls';

const CHOICES: { value: Comparison; label: string }[] = [
  { value: 'none', label: 'Bernstein only' },
  { value: 'hermite', label: 'Hermite H0…H3' },
  { value: 'bspline', label: 'Uniform cubic B-spline' },
  { value: 'lagrange', label: 'Lagrange, equally spaced nodes' },
];

const EXPLAIN: Record<Comparison, string> = {
  none: 'Pick a basis to draw it dashed on the same axes as the Bernstein functions.',
  hermite:
    'The Hermite bases weight the two end points x0, x1 and the two end tangents x0′, x1′ of one cubic patch. H0 + H1 = 1, but H2 and H3 take negative values: they weight vectors, not points, so there is no convex hull to stay in. For the cubic, x0′ = 3(P1 − P0) and x1′ = 3(P3 − P2) (arrows in the figure) give exactly the same curve.',
  bspline:
    'The four blending functions of one uniform cubic B-spline segment, which weight four consecutive points. Like Bernstein’s they are never negative and sum to 1, so the curve stays in the convex hull; but none of them reaches 1, so the curve passes through no control point. Dashed in the figure: the uniform B-spline of these control points.',
  lagrange:
    'The Lagrange bases for the nodes μ = 0, 1/N, …, 1 also sum to 1, and each is 1 at its own node, so the dashed curve passes through every control point. But they are not non-negative: a negative weight pushes the point away from its control point, and the curve can leave the convex hull.',
};

/** The switch to compare other bases, with their values at μ and whether they go negative. */
export function compareSection(api: LessonApi<BlendingState>) {
  const basisChoice = radioGroup(api, {
    name: 'compare',
    choices: CHOICES,
    get: (s) => s.b,
    set: (s, b) => ({ ...s, b }),
  });
  const explain = h('p', {});
  const tableBody = h('tbody', {});
  const table = dataTable(
    'Comparison weights at μ',
    ['Function', 'Weights', 'Value at μ'],
    tableBody,
  );
  const verdict = h('p', { class: 'note' });
  const element = h(
    'div',
    {},
    h('h2', {}, 'Compare with other bases'),
    h(
      'fieldset',
      { style: 'border:0;padding:0;margin:0' },
      h('legend', { class: 'visually-hidden' }, 'Basis drawn for comparison'),
      basisChoice.labels,
    ),
    explain,
    table,
    verdict,
  );

  return {
    element,
    update(state: BlendingState, info: DrawInfo) {
      const n = degree(state);
      basisChoice.update(state);
      explain.textContent = EXPLAIN[state.b];
      const basis = comparisonFamily(state.b, n);
      table.hidden = basis === null;
      if (!basis) {
        setChildren(verdict);
        return;
      }
      const palette = api.theme().palette;
      const colorIndex = (i: number) => (state.b === 'hermite' ? hermiteColorIndex(i, n) : i);
      const values = basis.values(state.mu);
      setChildren(
        tableBody,
        values.map((v, i) => {
          const row = h(
            'tr',
            { class: info.hover === `c${i}` ? 'current' : '' },
            h(
              'td',
              {},
              h('span', {
                class: 'swatch',
                style: `background:${palette[colorIndex(i) % palette.length]}`,
              }),
              formula(basis.labels[i]),
            ),
            h('td', {}, formula(basis.weights[i])),
            h('td', {}, fmt(v, 6)),
          );
          row.addEventListener('mouseenter', () => api.setHover(`c${i}`));
          row.addEventListener('mouseleave', () => api.setHover(null));
          return row;
        }),
      );
      const sum = values.reduce((a, b) => a + b, 0);
      const lowest = basisMinimum(basis);
      const sentences = [
        `At μ = ${texMu(state.mu)} these values sum to ${fmt(sum, 6)}.`,
        lowest.value < -1e-12
          ? `Not non-negative: the lowest value on [0, 1] is ${fmt(lowest.value, 4)}, reached by ${plain(basis.labels[lowest.index])} at μ = ${fmt(lowest.mu, 3)}.`
          : 'No value on [0, 1] is negative.',
      ];
      if (state.b === 'lagrange') sentences.push(lagrangeHullSentence(state));
      if (state.b === 'hermite' && n !== 3)
        sentences.push('Set N = 3 to see the Hermite form of this very curve in the figure.');
      if (state.b === 'bspline' && n < 3)
        sentences.push(
          'A cubic B-spline needs at least four control points: add one to see its curve.',
        );
      verdict.textContent = sentences.join(' ');
    },
  };
}

const plain = (label: string) => label.replace(/_\{?([^}]*)\}?/, '$1');

/** Whether the Lagrange curve through the control points stays inside their convex hull. */
function lagrangeHullSentence(state: BlendingState): string {
  const hull = convexHull(state.p);
  const nodes = equallySpacedNodes(degree(state));
  const samples = 400;
  let outside = 0;
  for (let k = 0; k <= samples; k++) {
    const point = lagrangePoint(nodes, state.p, k / samples);
    if (!convexHullContains(hull, point, 1e-9)) outside++;
  }
  return outside > 0
    ? `The dashed Lagrange curve leaves the convex hull of the control points (${Math.round((100 * outside) / (samples + 1))}% of its samples lie outside); the Bézier curve never does.`
    : 'Here the dashed Lagrange curve happens to stay in the convex hull; drag a point (or try the Lagrange preset) to push it out.';
}
