import { fmt, h, setChildren, dataTable } from '../../app/dom';
import { pointButtons } from '../../app/panelControls';
import { extendPolygon } from '../../interact/editPoints';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { bernsteinBasis, bezierBasisMatrix, bezierPoint, binomial } from '../../math';
import { formula, renderFormula, texNumber, texPoint } from '../../render/formula';
import { highlightedIndex } from './curveFigure';
import { compareSection } from './comparePanel';
import { type BlendingState, MAX_POINTS, degree, texMu } from './state';
import { blendingNumbersTex, expansionTex, matrixTex, rowTex } from './tex';

/** Worked-out weights and the point stay readable on screen up to this degree. */
const SPELL_OUT_UP_TO = 6;

export function blendingPanel(api: LessonApi<BlendingState>): LessonPanel<BlendingState> {
  const weightsTitle = h('h2', {});
  const weightsBody = h('tbody', {});
  const bar = h('div', {
    class: 'partition-bar',
    role: 'img',
    style:
      'display:flex;height:1.6em;border:1px solid var(--line);border-radius:4px;overflow:hidden;margin:0.5em 0',
  });
  const sumText = h('p', {});
  const pointFormula = h('div', { class: 'formula display' });
  const expansionsBody = h('tbody', {});
  const currentExpansion = h('div', { class: 'formula display' });
  const matrixFormula = h('div', { class: 'formula display' });
  const matrixAtMu = h('div', { class: 'formula display' });
  const centroidTitle = h('h2', {});
  const centroidFormula = h('div', { class: 'formula display' });
  const centroidNote = h('p', { class: 'note' });
  const compare = compareSection(api);
  const pointCount = pointButtons(api, {
    addLabel: 'N + 1: add a control point',
    removeLabel: 'N − 1: remove the last point',
    count: (s) => s.p.length,
    min: 2,
    max: MAX_POINTS,
    add: (s) => ({ ...s, p: [...s.p, extendPolygon(s.p)] }),
    remove: (s) => ({ ...s, p: s.p.slice(0, -1) }),
  });

  const element = h(
    'div',
    { class: 'lesson-text' },
    h(
      'p',
      {},
      'Every point of a Bézier curve is a weighted average of its control points. The weights are the blending functions W(N, i, μ): as μ runs from 0 to 1 the weight moves from P0 to PN, and the point follows.',
    ),
    formula('P(\\mu) = \\sum_{i=0}^{N} W(N,i,\\mu)\\,P_i', true),
    formula('W(N,i,\\mu) = \\binom{N}{i}\\mu^{i}(1-\\mu)^{N-i}', true),
    h(
      'p',
      { class: 'note' },
      'Drag the cursor on the plot (or Tab to μ and use the arrow keys), or the μ slider. Hover a curve of the plot or a row of the table to find its control point. Double-click the figure to add a point, Delete to remove one.',
    ),
    pointCount.element,
    weightsTitle,
    dataTable('Weights at μ', ['Point', 'W(N, i, μ)', 'Weight'], weightsBody),
    bar,
    sumText,
    pointFormula,
    h('h2', {}, 'The expansions'),
    h('p', {}, 'Writing out the sum gives one polynomial weight per control point:'),
    dataTable('Expansions', ['N', 'P(μ)'], expansionsBody),
    currentExpansion,
    h('h2', {}, 'Matrix form'),
    h(
      'p',
      {},
      'Collect the powers of u = μ: the curve is a row of powers, times a constant matrix M, times the column of control points.',
    ),
    matrixFormula,
    matrixAtMu,
    centroidTitle,
    centroidFormula,
    centroidNote,
    compare.element,
  );

  return {
    element,
    update(state, info) {
      const n = degree(state);
      const mu = state.mu;
      const weights = bernsteinBasis(n, mu);
      const palette = api.theme().palette;
      const color = (i: number) => palette[i % palette.length];
      const lit = highlightedIndex(info.hover);
      pointCount.update(state);

      weightsTitle.textContent = `Weights at μ = ${texMu(mu)} (N = ${n})`;
      setChildren(
        weightsBody,
        weights.map((w, i) => {
          const row = h(
            'tr',
            { class: lit === i ? 'current' : '', 'data-value': String(w) },
            h('td', {}, h('span', { class: 'swatch', style: `background:${color(i)}` }), `P${i}`),
            h('td', {}, formula(`W(${n},${i},${texMu(mu)}) = ${blendingNumbersTex(n, i, mu)}`)),
            h('td', { class: 'weight' }, fmt(w, 6)),
          );
          row.addEventListener('mouseenter', () => api.setHover(`w${i}`));
          row.addEventListener('mouseleave', () => api.setHover(null));
          return row;
        }),
      );

      setChildren(
        bar,
        weights.map((w, i) =>
          h('span', {
            title: `W(${n}, ${i}, μ) = ${fmt(w, 4)}`,
            style: `width:${(100 * w).toFixed(3)}%;background:${color(i)};${lit === i ? 'outline:3px solid var(--ink);outline-offset:-3px;' : ''}`,
          }),
        ),
      );
      const sum = weights.reduce((a, b) => a + b, 0);
      bar.setAttribute(
        'aria-label',
        `The weights stacked: ${weights.map((w, i) => `P${i} ${fmt(100 * w, 1)}%`).join(', ')}`,
      );
      sumText.textContent = `Together they fill the bar: ΣW = ${fmt(sum, 12)}. The weights are never negative and always sum to 1 (a partition of unity), so P(μ) is a convex combination of the control points and stays in their convex hull.`;

      const point = bezierPoint(state.p, mu);
      renderFormula(
        pointFormula,
        n <= SPELL_OUT_UP_TO
          ? `\\begin{aligned}P(${texMu(mu)}) &= ${weights.map((w, i) => `${texNumber(w, 4)}\\,${texPoint(state.p[i], 2)}`).join('\\\\ &\\quad + ')}\\\\ &= ${texPoint(point, 4)}\\end{aligned}`
          : `P(${texMu(mu)}) = \\sum_{i=0}^{${n}} W(${n},i,${texMu(mu)})\\,P_i = ${texPoint(point, 4)}`,
        true,
      );

      setChildren(
        expansionsBody,
        [1, 2, 3].map((k) =>
          h(
            'tr',
            { class: k === n ? 'current' : '' },
            h('td', {}, String(k)),
            h('td', {}, formula(expansionTex(k))),
          ),
        ),
      );
      if (n > 3) {
        renderFormula(currentExpansion, `N = ${n}:\\quad ${expansionTex(n, 3)}`, true);
        currentExpansion.hidden = false;
      } else currentExpansion.hidden = true;

      const matrix = bezierBasisMatrix(n);
      const powers = Array.from({ length: n + 1 }, (_, k) =>
        k === 0 ? '1' : k === 1 ? 'u' : `u^{${k}}`,
      );
      renderFormula(
        matrixFormula,
        `\\begin{aligned}x(u) &= U\\,M\\,X,\\qquad U = \\begin{pmatrix}${powers.join(' & ')}\\end{pmatrix},\\\\ X &= \\begin{pmatrix}${state.p.map((_, i) => `x_{${i}}`).join(' & ')}\\end{pmatrix}^{T},\\\\ M &= ${matrixTex(matrix)}\\end{aligned}`,
        true,
      );
      renderFormula(
        matrixAtMu,
        `\\text{at } u = ${texMu(mu)}:\\quad U M = ${rowTex(weights, 4)}`,
        true,
      );

      // x(1/2) weights every point by C(N, i)/2ᴺ: the "centre-weighted centroid".
      const denominator = 2 ** n;
      const terms = state.p.map((_, i) => `\\tfrac{${binomial(n, i)}}{${denominator}}x_{${i}}`);
      const centre = bezierPoint(state.p, 0.5);
      centroidTitle.textContent =
        n === 3 ? 'Worked example: x(0.5) for the cubic' : `Worked example: x(0.5) for N = ${n}`;
      renderFormula(
        centroidFormula,
        `\\begin{aligned}x(0.5) &= ${terms.join(' + ')}\\\\ &= ${texPoint(centre, 4)}\\end{aligned}`,
        true,
      );
      centroidNote.textContent =
        n === 3
          ? 'The middle of the cubic is the centroid of its control points with weights 1, 3, 3, 1: a centre-weighted centroid. The inner points count three times as much as the ends.'
          : `The middle of the curve is the centroid of its control points weighted by the binomial coefficients C(${n}, i): the points near the middle of the polygon count most. For the cubic this is (1/8)x0 + (3/8)x1 + (3/8)x2 + (1/8)x3.`;

      compare.update(state, info);
    },
  };
}
