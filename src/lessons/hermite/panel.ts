import { dataTable, fmt, h, setHidden, setText } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { checkbox, radioGroup } from '../../app/panelControls';
import { LiveFormula, formula } from '../../render/formula';
import { curvatureLink } from '../../kit/lessonLinks';
import { basisLine, bezierPoints, system } from './formulas';
import { joinsSection } from './joins';
import type { HermiteModel } from './model';
import { controlPoints } from './points';
import { construction } from './script';
import type { GradientMode, HermiteState } from './state';

const MODES: [GradientMode, string][] = [
  ['hand', 'By hand: drag the square tips of the arrows'],
  ['catmull-rom', 'From the neighbours (Catmull-Rom): Dₖ = (Pₖ₊₁ − Pₖ₋₁) / 2, zero at both ends'],
];

export function hermitePanel(
  api: LessonApi<HermiteState, HermiteModel>,
): LessonPanel<HermiteState, HermiteModel> {
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
    // The Bézier view is a step of its own: a script shown to its end stays at its end.
    set: (s, on) => {
      const next = { ...s, bezier: on };
      return construction.keptAtEnd(s, next, 'step');
    },
  });
  const pointCount = controlPoints.buttons(api);
  const patchTitle = h('h2', {});
  // Which patch the matrix, the basis and P(μ) are about (the steps build them all in turn).
  const choosePatch = (delta: number) => {
    const s = api.get();
    const patch = Math.min(s.points.length - 2, Math.max(0, s.patch + delta));
    if (patch !== s.patch) api.set({ ...s, patch });
  };
  const previousPatch = h('button', { type: 'button' }, 'Previous patch');
  const nextPatch = h('button', { type: 'button' }, 'Next patch');
  previousPatch.addEventListener('click', () => choosePatch(-1));
  nextPatch.addEventListener('click', () => choosePatch(1));
  const warning = h(
    'p',
    { class: 'warning', role: 'note' },
    'Two points have no neighbours: Catmull-Rom gives both ends a zero gradient, so the patch is a straight segment (with a slow start and a slow finish). Add a point to see the rule at work.',
  );
  const systemFormula = new LiveFormula(true);
  const coefficientsBody = h('tbody', {});
  const coefficients = new LiveRows(coefficientsBody);
  const basisFormula = new LiveFormula(true);
  const weightsBody = h('tbody', {});
  const weights = new LiveRows(weightsBody);
  const bezierFormula = new LiveFormula(true);
  const bezierBody = h('tbody', {});
  const bezierRows = new LiveRows(bezierBody);
  const joins = joinsSection();
  const curvature = curvatureLink();

  const element = h(
    'div',
    { class: 'lesson-text' },
    h(
      'p',
      {},
      'A cubic has four coefficients, so it can match four conditions: where a patch starts and ends, and which way and how fast it leaves and arrives (the gradients). Chain such patches through several points and share the gradient at each point: the curve is smooth at every join. In this lesson the parameter is μ, from 0 to 1 on each patch.',
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
    curvature.element,
    patchTitle,
    h('div', { class: 'lesson-tools' }, previousPatch, nextPatch),
    h('p', {}, 'The four conditions as a matrix, and their solution: the patch matrix.'),
    systemFormula.element,
    dataTable('Coefficients of the patch', ['Coefficient', 'x', 'y'], coefficientsBody),
    h('h2', {}, 'The Hermite basis at μ'),
    basisFormula.element,
    dataTable('Hermite weights at μ', ['Basis', 'Value at μ', 'Weighs'], weightsBody),
    joins.element,
    h('h2', {}, 'The same patch as a Bézier curve'),
    h(
      'p',
      {},
      'A cubic Bézier curve leaves its first control point towards the second with gradient 3(B₁ − B₀). So the Hermite patch is the Bézier curve with B₀ = Pᵢ, B₁ = Pᵢ + Dᵢ/3, B₂ = Pᵢ₊₁ − Dᵢ₊₁/3, B₃ = Pᵢ₊₁: the tips of the arrows are its inner control points. That is the bridge to the next chapter.',
    ),
    bezierFormula.element,
    dataTable('Bézier control points', ['Point', 'x', 'y'], bezierBody),
  );

  return {
    element,
    update(m, state) {
      const { patch } = m;
      const i = patch.index;
      mode.update(state);
      bezier.update(state);
      pointCount.update(state);
      curvature.update({
        src: 'hermite',
        p: state.points,
        d: m.gradients,
        t: (i + state.mu) / m.m,
      });
      setHidden(warning, !m.straight);
      setText(patchTitle, `Patch ${i + 1} of ${m.m}: from P${i} to P${i + 1}`);
      previousPatch.disabled = state.patch <= 0;
      nextPatch.disabled = state.patch >= m.m - 1;

      systemFormula.set(system([patch.p0, patch.p1, patch.d0, patch.d1], patch.coefficients));
      coefficients.set(
        patch.coefficients.map((a, k) => ({ cells: [`a${k}`, fmt(a[0], 4), fmt(a[1], 4)] })),
      );
      basisFormula.set(basisLine(i, state.mu, patch.weights, patch.point));
      const weighs = [`P${i}`, `P${i + 1}`, `D${i}`, `D${i + 1}`];
      weights.set(patch.weights.map((w, k) => ({ cells: [`H${k}`, fmt(w, 4), weighs[k]] })));
      joins.update(m);
      bezierFormula.set(bezierPoints(patch.bezier));
      bezierRows.set(
        patch.bezier.map((q, k) => ({ cells: [`B${k}`, fmt(q[0], 4), fmt(q[1], 4)] })),
      );
    },
  };
}
