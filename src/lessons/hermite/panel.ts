import { fmt, fmtPoint, h, setChildren, dataTable } from '../../app/dom';
import { checkbox, pointButtons, radioGroup } from '../../app/panelControls';
import { extendPolygon } from '../../interact/editPoints';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { hermiteMatrix, type Point } from '../../math';
import { formula, renderFormula, texNumber } from '../../render/formula';
import { joins, patchAt } from './model';
import { type GradientMode, type HermiteState, MAX_POINTS, patchCount } from './state';

const MODES: [GradientMode, string][] = [
  ['hand', 'By hand: drag the square tips of the arrows'],
  ['catmull-rom', 'From the neighbours (Catmull-Rom): Dₖ = (Pₖ₊₁ − Pₖ₋₁) / 2, zero at both ends'],
];

const column = (rows: readonly Point[]) =>
  `\\begin{pmatrix}${rows.map((q) => `${texNumber(q[0], 3)} & ${texNumber(q[1], 3)}`).join('\\\\')}\\end{pmatrix}`;

export function hermitePanel(api: LessonApi<HermiteState>): LessonPanel<HermiteState> {
  const mode = radioGroup(api, {
    name: 'mode',
    choices: MODES.map(([value, label]) => ({ value, label })),
    get: (s) => s.mode,
    set: (s, value) => ({ ...s, mode: value }),
  });
  const bezier = checkbox(api, {
    id: 'hermite-bezier',
    label: 'Show each patch as a Bézier curve: control points at P ± D/3',
    get: (s) => s.bezier,
    set: (s, on) => ({ ...s, bezier: on }),
  });
  const pointCount = pointButtons(api, {
    addLabel: 'Add a point',
    removeLabel: 'Remove the last point',
    count: (s) => s.p.length,
    min: 2,
    max: MAX_POINTS,
    add: (s) => {
      const last = s.p[s.p.length - 1];
      const next = extendPolygon(s.p);
      // The new point's gradient follows the new edge.
      return {
        ...s,
        p: [...s.p, next],
        d: [...s.d, [next[0] - last[0], next[1] - last[1]] as const],
      };
    },
    remove: (s) => ({ ...s, p: s.p.slice(0, -1), d: s.d.slice(0, -1) }),
  });
  const patchTitle = h('h2', {});
  const warning = h(
    'p',
    { class: 'warning', role: 'note' },
    'Two points have no neighbours: Catmull-Rom gives both ends a zero gradient, so the patch is a straight segment (with a slow start and a slow finish). Add a point to see the rule at work.',
  );
  const system = h('div', { class: 'formula display' });
  const coefficientsBody = h('tbody', {});
  const basisLine = h('div', { class: 'formula display' });
  const weightsBody = h('tbody', {});
  const bezierBody = h('tbody', {});
  const joinsSection = h('section', {});
  const bezierLine = h('div', { class: 'formula display' });

  const element = h(
    'div',
    { class: 'lesson-text' },
    h(
      'p',
      {},
      'A cubic has four coefficients, so it can match four conditions: where a patch starts and ends, and which way and how fast it leaves and arrives (the gradients). Chain such patches through several points and share the gradient at each point: the curve is smooth at every join.',
    ),
    formula(
      "\\begin{aligned}P(\\mu) &= a_3\\mu^3 + a_2\\mu^2 + a_1\\mu + a_0\\\\ P(0) &= P_i,\\quad P(1) = P_{i+1}\\\\ P'(0) &= D_i,\\quad P'(1) = D_{i+1}\\end{aligned}",
      true,
    ),
    h('fieldset', {}, h('legend', {}, 'Gradients Dₖ'), mode.labels),
    h(
      'p',
      { class: 'note' },
      'Each arrow is drawn a third as long as its gradient: its tip is at P + D/3. Drag a tip (or Tab to it and use the arrow keys) to set D; dragging one in Catmull-Rom mode switches to gradients by hand. Double-click adds a point after the last one, Delete removes one. Drag the cursor in the lower plot to move μ.',
    ),
    bezier.element,
    warning,
    pointCount.element,
    patchTitle,
    h('p', {}, 'Equation 7: the four conditions as a matrix, and their solution.'),
    system,
    dataTable('Coefficients of the patch', ['Coefficient', 'x', 'y'], coefficientsBody),
    h('h2', {}, 'The Hermite basis at μ'),
    basisLine,
    table('Hermite weights at μ', ['Basis', 'Value at μ', 'Weighs'], weightsBody),
    joinsSection,
    h('h2', {}, 'The same patch as a Bézier curve'),
    h(
      'p',
      {},
      'A cubic Bézier curve leaves its first control point towards the second with gradient 3(B₁ − B₀). So the Hermite patch is the Bézier curve with B₀ = Pᵢ, B₁ = Pᵢ + Dᵢ/3, B₂ = Pᵢ₊₁ − Dᵢ₊₁/3, B₃ = Pᵢ₊₁: the tips of the arrows are its inner control points. That is the bridge to the next chapter.',
    ),
    bezierLine,
    table('Bézier control points', ['Point', 'x', 'y'], bezierBody),
  );

  return {
    element,
    update(state) {
      const patch = patchAt(state);
      const i = patch.index;
      const m = patchCount(state);
      mode.update(state);
      bezier.update(state);
      warning.hidden = !(state.mode === 'catmull-rom' && state.p.length === 2);
      pointCount.update(state);
      patchTitle.textContent = `Patch ${i + 1} of ${m}: from P${i} to P${i + 1}`;
      const inverse = hermiteMatrix()
        .map((row) => row.join(' & '))
        .join('\\\\');
      const data = [patch.p0, patch.p1, patch.d0, patch.d1];
      renderFormula(
        system,
        `\\begin{aligned}${column(data)} &= \\begin{pmatrix}1&0&0&0\\\\1&1&1&1\\\\0&1&0&0\\\\0&1&2&3\\end{pmatrix}\\begin{pmatrix}a_0\\\\a_1\\\\a_2\\\\a_3\\end{pmatrix}\\\\ \\begin{pmatrix}a_0\\\\a_1\\\\a_2\\\\a_3\\end{pmatrix} &= \\begin{pmatrix}${inverse}\\end{pmatrix}${column(data)}\\\\ &= ${column(patch.coefficients)}\\end{aligned}`,
        true,
      );
      setChildren(
        coefficientsBody,
        patch.coefficients.map((a, k) =>
          h('tr', {}, h('td', {}, `a${k}`), h('td', {}, fmt(a[0], 4)), h('td', {}, fmt(a[1], 4))),
        ),
      );
      const [h0, h1, h2, h3] = patch.weights.map((w) => texNumber(w, 3));
      renderFormula(
        basisLine,
        `\\begin{aligned}P(${texNumber(state.mu, 3)}) &= H_0 P_{${i}} + H_1 P_{${i + 1}} + H_2 D_{${i}} + H_3 D_{${i + 1}}\\\\ &= ${h0}\\,P_{${i}} + ${h1}\\,P_{${i + 1}} + ${h2}\\,D_{${i}} + ${h3}\\,D_{${i + 1}}\\\\ &= (${texNumber(patch.point[0], 3)},\\ ${texNumber(patch.point[1], 3)})\\end{aligned}`,
        true,
      );
      renderFormula(
        bezierLine,
        `\\begin{aligned}${patch.bezier.map((q, k) => `B_${k} &= (${texNumber(q[0], 2)},\\ ${texNumber(q[1], 2)})`).join('\\\\ ')}\\end{aligned}`,
        true,
      );
      const weighs = [`P${i}`, `P${i + 1}`, `D${i}`, `D${i + 1}`];
      setChildren(
        weightsBody,
        patch.weights.map((w, k) =>
          h('tr', {}, h('td', {}, `H${k}`), h('td', {}, fmt(w, 4)), h('td', {}, weighs[k])),
        ),
      );
      setChildren(
        bezierBody,
        patch.bezier.map((q, k) =>
          h('tr', {}, h('td', {}, `B${k}`), h('td', {}, fmt(q[0], 4)), h('td', {}, fmt(q[1], 4))),
        ),
      );
      updateJoins(joinsSection, state);
    },
  };
}

