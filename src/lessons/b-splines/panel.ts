import { dataTable, h, setHidden, setText } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { type Point, pointsShape } from '../../math';
import { LiveFormula, formula } from '../../render/formula';
import { curvatureLink } from '../../kit/lessonLinks';
import { facts } from './facts';
import { closedSlip, notesSymbols } from './notes';
import { knotControls } from './knotControls';
import { slotNumbers } from '../../render/formulaParts';
import type { BSplineModel } from './model';
import { segmentButtons } from './segmentButtons';
import { scriptOf } from './scripts';
import { type BSplineState, isRationalPart, isUniformPart } from './state';
import { TEXTS } from './texts';
import { triangleTable } from './triangleTable';
import { weightSliders } from './weightSliders';

const MATRIX =
  'Q_i(t) = \\begin{bmatrix}1 & t & t^2 & t^3\\end{bmatrix}\\,\\frac16\\begin{bmatrix}1 & 4 & 1 & 0\\\\ -3 & 0 & 3 & 0\\\\ 3 & -6 & 3 & 0\\\\ -1 & 3 & -3 & 1\\end{bmatrix}\\begin{bmatrix}P_{i-3}\\\\ P_{i-2}\\\\ P_{i-1}\\\\ P_i\\end{bmatrix}';
const RECURSION =
  'N_{i,r}(u) = \\frac{u - u_i}{u_{i+r} - u_i}\\,N_{i,r-1}(u) + \\frac{u_{i+r+1} - u}{u_{i+r+1} - u_{i+1}}\\,N_{i+1,r-1}(u)';

/** What a B-spline makes of control points on one spot or on one line, or null. */
export function shapeSentence(p: readonly Point[]): string | null {
  switch (pointsShape(p).kind) {
    case 'one spot':
      return 'All control points are on one spot: every segment blends four copies of it, so the curve is that single point.';
    case 'one line':
      return 'The control points lie on one line: every segment blends four points of it, so the curve stays on that line.';
    default:
      return null;
  }
}

export function bsplinePanel(
  api: LessonApi<BSplineState, BSplineModel>,
): LessonPanel<BSplineState, BSplineModel> {
  const title = h('h2', {});
  const text = h('p', {});
  // The slides' closed spline, beside the lesson's (the closed scene only).
  const slip = closedSlip();
  const stepLine = h('p', { class: 'note' });
  // Degenerate control points, said in words (the figure alone shows a dot or a line).
  const shapeNote = h('p', { class: 'note' });
  // The step's formula: its shape typeset once, its numbers (u, N, P(u)) written as text.
  const stepFormula = new LiveFormula(true);
  const stepBox = h('div', { class: 'step-formulas' }, stepFormula.element);
  const matrix = formula(MATRIX, true);
  const recursion = formula(RECURSION, true);
  const segments = segmentButtons(api);
  const before = h('button', { type: 'button' }, 'Take this curve as the new “before”');
  before.addEventListener('click', () =>
    api.set({ ...api.get(), before: api.get().points.map((p) => [...p]) }),
  );
  const localTools = h('div', { class: 'lesson-tools' }, before);
  const knots = knotControls(api);
  const weights = weightSliders(api);
  const triangle = triangleTable();
  const factBody = h('tbody', {});
  const factRows = new LiveRows(factBody);
  const curvature = curvatureLink();
  const element = h(
    'div',
    { class: 'lesson-text' },
    title,
    text,
    slip,
    h(
      'p',
      { class: 'note' },
      'The slider t moves the cursor along the whole curve, from its start (0) to its end (1): s = (m − 2)·t in the uniform cubic, u = u(p) + t·(u(m+1) − u(p)) on a knot vector.',
    ),
    notesSymbols(),
    stepLine,
    shapeNote,
    stepBox,
    matrix,
    recursion,
    segments.element,
    localTools,
    knots.element,
    weights.element,
    triangle.element,
    curvature.element,
    h('h2', {}, 'Numbers'),
    dataTable('Numbers of the curve', ['Quantity', 'Value'], factBody, 'names lists'),
  );
  let shownPart = '';
  /** The points the shape note was written for: t and the step leave them alone. */
  let shownPoints: readonly Point[] | null = null;

  return {
    element,
    update(m, state) {
      const { part } = state;
      if (part !== shownPart) {
        shownPart = part;
        setText(title, TEXTS[part].title);
        setText(text, TEXTS[part].text);
        setHidden(slip, part !== 'closed');
        setHidden(matrix, !isUniformPart(part));
        setHidden(recursion, isUniformPart(part));
        setHidden(localTools, part !== 'local');
        // The continuity scene's steps set the degree and the knots themselves.
        setHidden(knots.element, isUniformPart(part) || part === 'continuity');
        setHidden(weights.element, !isRationalPart(part));
      }
      if (state.points !== shownPoints) {
        shownPoints = state.points;
        const note = shapeSentence(state.points);
        setHidden(shapeNote, note === null);
        if (note !== null) setText(shapeNote, note);
      }
      const script = scriptOf(state);
      const caption = script.caption(state, m, state.step);
      setText(stepLine, `Step ${state.step} of ${m.shown.lastStep}: ${caption}`);
      const tex = script.formula(state, m, state.step, true);
      setHidden(stepBox, tex === null);
      if (tex !== null) stepFormula.set(slotNumbers(tex));
      segments.update(m, state);
      knots.update(state);
      weights.update(state);
      triangle.update(m, state, api.theme().palette);
      factRows.set(facts(m));
      curvature.update(
        part === 'uniform' ? { src: 'b-spline', p: state.points, t: state.t } : null,
      );
    },
    hover(id) {
      segments.hover(id);
    },
  };
}
