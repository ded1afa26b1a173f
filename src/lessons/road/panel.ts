import { notesKey } from '../../kit/notes';
import { fmt, h, setChildren } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { checkbox } from '../../app/panelControls';
import { rangeField } from '../../app/rangeControls';
import { type CurvatureOf, curvatureLink } from '../../kit/lessonLinks';
import { derivationSection } from './derivationPanel';
import { globalSection } from './globalPanel';
import { methodSection } from './methodPanel';
import type { RoadModel } from './model';
import { segmentSection } from './segmentPanel';
import { solveSection } from './solvePanel';
import { villagePoints } from './points';
import { type RoadState, segmentCount } from './state';
import './road.css';
import { gestures } from '../../kit/gestures';

export function roadPanel(api: LessonApi<RoadState, RoadModel>): LessonPanel<RoadState, RoadModel> {
  const method = methodSection(api);
  const solve = solveSection();
  const derivation = derivationSection();
  const global = globalSection();
  const segment = segmentSection();

  const marker = rangeField(api, {
    label: 'p̄ along the road',
    name: 'p̄',
    min: 0,
    max: 1,
    step: 0.01,
    maxOf: (s) => segmentCount(s),
    get: (s) => s.pBar,
    set: (s, pBar) => ({ ...s, pBar }),
    coalesce: 'road-s',
    readout: true,
  });

  const comb = checkbox(api, {
    id: 'road-comb',
    label: 'Curvature comb: teeth across the road as long as its curvature',
    get: (s) => s.comb,
    set: (s, on) => ({ ...s, comb: on }),
  });
  const pointCount = villagePoints.buttons(api);
  const notes = h('div', {});
  let shownNotes: readonly string[] = [];
  let hover: string | null = null;

  const curvature = curvatureLink();
  const element = h(
    'div',
    { class: 'lesson-text' },
    h(
      'p',
      {},
      `How should one specify the path of a road through a number of villages? To move a village, ${gestures().move}; to add one, ${gestures().add}; to remove one, ${gestures().remove}. Choose how the road is built below, or compare several at once.`,
    ),
    notes,
    derivation.element,
    global.element,
    method.element,
    comb.element,
    pointCount.element,
    curvature.element,
    method.explanation,
    solve.element,
    h('h2', {}, 'The parameter along the road'),
    h(
      'p',
      { class: 'note' },
      'The road is a parametric curve (x(p̄), y(p̄)). The global parameter p̄ runs from 0 at P0 to m at Pm; segment i is p̄ from i to i + 1, with local parameter p = p̄ − i from 0 to 1. Ticks mark every quarter of p̄: they crowd together on short segments.',
    ),
    marker.element,
    segment.element,
    notesKey([
      [
        'P₀ … Pₘ, the villages',
        'the same in the lecture slides; x₀ … xₙ, the control points, in the continuation notes’ natural cubic splines',
      ],
      [
        'p̄, p',
        'p̄ and p in the lecture slides (the global and the local parameter); t in the continuation notes',
      ],
      ['Dᵢ', 'Dᵢ, the gradient at Pᵢ, in the lecture slides; x′ᵢ in the continuation notes'],
      [
        'a, b, c, d',
        'y = a + bp + cp² + dp³ in the lecture slides; the continuation notes use Bézier control points instead',
      ],
    ]),
  );

  return {
    element,
    update(m, state) {
      method.update(m, state);
      solve.update(m);
      derivation.update(m);
      global.update(m);
      comb.update(state);
      pointCount.update(state);
      curvature.update(roadCurve(m, state));
      const { piece, p } = m.along;
      marker.update(state, `p̄ = ${fmt(state.pBar, 2)}: segment ${piece}, p = ${fmt(p, 2)}`);
      segment.update(m, hover);
      // The list of notes changes only when the villages' oddities do.
      if (m.notes.join('\n') !== shownNotes.join('\n')) {
        shownNotes = m.notes;
        setChildren(
          notes,
          m.notes.map((line) => h('p', { class: 'note', role: 'note' }, line)),
        );
      }
    },
    hover(id) {
      hover = id;
      segment.update(api.model(), hover);
    },
  };
}

/** The road as the curvature lesson takes it: natural, or Hermite with the method's gradients. */
function roadCurve(m: RoadModel, state: RoadState): CurvatureOf | null {
  const t = state.pBar / Math.max(1, state.villages.length - 1);
  if (state.road === 'natural') return { src: 'natural', p: state.villages, t };
  if ((state.road === 'hermite' || state.road === 'clamped') && m.gradients)
    return { src: 'hermite', p: state.villages, d: m.gradients, t };
  return null;
}
