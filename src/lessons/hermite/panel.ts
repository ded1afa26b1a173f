import { dataTable, fmt, h, setDisabled, setHidden, setText } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { checkbox, radioGroup } from '../../app/panelControls';
import { LiveFormula, formula, renderFormula } from '../../render/formula';
import { curvatureLink } from '../../kit/lessonLinks';
import { notesKey, notesQuote, notesSlip } from '../../kit/notes';
import {
  basisLine,
  bezierPoints,
  bezierProduct,
  conditions,
  conditionsMatrixByName,
  continuationSystem,
  inverted,
} from './formulas';
import { joinsSection } from './joins';
import type { HermiteModel } from './model';
import { controlPoints } from './points';
import { scriptOf } from './script';
import type { GradientMode, HermiteState } from './state';
import { gestures } from '../../kit/gestures';

/** How this lesson's symbols read in the course's documents. */
const SYMBOLS: [string, string][] = [
  [
    'Dᵢ',
    'the gradient at Pᵢ: P′ᵢ in the lecture notes (equations 6 and 7), Dᵢ in the lecture slides, x′ᵢ in the continuation notes (p′ᵢ in their Catmull-Rom section)',
  ],
  [
    'a₀ … a₃',
    'P = a₃μ³ + a₂μ² + a₁μ + a₀ as in the lecture notes; aᵢ, bᵢ, cᵢ, dᵢ in the lecture slides; d, c, b, a in the continuation notes, which write x(t) = at³ + bt² + ct + d',
  ],
  ['H₀ … H₃', 'the same in the continuation notes: H₀ weighs x₀, H₁ x₁, H₂ x′₀, H₃ x′₁'],
  [
    'B₀ … B₃',
    'the Bézier control points: P₀ … P₃ in the lecture notes’ section “Bezier Curves are Cubic Spline Patches”, x₀ … x₃ in the continuation notes',
  ],
];

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
    // The Bézier view walks its own steps: ticked or cleared, it shows all of them.
    set: (s, on) => {
      const next = { ...s, bezier: on };
      return { ...next, step: scriptOf(next).lastStep(next) };
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
  const conditionsFormula = new LiveFormula(true);
  const matrixFormula = h('div', { class: 'formula display' });
  const inverseFormula = new LiveFormula(true);
  const continuationFormula = new LiveFormula(true);
  const coefficientsBody = h('tbody', {});
  const coefficients = new LiveRows(coefficientsBody);
  const basisFormula = new LiveFormula(true);
  const weightsBody = h('tbody', {});
  const weights = new LiveRows(weightsBody);
  const bezierFormula = new LiveFormula(true);
  const bezierProductFormula = new LiveFormula(true);
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
    notesKey(SYMBOLS),
    h('fieldset', {}, h('legend', {}, 'Gradients Dₖ'), mode.labels),
    h(
      'p',
      { class: 'note' },
      `Each arrow is drawn a third as long as its gradient: its tip is at P + D/3. To set D, take a tip and ${gestures().move}; moving one in Catmull-Rom mode switches to gradients by hand. To add a point after the last, ${gestures().add}; to remove one, ${gestures().remove}. Drag the cursor in the lower plot to move μ.`,
    ),
    bezier.element,
    warning,
    pointCount.element,
    curvature.element,
    patchTitle,
    h('div', { class: 'lesson-tools' }, previousPatch, nextPatch),
    h(
      'p',
      {},
      'At μ = 0 and μ = 1 the ends give four conditions on a₀ … a₃ (the lecture notes, equation 6):',
    ),
    conditionsFormula.element,
    h(
      'p',
      {},
      'As one matrix, with the data in the lecture’s order (point, gradient, next point, next gradient), and inverted to solve for a₀ … a₃ (equation 7):',
    ),
    matrixFormula,
    inverseFormula.element,
    notesSlip(
      'lecture',
      'the data matrices as 4×2 in one sentence and as 2×4 a paragraph later',
      'Each point or gradient is a row here, so the data (Pᵢ, Dᵢ, Pᵢ₊₁, Dᵢ₊₁) and the coefficients a₀ … a₃ are 4 × 2 matrices in 2D (4 × 3 in 3D): eight equations in 2D, twelve in 3D, all with the same 4 × 4 matrix.',
    ),
    dataTable('Coefficients of the patch', ['Coefficient', 'x', 'y'], coefficientsBody),
    h(
      'p',
      {},
      'The continuation notes write the same cubic as ',
      notesQuote('x(t) = at³ + bt² + ct + d'),
      ' and order the data x₀, x₁, x′₀, x′₁ (here Pᵢ, Pᵢ₊₁, Dᵢ, Dᵢ₊₁), so their matrix has its rows and columns in another order. The numbers are the same, last first: a = a₃, b = a₂, c = a₁, d = a₀.',
    ),
    notesQuote(continuationFormula.element),
    h('h2', {}, 'The Hermite basis at μ'),
    basisFormula.element,
    dataTable('Hermite weights at μ', ['Basis', 'Value at μ', 'Weighs'], weightsBody),
    joins.element,
    h('h2', {}, 'The same patch as a Bézier curve'),
    h(
      'p',
      {},
      'A cubic Bézier curve leaves B₀ with gradient 3(B₁ − B₀) and arrives at B₃ with gradient 3(B₃ − B₂). So the Hermite patch is the Bézier curve with B₀ = Pᵢ, B₁ = Pᵢ + Dᵢ/3, B₂ = Pᵢ₊₁ − Dᵢ₊₁/3, B₃ = Pᵢ₊₁. B₁ is the tip of the arrow at Pᵢ; B₂ lies a third of Dᵢ₊₁ behind Pᵢ₊₁, opposite the tip of its arrow, which points on ahead.',
    ),
    bezierFormula.element,
    dataTable('Bézier control points', ['Point', 'x', 'y'], bezierBody),
    h(
      'p',
      {},
      'The other way round (the lecture notes, “Bezier Curves are Cubic Spline Patches”): equation 7 times a Bézier curve’s end points and end gradients gives its coefficients a₀ … a₃, the same numbers as multiplying the curve out (equation 11: a₀ = B₀, a₁ = 3B₁ − 3B₀, a₂ = 3B₂ − 6B₁ + 3B₀, a₃ = B₃ − 3B₂ + 3B₁ − B₀).',
    ),
    bezierProductFormula.element,
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
      setDisabled(previousPatch, state.patch <= 0);
      setDisabled(nextPatch, state.patch >= m.m - 1);

      conditionsFormula.set(conditions(i, patch.data));
      renderFormula(matrixFormula, conditionsMatrixByName(i), true);
      inverseFormula.set(inverted(patch.data, patch.coefficients));
      continuationFormula.set(continuationSystem(patch.data, patch.coefficients));
      coefficients.set(
        patch.coefficients.map((a, k) => ({ cells: [`a${k}`, fmt(a[0], 4), fmt(a[1], 4)] })),
      );
      basisFormula.set(basisLine(i, state.mu, patch.weights, patch.point));
      const weighs = [`P${i}`, `P${i + 1}`, `D${i}`, `D${i + 1}`];
      weights.set(patch.weights.map((w, k) => ({ cells: [`H${k}`, fmt(w, 4), weighs[k]] })));
      joins.update(m);
      bezierFormula.set(bezierPoints(patch.bezier));
      bezierProductFormula.set(bezierProduct(patch.data, patch.coefficients));
      bezierRows.set(
        patch.bezier.map((q, k) => ({ cells: [`B${k}`, fmt(q[0], 4), fmt(q[1], 4)] })),
      );
    },
  };
}
