import { dataTable, fmt, fmtPoint, h, setChildren, setHidden, setText } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { type Point, snapJoint } from '../../math';
import { renderFormula } from '../../render/formula';
import { type CurvatureOf, curvatureLink } from '../../kit/lessonLinks';
import { verdict } from './drawParts';
import { asCubic, type BezierSplinesModel } from './model';
import { introductions } from './sections';
import { steps } from './script';
import {
  type BezierSplinesState,
  PARTS,
  type Part,
  c2ControlPoints,
  handTangents,
  midpoint,
} from './state';
import { quadraticSplineC1 } from '../../math';

type Api = LessonApi<BezierSplinesState, BezierSplinesModel>;

// The main figure and the 3 × 3 grid share the stage; the part decides which
// is shown (the shell's layout is fixed per lesson, so the lesson hides one).
const LAYOUT_STYLE = `
.lesson-page[data-lesson="bezier-splines"]:has(.bs-panel[data-part="grid"]) .figure[data-figure="main"] { display: none; }
.lesson-page[data-lesson="bezier-splines"]:not(:has(.bs-panel[data-part="grid"])) .figure-grid { display: none; }
`;

const full = (v: number) => String(v);
const joints = (q: readonly Point[]) => q.filter((_, j) => j % 3 === 0);

function quadraticTools() {
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  return {
    element: h(
      'div',
      {},
      h('h3', {}, 'The control points so far'),
      dataTable('Quadratic spline control points', ['i', 'pᵢ', 'bᵢ'], body),
    ),
    update(m: BezierSplinesModel, s: BezierSplinesState) {
      const shown = Math.min(s.step, s.p.length - 1);
      rows.set(
        m.quadraticControls
          .slice(0, shown)
          .map((b, i) => ({ cells: [String(i), fmtPoint(s.p[i]), fmtPoint(b)] })),
      );
    },
  };
}

function systemTools() {
  const matrixHead = h('thead', {});
  const matrixBody = h('tbody', {});
  const matrix = new LiveRows(matrixBody);
  const matrixTable = h(
    'table',
    { class: 'data-table', 'aria-label': 'The linear system' },
    matrixHead,
    matrixBody,
  );
  const solutionBody = h('tbody', {});
  const solution = new LiveRows(solutionBody);
  const residual = h('output', { 'aria-label': 'Residual' });
  const difference = h('output', { 'aria-label': 'Difference from the natural cubic spline' });
  const matrixPart = h(
    'div',
    {},
    h('h3', {}, 'The system A c = r'),
    h('div', { class: 'table-scroll' }, matrixTable),
  );
  const solutionPart = h(
    'div',
    {},
    h('h3', {}, 'Solved'),
    h('p', {}, 'Largest residual |A c − r| of any equation: ', residual),
    h(
      'p',
      {},
      'Largest difference from the natural cubic spline (cubicSplineC2, from naturalCubicDerivatives): ',
      difference,
    ),
    dataTable('Solved control points', ['', 'x', 'y', 'natural x', 'natural y'], solutionBody),
  );
  let size = 0;
  return {
    element: h('div', {}, matrixPart, solutionPart),
    update(m: BezierSplinesModel, s: BezierSplinesState) {
      setHidden(matrixPart, s.step < 6);
      setHidden(solutionPart, s.step < 7);
      const { equations, controls } = m.system;
      if (equations.length !== size) {
        size = equations.length;
        setChildren(
          matrixHead,
          h(
            'tr',
            {},
            h('th', {}, 'row'),
            ...m.names.map((n) => h('th', { scope: 'col' }, n)),
            h('th', {}, 'r x'),
            h('th', {}, 'r y'),
          ),
        );
      }
      matrix.set(
        equations.map((e) => ({
          heading: true,
          cells: [
            e.kind === 'point' ? `p${e.at}` : `${e.kind} ${e.at}`,
            ...e.coefficients.map((v) => (v === 0 ? '·' : String(v))),
            fmt(e.right[0]),
            fmt(e.right[1]),
          ],
        })),
      );
      setText(residual, m.system.residual.toExponential(2));
      setText(difference, m.difference.toExponential(2));
      const natural = [m.natural[0][0], ...m.natural.flatMap((seg) => seg.slice(1))];
      solution.set(
        controls.map((c, j) => ({
          heading: true,
          data: {
            exact: `${full(c[0])},${full(c[1])};${full(natural[j][0])},${full(natural[j][1])}`,
          },
          cells: [
            m.names[j],
            fmt(c[0], 4),
            fmt(c[1], 4),
            fmt(natural[j][0], 4),
            fmt(natural[j][1], 4),
          ],
        })),
      );
    },
  };
}

