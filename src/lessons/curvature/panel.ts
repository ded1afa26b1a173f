import { dataTable, h, setChildren, setHidden, setText } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { radioGroup } from '../../app/panelControls';
import { notesKey, notesSlip } from '../../kit/notes';
import { formula } from '../../render/formula';
import type { CurvatureModel } from './model';
import { CURVE_SOURCES, type CurveSource } from '../../kit/lessonLinks';
import { SOURCE_NAMES } from './sources';
import { PART_SCRIPTS } from './scripts';
import { SLOPE_STEP } from './curvatureSlope';
import { type CurvatureState, type Part, type SpaceCurve, schema } from './state';
import { arcRows, valueRows } from './values';
import { gestures } from '../../kit/gestures';

const INTRO: Record<Part, string> = {
  plane:
    'Drag the points P0, P1, … and move t. The velocity P′(t) has the curve’s direction; divided by the speed |P′| it is the unit tangent T. The normal N is perpendicular to T, on the side the curve turns to, and the curvature κ says how fast T turns per unit of length: the osculating circle, of radius 1/|κ|, bends exactly as the curve does at P(t).',
  space:
    'In space T turns towards the principal normal N, and the binormal B = T × N completes a right-handed frame. The curvature κ measures how fast T turns, the torsion τ how fast the osculating plane (spanned by T and N) turns about T. Move the control points Q0 … Q3 in space or in the top view. To turn the space figure, ' +
    gestures().orbit +
    '.',
  joins:
    'At a join of two pieces, C² (P′ and P″ the same on both sides) keeps the curvature κ continuous: G², the curvature continuity of the continuation notes. G³ asks one thing more: that κ changes at the same rate on both sides, dκ/ds continuous, with s the arc length. The continuation notes ask “Is C¹ enough?”, answer that car surfaces have to guarantee at least G³, and add that splines of degree n can guarantee Cⁿ⁻¹: cubic pieces give C², so C³ (and with it G³) takes pieces of degree 4 or more. In the plot of κ against p̄ a jump of κ is a step (not G²), a jump of dκ/ds a kink (G², not G³). The lesson takes dκ/ds by one-sided finite differences of κ, with a step h = ' +
    `${SLOPE_STEP} of each piece’s parameter, and divides by the speed |P′|.`,
  arc: 'The parameter t is not length: equal steps of t cover short stretches where the curve is slow and long ones where it is fast. The arc length s(t) adds up the speed; a table of s at equal steps of t, read backwards, gives the parameters of equal steps of length.',
};

/** The curvature vector, as it is (the continuation notes write it as T′(t): see curvatureSlip). */
const CURVATURE_VECTOR = "K = \\frac{dT}{ds} = \\frac{T'(t)}{|P'(t)|} = \\kappa N";

const FORMULAS: Record<Part, string> = {
  // One idea a line: on one line the plane's four ran 467 px in a laptop's 404 px panel.
  plane: `\\begin{gathered}${CURVATURE_VECTOR},\\qquad \\kappa = \\frac{x'y'' - y'x''}{(x'^2 + y'^2)^{3/2}},\\\\ R = \\frac{1}{|\\kappa|},\\qquad \\text{centre} = P + R\\,N\\end{gathered}`,
  space: `\\begin{gathered}${CURVATURE_VECTOR},\\qquad B = T \\times N,\\\\ \\kappa = \\frac{|P' \\times P''|}{|P'|^3},\\qquad \\tau = \\frac{(P' \\times P'') \\cdot P'''}{|P' \\times P''|^2}\\end{gathered}`,
  joins:
    "G^2:\\ \\kappa(\\bar p^-) = \\kappa(\\bar p^+),\\qquad G^3:\\ G^2 \\text{ and } \\tfrac{d\\kappa}{ds}(\\bar p^-) = \\tfrac{d\\kappa}{ds}(\\bar p^+),\\qquad \\frac{d\\kappa}{ds} = \\frac{1}{|P'|}\\frac{d\\kappa}{dp}",
  arc: "s(t) = \\int_0^t |P'(\\xi)|\\,d\\xi,\\qquad t(s_i) = s^{-1}\\!\\left(\\tfrac{i}{n} L\\right)",
};

/**
 * The continuation notes define the curvature vector as K(T) ≔ T′(t), the
 * derivative of T in the parameter; the curvature is its derivative in arc
 * length, dT/ds, which is T′(t) only at unit speed.
 */
const curvatureSlip = () =>
  notesSlip(
    'continuation',
    'the curvature vector as K(T) ≔ T′(t), the derivative of T in the parameter t',
    'The curvature vector is K(t) = dT/ds, the turn of T per unit of arc length s: K = T′(t)/|P′(t)| = κN. Its length is |κ|, so 1/|K| is the radius of the osculating circle, as the notes say; T′(t) itself is |P′(t)| times as long, and equals K only where the speed |P′(t)| is 1.',
  );

/** How the lesson's symbols read in the notes. */
const notesSymbols = () =>
  notesKey([
    ['K = dT/ds = κN', 'K(t), the curvature vector, in the continuation notes'],
    [
      'κ, signed in the plane (> 0 turning left)',
      '‖K(t)‖ in the continuation notes, never negative',
    ],
    ['N, towards the turn', 'N(t) = K(t)/‖K(t)‖ in the continuation notes'],
    ['p̄ = i + p, the global and local parameter of a spline', 'p̄ and p in the lecture slides'],
  ]);