function table(name: string, headings: string[], body: HTMLElement) {
  return h(
    'table',
    { class: 'data-table', 'aria-label': name },
    h(
      'thead',
      {},
      h(
        'tr',
        {},
        headings.map((text) => h('th', { scope: 'col' }, text)),
      ),
    ),
    body,
  );
}

function updateJoins(section: HTMLElement, state: HermiteState) {
  const list = joins(state);
  if (!list.length) {
    setChildren(
      section,
      h('h2', {}, 'Joins'),
      h('p', {}, 'One patch, no joins yet: add a point to chain a second patch on.'),
    );
    return;
  }
  const onlyC1 = list.filter((join) => join.continuity === 'C1').length;
  setChildren(
    section,
    h('h2', {}, 'Joins'),
    h(
      'p',
      {},
      `Both patches at an inner point use its one gradient, so P′ is the same on both sides: every join is C¹, measured here on the patches. ${onlyC1 ? `The second derivatives differ at ${onlyC1} of ${list.length}: C¹ but not C². A spline that is C² as well is the next step.` : ''}`,
    ),
    dataTable(
      'Joins',
      ['Join', 'P′ before', 'P′ after', 'Continuity'],
      h(
        'tbody',
        {},
        list.map((join) =>
          h(
            'tr',
            {},
            h('td', {}, `P${join.k}`),
            h('td', {}, fmtPoint(join.before, 3)),
            h('td', {}, fmtPoint(join.after, 3)),
            h('td', {}, join.continuity),
          ),
        ),
      ),
    ),
  );
}
