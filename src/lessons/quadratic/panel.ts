import { fmt, h, setChildren, dataTable } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { distance, parametricQuadraticPoint } from '../../math';
import { formula, renderFormula, texNumber, texPoint } from '../../render/formula';
import { fmtNumber } from './figure';
import { clampMu, explicitParabola, muRules, quadraticCoefficients, sameXWords } from './model';
import { type QuadraticState, STEP_TITLES } from './state';

/** Every digit a reader may want to check by hand (12 significant). */
const allDigits = (v: number) => String(Number(v.toPrecision(12)));
/** Up to three decimals, trailing zeros dropped: for the matrix of the system. */
const texShort = (v: number) => fmt(Number(v.toFixed(3)), 3).replace(/\.?0+$/, '');
const texMu = (mu: number) => String(Number(mu.toFixed(4)));

const STEP_TEXT = [
  'Three points, and we want a smooth curve through them. The first idea: a function y = a₂x² + a₁x + a₀, three unknowns for three points. Drag the points; put two of them above one another, or make them go backwards in x, and watch this idea fail. The μ₁ slider belongs to the next step.',
  'Make both coordinates functions of a parameter μ instead: P(μ) = a₂μ² + a₁μ + a₀ starts at P0 (μ = 0) and ends at P2 (μ = 1). Nothing says at which μ it should pass P1: we choose that value, μ₁. The dots sit at μ = 0, 0.1, …, 1: where they spread out, the point moves fast.',
  'The same three points give a different curve for every μ₁. With μ₁ small the curve hurries to P1 and then swings wide towards P2; with μ₁ near 1 it is the other way round. One set of points, many curves: the parameter values are part of the data.',
  'So choose μ₁ from the points themselves. Uniform ignores the geometry; chord length gives each span its share of μ by its length; centripetal uses square roots of the lengths. Move P1 close to P0 and compare: chord length and centripetal give the natural curve, uniform overshoots.',
];

export function quadraticPanel(api: LessonApi<QuadraticState>): LessonPanel<QuadraticState> {
  const stepTitle = h('h2', {});
  const stepText = h('p', {});
  const parabolaBox = h('div', {});
  const parametricBox = h('div', {});
  const rulesBox = h('div', { class: 'formula display' });
  const rules = rulesTable(api);
  const digitsBody = h('tbody', {});

  const parabolaSection = h('section', {}, h('h2', {}, 'The parabola y(x)'), parabolaBox);
  const parametricSection = h(
    'section',
    {},
    h('h2', {}, 'The parametric quadratic'),
    parametricBox,
    h(
      'details',
      {},
      h('summary', {}, 'All digits of the coefficients'),
      dataTable('Coefficients, all digits', ['Vector', 'x', 'y'], digitsBody),
    ),
  );
  const rulesSection = h(
    'section',
    {},
    h('h2', {}, 'Choosing μ₁ from the points'),
    rulesBox,
    dataTable(
      'Rules for μ1',
      ['Rule', 'μ₁', h('span', { class: 'visually-hidden' }, 'Action')],
      h('tbody', {}, rules.rows),
    ),
  );
  const higherSection = h(
    'section',
    {},
    h('h2', {}, 'Why not just go to a higher degree?'),
    h(
      'p',
      {},
      'Three points, degree 2. Four points need a cubic, n + 1 points a polynomial of degree n, and one polynomial through many points wiggles more and more between them. ',
      h(
        'a',
        { href: '#/lagrange' },
        'See it in the next lesson: one polynomial through n + 1 points',
      ),
      '.',
    ),
  );
  const element = h('div', { class: 'lesson-text' });
  let shownStep = -1;

  return {
    element,
    update(state) {
      const p = state.p;
      stepTitle.textContent = `Step ${state.step} of ${STEP_TITLES.length - 1}: ${STEP_TITLES[state.step]}`;
      stepText.textContent = STEP_TEXT[state.step];
      if (state.step !== shownStep) {
        // The section the step is about comes first, under the step's text.
        shownStep = state.step;
        const first = [parabolaSection, parametricSection, parametricSection, rulesSection][
          state.step
        ];
        const rest = [parabolaSection, parametricSection, rulesSection].filter((x) => x !== first);
        setChildren(element, stepTitle, stepText, first, ...rest, higherSection);
      }
      updateParabola(parabolaBox, p);
      updateParametric(parametricBox, digitsBody, p, state.mu);
      rulesFormula(rulesBox, p);
      rules.update(state);
    },
  };
}

function updateParabola(box: HTMLElement, p: QuadraticState['p']) {
  const parabola = explicitParabola(p);
  if (parabola.kind === 'same-x') {
    setChildren(
      box,
      h(
        'p',
        { class: 'warning', role: 'note' },
        `There is none: ${sameXWords(p, parabola.x, fmtNumber)}, so the system below has equal rows and no solution.`,
      ),
      formula(vandermonde(p), true),
    );
    return;
  }
  const [a0, a1, a2] = parabola.coefficients;
  const parts = [
    formula(vandermonde(p), true),
    formula(`y = ${texNumber(a2, 4)}\\,x^2 ${signed(a1)}\\,x ${signed(a0)}`, true),
  ];
  if (parabola.kind === 'backwards') {
    parts.unshift(
      h(
        'p',
        { class: 'warning', role: 'note' },
        `It exists, but it meets the points in the wrong order: x1 = ${fmtNumber(p[1][0])} is not between x0 = ${fmtNumber(p[0][0])} and x2 = ${fmtNumber(p[2][0])}. A function y(x) cannot go back in x.`,
      ),
    );
  }
  setChildren(box, parts);
}

