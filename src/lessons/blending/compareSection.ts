import { dataTable, fmt, h, setHidden, setText } from '../../app/dom';
import type { LessonApi } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { radioGroup } from '../../app/panelControls';
import { fixed, texT, words } from '../../kit/format';
import { formula } from '../../render/formula';
import { comparedIds, comparedIndex } from './hover';
import type { BlendingModel, Compared } from './model';
import { wordsSlip } from './notesKey';
import type { Nearest } from './passes';
import { keepShownToEnd } from './script';
import type { BlendingState, Comparison } from './state';

const CHOICES: { value: Comparison; label: string }[] = [
  { value: 'none', label: 'Bernstein only' },
  { value: 'hermite', label: 'Hermite H0…H3' },
  { value: 'bspline', label: 'Uniform cubic B-spline' },
  { value: 'lagrange', label: 'Lagrange, equally spaced nodes' },
  { value: 'mirror', label: 'Bernstein mirrored: μ → 1 − μ' },
  { value: 'interpolating', label: 'Interpolating or approximating: Lagrange and Bézier' },
];

const EXPLAIN: Record<Comparison, string> = {
  none: 'Pick a basis to draw it dashed on the same axes as the Bernstein functions.',
  hermite:
    'The Hermite bases weight the two end points P0, PN and the two end gradients D0, DN of one cubic patch (the lecture’s equation 7). H0 + H1 = 1, and H2 = μ(1−μ)² is never negative, but H3 = −μ²(1−μ) is below zero on the whole of (0, 1): H2 and H3 weight vectors, not points, so there is no convex hull to stay in. For the cubic, D0 = 3(P1 − P0) and D3 = 3(P3 − P2) (arrows in the figure) give exactly the same curve.',
  bspline:
    'The four blending functions of one uniform cubic B-spline segment, which weight four consecutive points. Like Bernstein’s they are never negative and sum to 1, so the curve stays in the convex hull; but none of them reaches 1, so the curve passes through no control point. Dashed in the figure: the uniform B-spline of these control points.',
  lagrange:
    'The Lagrange bases for the nodes μ = 0, 1/N, …, 1 also sum to 1, and each is 1 at its own node, so the dashed curve passes through every control point. But they are not non-negative: a negative weight pushes the point away from its control point, and the curve can leave the convex hull.',
  mirror:
    'The blending functions are symmetric under μ → 1 − μ: W(N, i, μ) = W(N, N − i, 1 − μ), since C(N, i) = C(N, N − i). Step through it with the clicker: the second cursor at 1 − μ, each pair of functions, and the curve traced backwards by the reversed control points.',
  interpolating:
    'An interpolating curve passes through every one of its points; an approximating curve is shaped by its control points without having to pass through them. The Lagrange curve (dashed) interpolates: Lᵢ is 1 at its own node μ = i/N and 0 at the others, so at μ = i/N the curve is at Pᵢ. The Bézier curve approximates: only W(N, 0, μ) and W(N, N, μ) reach 1, so it passes through P0 and PN, and no other point has its whole weight anywhere. Each point’s distance to a curve is the least |C(μ) − Pᵢ| over μ: 0 exactly where the curve passes through it.',
};

const plain = (label: string) => label.replace(/_\{?([^}]*)\}?/, '$1');

