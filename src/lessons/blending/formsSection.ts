import { dataTable, h, setClass, setHidden, setText } from '../../app/dom';
import { LiveFormula, formula, renderFormula } from '../../render/formula';
import type { BlendingModel } from './model';
import { centroidFormula, expansionTex, matrixFormTex, rowFormula } from './tex';

/** The same curve written out: the expansions, the matrix form, and P(0.5) worked out. */
export function formsSection() {
  // The expansions for N = 1, 2, 3 never change; the row of the current N is marked.
  const expansions = [1, 2, 3].map((k) =>
    h('tr', {}, h('td', {}, String(k)), h('td', {}, formula(expansionTex(k)))),
  );
  const currentExpansion = h('div', { class: 'formula display' });
  const matrix = h('div', { class: 'formula display' });
  const matrixAtMu = new LiveFormula(true);
  const centroidTitle = h('h2', {});
  const centroid = new LiveFormula(true);
  const centroidNote = h('p', { class: 'note' });
  let shownN = -1;

  return {
    elements: [
      h('h2', {}, 'The expansions'),
      h('p', {}, 'Writing out the sum gives one polynomial weight per control point:'),
      dataTable('Expansions', ['N', 'P(μ)'], h('tbody', {}, expansions)),
      currentExpansion,
      h('h2', {}, 'Matrix form'),
      h(
        'p',
        {},
        'Collect the powers of μ: the curve is a row of powers of μ, times a constant matrix M, times the column of control points.',
      ),
      matrix,
      matrixAtMu.element,
      centroidTitle,
      centroid.element,
      centroidNote,
    ],
    update(m: BlendingModel) {
      const { n } = m;
      if (n !== shownN) {
        shownN = n;
        expansions.forEach((row, k) => setClass(row, k + 1 === n ? 'current' : ''));
        if (n > 3) renderFormula(currentExpansion, `N = ${n}:\\quad ${expansionTex(n, 3)}`, true);
        setHidden(currentExpansion, n <= 3);
        renderFormula(matrix, matrixFormTex(m.matrix), true);
        setText(
          centroidTitle,
          n === 3 ? 'Worked example: P(0.5) for the cubic' : `Worked example: P(0.5) for N = ${n}`,
        );
        setText(
          centroidNote,
          n === 3
            ? 'The middle of the cubic is the centroid of its control points with weights 1, 3, 3, 1: a centre-weighted centroid. The inner points count three times as much as the ends.'
            : `The middle of the curve is the centroid of its control points weighted by the binomial coefficients C(${n}, i): the points near the middle of the polygon count most. For the cubic this is (1/8)P0 + (3/8)P1 + (3/8)P2 + (1/8)P3.`,
        );
      }
      matrixAtMu.set(rowFormula(m.state.mu, m.weights));
      centroid.set(centroidFormula(n, m.centre));
    },
  };
}