export function curvaturePanel(
  api: LessonApi<CurvatureState, CurvatureModel>,
): LessonPanel<CurvatureState, CurvatureModel> {
  const intro = h('p', {});
  const lectureFormula = h('div', {});
  // Beside the curvature vector's formula, where the notes write it otherwise.
  const slip = curvatureSlip();
  const stepTitle = h('h2', {});
  const why = h('p', { class: 'note', role: 'status' });
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  const arcBody = h('tbody', {});
  const arcTable = new LiveRows(arcBody);
  const values = dataTable('Values at t', ['Quantity', 'Value'], body, 'names lists');
  const table = h(
    'div',
    {},
    h('h2', {}, 'The arc length table'),
    dataTable('Arc length table', ['i', 'tᵢ = i/n', 's(tᵢ)', 'sᵢ = iL/n', 't(sᵢ)'], arcBody),
  );
  const curveChoice = radioGroup<CurvatureState, SpaceCurve>(api, {
    name: 'space-curve',
    choices: [
      { value: 'helix', label: 'Helix (a cos θ, a sin θ, bθ)' },
      { value: 'bezier', label: 'Cubic Bézier with 3D control points' },
    ],
    get: (s) => s.spaceCurve,
    set: (s, spaceCurve) => ({ ...s, spaceCurve }),
  });
  const numberInput = (
    label: string,
    key: 'radius' | 'rise' | 'equalSteps',
    min: number,
    max: number,
    step: number,
  ) => {
    const input = h('input', { type: 'number', min, max, step, 'aria-label': label });
    input.addEventListener('change', () => {
      const value = key === 'equalSteps' ? Math.round(Number(input.value)) : Number(input.value);
      // The link's field checks the range too; here an out-of-range entry is simply not taken.
      if (input.value === '' || !(value >= min && value <= max)) return;
      // The state keeps what the link keeps (ten significant digits), so a link opens this picture.
      const kept = schema[key].decode(schema[key].encode(value));
      if (kept.ok) api.set({ ...api.get(), [key]: kept.value });
    });
    return { element: h('label', { class: 'toggle' }, `${label} `, input), input };
  };
  const a = numberInput('Helix radius a', 'radius', 0.1, 5, 0.05);
  const b = numberInput('Helix rise b per radian', 'rise', -3, 3, 0.05);
  const n = numberInput('Equal steps n', 'equalSteps', 2, 24, 1);
  const spaceControls = h('div', { class: 'lesson-tools' }, ...curveChoice.labels);
  const sourceChoice = radioGroup<CurvatureState, CurveSource>(api, {
    name: 'plane-curve',
    choices: CURVE_SOURCES.map((value) => ({ value, label: SOURCE_NAMES[value] })),
    get: (s) => s.source,
    set: (s, source) => ({ ...s, source }),
  });
  const pieces = h('p', { class: 'note' });
  const notice = h('p', { class: 'note', role: 'status' });
  const sourceControls = h(
    'div',
    {},
    h('h2', {}, 'The plane curve'),
    h('div', { class: 'lesson-tools' }, ...sourceChoice.labels),
    pieces,
    notice,
  );
  const helixControls = h('div', {}, a.element, b.element);

  const element = h(
    'div',
    { class: 'lesson-text' },
    intro,
    lectureFormula,
    slip,
    notesSymbols(),
    h(
      'p',
      { class: 'note' },
      'The parameter is t (slider and Play below the figure; or drag the cursor in the plot).',
    ),
    sourceControls,
    spaceControls,
    helixControls,
    n.element,
    stepTitle,
    why,
    values,
    table,
  );
  let shownPart: Part | null = null;

  return {
    element,
    update(m, state) {
      if (state.part !== shownPart) {
        shownPart = state.part;
        setText(intro, INTRO[state.part]);
        setChildren(lectureFormula, formula(FORMULAS[state.part], true));
      }
      setHidden(slip, state.part === 'arc');
      setHidden(spaceControls, state.part !== 'space');
      setHidden(sourceControls, state.part !== 'plane');
      sourceChoice.update(state);
      if (m.plane) {
        const count = m.plane.pieces.segments.length;
        setText(
          pieces,
          count === 1
            ? `One piece: the plot runs over t ∈ [0, 1].`
            : `${count} pieces, joined at the dots: the plot runs over the global parameter p̄ = ${count}·t ∈ [0, ${count}], piece i for p̄ ∈ [i, i + 1] with local parameter p = p̄ − i (the lecture slides’ p̄ and p). P′ is each piece’s own dP/dp, the same as dP/dp̄. A C² join keeps κ continuous; at a C¹ or G¹ join κ may jump.`,
        );
        setText(notice, m.plane.pieces.notice ?? '');
        setHidden(notice, !m.plane.pieces.notice);
      }
      setHidden(helixControls, state.part !== 'space' || state.spaceCurve !== 'helix');
      setHidden(n.element, state.part !== 'arc');
      curveChoice.update(state);
      for (const [control, value] of [
        [a, state.radius],
        [b, state.rise],
        [n, state.equalSteps],
      ] as const) {
        if (document.activeElement !== control.input) control.input.value = String(value);
      }
      const { k, lastStep } = m.shown;
      const caption = PART_SCRIPTS[state.part].caption(state, m, k);
      setText(stepTitle, `Step ${k} of ${lastStep}: ${caption}`);
      const reason =
        state.part === 'space' ? m.space.at.why : state.part === 'plane' ? m.plane!.at.why : null;
      setText(why, reason ?? '');
      setHidden(why, !reason);
      setHidden(values, state.part === 'arc');
      setHidden(table, state.part !== 'arc');
      if (state.part === 'arc') arcTable.set(arcRows(m));
      else rows.set(valueRows(m, state, api.theme().palette));
    },
  };
}