/** The switch to compare other bases, with their values at μ and whether they go negative. */
export function compareSection(api: LessonApi<BlendingState, BlendingModel>) {
  const basisChoice = radioGroup(api, {
    name: 'compare',
    choices: CHOICES,
    get: (s) => s.comparison,
    // A script shown to its end stays shown to its end (in the script of the new choice).
    set: (s, comparison) => keepShownToEnd(s, { ...s, comparison }),
  });
  const explain = h('p', {});
  // Beside the words' meaning, where the “Splines” slides swap them (that scene only).
  const slip = wordsSlip();
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  const table = dataTable('Comparison weights at μ', ['Function', 'Weights', 'Value at μ'], body);
  const verdict = h('p', { class: 'note' });
  // The names in the first two columns are formulas: made again only when the family changes.
  let shownFamily: Compared | null = null;
  let lit: number | null = null;

  body.addEventListener('mouseover', (e) => {
    const row = (e.target as Element).closest('tr');
    if (row) api.setHover(comparedIds.id(row.sectionRowIndex));
  });
  body.addEventListener('mouseleave', () => api.setHover(null));

  function showLit() {
    [...body.rows].forEach((row, i) => row.classList.toggle('current', i === lit));
  }

  return {
    element: h(
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
      slip,
      table,
      verdict,
    ),
    update(m: BlendingModel) {
      const { state, n, compared } = m;
      basisChoice.update(state);
      setText(explain, EXPLAIN[state.comparison]);
      setHidden(slip, state.comparison !== 'interpolating');
      setHidden(table, compared === null);
      if (!compared) {
        rows.set([]);
        shownFamily = null;
        setText(verdict, '');
        return;
      }
      const palette = api.theme().palette;
      rows.set(
        compared.atMu.map((v, i) => ({
          cells: [
            { text: '', swatch: palette[compared.colors[i] % palette.length] },
            '',
            fmt(v, 6),
          ],
        })),
      );
      if (labelsChanged(shownFamily, compared)) {
        [...body.rows].forEach((row, i) => {
          row.cells[0].querySelector('.formula')?.remove();
          row.cells[1].querySelector('.formula')?.remove();
          row.cells[0].append(formula(compared.labels[i]));
          row.cells[1].append(formula(compared.weights[i]));
        });
      }
      shownFamily = compared;
      showLit();

      const lowest = compared.samples.lowest;
      const sentences = [
        // Read out by a lecturer: a sum to three decimals (1, 1.084), a true minus sign.
        `At μ = ${texT(state.mu)} these values sum to ${words(compared.sum)}.`,
        lowest.value < -1e-12
          ? `Not non-negative: the lowest value on [0, 1] is ${fixed(lowest.value, 4)}, reached by ${plain(compared.labels[lowest.index])} at μ = ${fmt(lowest.mu, 3)}.`
          : 'No value on [0, 1] is negative.',
      ];
      if (compared.outside !== null)
        sentences.push(
          compared.outside > 0
            ? `The dashed Lagrange curve leaves the convex hull of the control points (${Math.round(100 * compared.outside)}% of its samples lie outside); the Bézier curve never does.`
            : 'Here the dashed Lagrange curve happens to stay in the convex hull; drag a point (or try the Lagrange preset) to push it out.',
        );
      if (m.passes)
        sentences.push(
          `Distance of P0 … P${n} to the Lagrange curve: ${distances(m.passes.lagrange)}; to the Bézier curve: ${distances(m.passes.bezier)}.`,
        );
      if (state.comparison === 'hermite' && n !== 3)
        sentences.push('Set N = 3 to see the Hermite form of this very curve in the figure.');
      if (state.comparison === 'bspline' && n < 3)
        sentences.push(
          'A cubic B-spline needs at least four control points: add one to see its curve.',
        );
      setText(verdict, sentences.join(' '));
    },
    hover(id: string | null) {
      lit = comparedIndex(id);
      showLit();
    },
  };
}

/** Each point's distance to a curve, in words: "0, 0.714, 0.714, 0". */
const distances = (near: readonly Nearest[]) => near.map((q) => words(q.distance)).join(', ');

/** Whether the rows must show other names: another family, or one of another size. */
function labelsChanged(before: Compared | null, after: Compared): boolean {
  return (
    !before ||
    before.labels.length !== after.labels.length ||
    before.labels.some((label, i) => label !== after.labels[i]) ||
    before.weights.some((weight, i) => weight !== after.weights[i])
  );
}