const signed = (v: number) => (v < 0 ? `- ${texNumber(-v, 4)}` : `+ ${texNumber(v, 4)}`);

/** The three equations y_i = a0 + a1 x_i + a2 x_i² as a matrix, with the numbers. */
function vandermonde(p: QuadraticState['p']): string {
  const rows = p.map((q) => `1 & ${texShort(q[0])} & ${texShort(q[0] * q[0])}`).join('\\\\');
  const ys = p.map((q) => texShort(q[1])).join('\\\\');
  return `\\begin{pmatrix}${rows}\\end{pmatrix}\\begin{pmatrix}a_0\\\\a_1\\\\a_2\\end{pmatrix} = \\begin{pmatrix}${ys}\\end{pmatrix}`;
}

function updateParametric(
  box: HTMLElement,
  digitsBody: HTMLElement,
  p: QuadraticState['p'],
  mu: number,
) {
  const [a0, a1, a2] = quadraticCoefficients(p, mu);
  const at = parametricQuadraticPoint(p[0], p[1], p[2], mu, mu);
  const m = texMu(mu);
  const lines = [
    // Equation 2 of the notes: the three conditions.
    `\\begin{aligned}P(0) &= a_0 = P_0 = ${texPoint(p[0], 3)}\\\\ P(${m}) &= a_2\\cdot ${m}^2 + a_1\\cdot ${m} + a_0 = P_1 = ${texPoint(p[1], 3)}\\\\ P(1) &= a_2 + a_1 + a_0 = P_2 = ${texPoint(p[2], 3)}\\end{aligned}`,
    // Equation 3: their solution.
    `\\begin{aligned}a_0 &= P_0 = ${texPoint(a0, 4)}\\\\ a_2 &= \\frac{P_1 - P_0 - \\mu_1 (P_2 - P_0)}{\\mu_1(\\mu_1 - 1)} = ${texPoint(a2, 4)}\\\\ a_1 &= P_2 - P_0 - a_2 = ${texPoint(a1, 4)}\\end{aligned}`,
    `\\text{Check: } P(${m}) = ${texPoint(at, 4)} = P_1`,
  ];
  if (box.childElementCount !== lines.length) {
    setChildren(
      box,
      lines.map(() => h('div', { class: 'formula display' })),
    );
  }
  lines.forEach((tex, i) => renderFormula(box.children[i] as HTMLElement, tex, true));
  const rows: [string, readonly number[]][] = [
    ['a0', a0],
    ['a1', a1],
    ['a2', a2],
    [`P(${texMu(mu)})`, at],
  ];
  setChildren(
    digitsBody,
    rows.map(([name, v]) =>
      h('tr', {}, h('td', {}, name), h('td', {}, allDigits(v[0])), h('td', {}, allDigits(v[1]))),
    ),
  );
}

/** The rules' table: rows and buttons built once, so a button keeps focus when clicked. */
function rulesTable(api: LessonApi<QuadraticState>) {
  const rows = (['Uniform', 'Chord length', 'Centripetal'] as const).map((name, k) => {
    const swatch = h('span', { class: 'swatch' });
    const value = h('td', {});
    const use = h('button', { type: 'button' }, `Use ${name.toLowerCase()}`);
    use.addEventListener('click', () => {
      const rule = muRules(api.get().p)[k];
      if (rule.usable) api.set({ ...api.get(), mu: clampMu(rule.mu) });
    });
    const row = h('tr', {}, h('td', {}, swatch, name), value, h('td', {}, use));
    return { row, swatch, value, use };
  });
  return {
    rows: rows.map((r) => r.row),
    update(state: QuadraticState) {
      const palette = api.theme().palette;
      muRules(state.p).forEach((rule, k) => {
        const { row, swatch, value, use } = rows[k];
        const chosen = rule.usable && Math.abs(clampMu(rule.mu) - state.mu) < 1e-12;
        row.className = chosen ? 'current' : '';
        swatch.style.background = state.step === 3 && rule.usable ? palette[k] : 'transparent';
        value.textContent = rule.usable
          ? fmt(rule.mu, 4)
          : `${fmt(rule.mu, 0)}: P1 is an end point, no curve`;
        use.disabled = !rule.usable || chosen;
      });
    },
  };
}

function rulesFormula(box: HTMLElement, p: QuadraticState['p']) {
  const [, chord, centripetal] = muRules(p);
  const first = texNumber(distance(p[0], p[1]), 3);
  const second = texNumber(distance(p[1], p[2]), 3);
  renderFormula(
    box,
    `\\begin{aligned}d_0 &= |P_1 - P_0| = ${first},\\quad d_1 = |P_2 - P_1| = ${second}\\\\ \\text{uniform: } \\mu_1 &= \\tfrac12\\\\ \\text{chord length: } \\mu_1 &= \\frac{d_0}{d_0 + d_1} = ${texNumber(chord.mu, 4)}\\\\ \\text{centripetal: } \\mu_1 &= \\frac{\\sqrt{d_0}}{\\sqrt{d_0} + \\sqrt{d_1}} = ${texNumber(centripetal.mu, 4)}\\end{aligned}`,
    true,
  );
}
