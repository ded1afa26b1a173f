import { dataTable, fmtPoint, h, setHidden, setText } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { renderFormula } from '../../render/formula';
import { type CurvatureOf, curvatureLink } from '../../kit/lessonLinks';
import { checkTools, datasetDownloads } from './checkTools';
import { inspectorTools } from './inspectorTools';
import type { BezierSplinesModel } from './model';
import { scripts } from './script';
import { introductions } from './sections';
import { type BezierSplinesState, PARTS, type Part, handTangents } from './state';
import { systemTools } from './systemTools';
import { gestures } from '../../kit/gestures';

type Api = LessonApi<BezierSplinesState, BezierSplinesModel>;

interface Tools {
  element: HTMLElement;
  update(m: BezierSplinesModel): void;
}

function quadraticTools(): Tools {
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  return {
    element: h(
      'div',
      {},
      h('h3', {}, 'The control points so far'),
      dataTable('Quadratic spline control points', ['i', 'pᵢ', 'bᵢ'], body),
    ),
    update(m) {
      // The first piece's b₀, then one bᵢ per mirror step.
      const shown = m.shown.has('firstPiece') ? 1 + m.shown.count('mirror') : 0;
      rows.set(
        m.quadraticControls
          .slice(0, shown)
          .map((b, i) => ({ cells: [String(i), fmtPoint(m.state.points[i]), fmtPoint(b)] })),
      );
    },
  };
}

function catmullTools(api: Api): Tools {
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
            api.set({ ...s, tangents: handTangents(s.points) });
          },
        },
        'Reset the hand-set tangents',
      ),
    ),
    update(m) {
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
  const tools: Partial<Record<Part, Tools>> = {
    quadratic: quadraticTools(),
    system: systemTools(),
    inspector: inspectorTools(api),
    catmull: catmullTools(api),
    grid: {
      element: h('div', {}, h('h3', {}, 'The datasets'), datasetDownloads(api)),
      update: () => undefined,
    },
    worked: checkTools(api),
  };
  const curvature = curvatureLink();
  const element = h(
    'div',
    { class: 'lesson-text bs-panel' },
    ...PARTS.map((part) => intros[part]),
    h('h3', {}, 'This step'),
    caption,
    stepFormula,
    ...PARTS.map((part) => tools[part]?.element),
    curvature.element,
    h(
      'p',
      { class: 'note' },
      `Step through each part with Back and Next (or a clicker). To move a point, ${gestures().move}; to add one, ${gestures().add}; to remove one, ${gestures().remove}.`,
    ),
  );
  let tex = '';
  return {
    element,
    update(m, s) {
      for (const part of PARTS) {
        setHidden(intros[part], part !== s.part);
        const tool = tools[part];
        if (tool) setHidden(tool.element, part !== s.part);
      }
      const script = scripts[s.part];
      setText(caption, script.caption(s, m, s.step));
      const next = script.formula(s, m, s.step, true) ?? '';
      if (next !== tex) {
        tex = next;
        setHidden(stepFormula, next === '');
        if (next) renderFormula(stepFormula, next, true);
      }
      tools[s.part]?.update(m);
      curvature.update(curvatureOf(s));
    },
  };
}

/** The part's spline as the curvature lesson takes it (none for the quadratic and the grid). */
function curvatureOf(s: BezierSplinesState): CurvatureOf | null {
  const { points: p, tangents } = s;
  if (s.part === 'system') return { src: 'natural', p };
  if (s.part === 'inspector') return { src: 'chain', p: s.handBuilt };
  if (s.part === 'catmull')
    return { src: 'hermite', p, d: tangents.length === p.length ? tangents : handTangents(p) };
  return null;
}