function inspectorTools(api: Api) {
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  const snaps = h('div', { class: 'button-row' });
  let jointCount = -1;
  const snap = (k: number, mode: 'G1' | 'C1') => () => {
    const s = api.get();
    const j = 3 * k;
    const after = snapJoint(s.q[j - 1], s.q[j], s.q[j + 1], mode);
    api.set({ ...s, q: s.q.map((c, i) => (i === j + 1 ? after : c)), step: Math.max(s.step, 2) });
  };
  const preset = (label: string, make: (q: Point[]) => Point[]) =>
    h(
      'button',
      {
        type: 'button',
        onclick: () => {
          const s = api.get();
          api.set({ ...s, q: make(s.q), step: Math.max(s.step, 2) });
        },
      },
      label,
    );
  const presets = h(
    'div',
    { class: 'button-row' },
    preset('C² spline through the joints', (q) => c2ControlPoints(joints(q))),
    preset('C¹ quadratic spline through the joints', (q) => {
      const p = joints(q);
      const pieces = quadraticSplineC1(p, midpoint(p[0], p[1])).map(asCubic);
      return [p[0], ...pieces.flatMap((piece) => piece.slice(1))];
    }),
    preset('Sharp corner at joint 1', (q) =>
      q.map((c, i) => (i === 2 || i === 4 ? q[3].slice() : c)),
    ),
  );
  return {
    element: h(
      'div',
      {},
      h('h3', {}, 'Every joint'),
      h(
        'div',
        { class: 'table-scroll' },
        dataTable(
          'Continuity at each joint',
          [
            'joint',
            'verdict',
            'P′ left',
            'P′ right',
            'angle',
            'ratio',
            'P″ left',
            'P″ right',
            'κ left',
            'κ right',
          ],
          body,
        ),
      ),
      snaps,
      h('h3', {}, 'Start from'),
      presets,
    ),
    update(m: BezierSplinesModel) {
      if (m.joints.length !== jointCount) {
        jointCount = m.joints.length;
        setChildren(
          snaps,
          m.joints.flatMap((_, i) => [
            h(
              'button',
              { type: 'button', onclick: snap(i + 1, 'G1') },
              `Make G¹ at joint ${i + 1}`,
            ),
            h(
              'button',
              { type: 'button', onclick: snap(i + 1, 'C1') },
              `Make C¹ at joint ${i + 1}`,
            ),
          ]),
        );
      }
      rows.set(
        m.joints.map((r, i) => ({
          heading: true,
          data: { joint: String(i + 1), continuity: r.continuity },
          cells: [
            String(i + 1),
            verdict(r.continuity),
            fmtPoint(r.leftVelocity),
            fmtPoint(r.rightVelocity),
            Number.isNaN(r.angle) ? '—' : `${fmt(r.angle, 1)}°`,
            Number.isFinite(r.lengthRatio) ? fmt(r.lengthRatio, 3) : '—',
            fmtPoint(r.leftSecond),
            fmtPoint(r.rightSecond),
            Number.isNaN(r.leftCurvature) ? '—' : fmt(r.leftCurvature, 3),
            Number.isNaN(r.rightCurvature) ? '—' : fmt(r.rightCurvature, 3),
          ],
        })),
      );
    },
  };
}

function catmullTools(api: Api) {
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  return {
    element: h(
      'div',
      {},
      h('h3', {}, 'Where each one crosses itself'),
      dataTable('Self-intersections of the Catmull-Rom splines', ['α', 'name', 'crossings'], body),
      h(
        'button',
        {
          type: 'button',
          onclick: () => {
            const s = api.get();
            api.set({ ...s, tg: handTangents(s.p) });
          },
        },
        'Reset the hand-set tangents',
      ),
    ),
    update(m: BezierSplinesModel) {
      rows.set(
        m.alphas.map((a) => ({ cells: [String(a.alpha), a.name, String(a.crossings.length)] })),
      );
    },
  };
}

export function bezierSplinesPanel(api: Api): LessonPanel<BezierSplinesState, BezierSplinesModel> {
  const intros = introductions();
  const caption = h('p', { class: 'step-caption' });
  const stepFormula = h('div', { class: 'formula display' });
  const tools: Partial<
    Record<
      Part,
      { element: HTMLElement; update(m: BezierSplinesModel, s: BezierSplinesState): void }
    >
  > = {
    quadratic: quadraticTools(),
    system: systemTools(),
    inspector: inspectorTools(api),
    catmull: catmullTools(api),
  };
  const curvature = curvatureLink();
  const element = h(
    'div',
    { class: 'lesson-text bs-panel' },
    h('style', {}, LAYOUT_STYLE),
    ...PARTS.map((part) => intros[part]),
    h('h3', {}, 'This step'),
    caption,
    stepFormula,
    ...PARTS.map((part) => tools[part]?.element),
    curvature.element,
    h(
      'p',
      { class: 'note' },
      'Step through each part with the buttons or a clicker; drag any point, Tab to a point and move it with the arrow keys; double-click adds a point, Delete removes one.',
    ),
  );
  let tex = '';
  return {
    element,
    update(m, s) {
      element.dataset.part = s.part;
      for (const part of PARTS) {
        setHidden(intros[part], part !== s.part);
        const tool = tools[part];
        if (tool) setHidden(tool.element, part !== s.part);
      }
      setText(caption, steps.describe(s, s.step));
      const next = steps.formula?.(m, s) ?? '';
      if (next !== tex) {
        tex = next;
        setHidden(stepFormula, next === '');
        if (next) renderFormula(stepFormula, next, true);
      }
      tools[s.part]?.update(m, s);
      curvature.update(curvatureOf(s));
    },
  };
}

/** The part's spline as the curvature lesson takes it (none for the quadratic and the grid). */
function curvatureOf(s: BezierSplinesState): CurvatureOf | null {
  if (s.part === 'system') return { src: 'natural', p: s.p };
  if (s.part === 'inspector') return { src: 'chain', p: s.q };
  if (s.part === 'catmull')
    return { src: 'hermite', p: s.p, d: s.tg.length === s.p.length ? s.tg : handTangents(s.p) };
  return null;
}
