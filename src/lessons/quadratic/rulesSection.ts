import { dataTable, fmt, h, setClass, setDisabled, setText } from '../../app/dom';
import type { LessonApi } from '../../app/lesson';
import { LiveFormula, SLOT, texNumber } from '../../render/formula';
import { freeBox } from '../../render/liveBoxes';
import type { QuadraticModel } from './model';
import { seriesColour } from '../../kit/seriesColours';
import { type QuadraticState, clampMu } from './state';

const RULES = `\\begin{aligned}d_0 &= |P_1 - P_0| = ${SLOT},\\quad d_1 = |P_2 - P_1| = ${SLOT}\\\\ \\text{uniform: } \\mu_1 &= \\tfrac12\\\\ \\text{chord length: } \\mu_1 &= \\frac{d_0}{d_0 + d_1} = ${SLOT}\\\\ \\text{centripetal: } \\mu_1 &= \\frac{\\sqrt{d_0}}{\\sqrt{d_0} + \\sqrt{d_1}} = ${SLOT}\\end{aligned}`;

/** "Choosing μ₁ from the points": the rules with the numbers, and a button to use each. */
export function rulesSection(api: LessonApi<QuadraticState, QuadraticModel>) {
  const formula = new LiveFormula(true);
  // Rows and buttons are built once, so a button keeps focus when clicked.
  const rows = (['Uniform', 'Chord length', 'Centripetal'] as const).map((name, k) => {
    const swatch = h('span', { class: 'swatch' });
    // Its own box (render/liveBoxes.ts): a drag lays out the number, not the table.
    const value = freeBox(h('span', {}));
    const use = h('button', { type: 'button' }, `Use ${name.toLowerCase()}`);
    use.addEventListener('click', () => {
      const rule = api.model().parametric.rules[k];
      if (rule.usable) api.set({ ...api.get(), mu: clampMu(rule.mu) });
    });
    const row = h('tr', {}, h('td', {}, swatch, name), h('td', {}, value), h('td', {}, use));
    return { row, swatch, value, use };
  });
  return {
    element: h(
      'section',
      {},
      h('h2', {}, 'Choosing μ₁ from the points'),
      formula.element,
      dataTable(
        'Rules for μ1',
        ['Rule', 'μ₁', h('span', { class: 'visually-hidden' }, 'Action')],
        h('tbody', {}, ...rows.map((r) => r.row)),
      ),
    ),
    update(m: QuadraticModel) {
      const { rules, d0, d1 } = m.parametric;
      const [, chord, centripetal] = rules;
      formula.set(RULES, [
        texNumber(d0, 3),
        texNumber(d1, 3),
        texNumber(chord.mu, 4),
        texNumber(centripetal.mu, 4),
      ]);
      const palette = api.theme().palette;
      rules.forEach((rule, k) => {
        const { row, swatch, value, use } = rows[k];
        const chosen = rule.usable && Math.abs(clampMu(rule.mu) - m.state.mu) < 1e-12;
        setClass(row, chosen ? 'current' : '');
        swatch.style.background =
          m.shown.is('rules') && rule.usable ? seriesColour(palette, k) : 'transparent';
        setText(
          value,
          rule.usable ? fmt(rule.mu, 4) : `${fmt(rule.mu, 0)}: P1 is an end point, no curve`,
        );
        setDisabled(use, !rule.usable || chosen);
      });
    },
  };
}
