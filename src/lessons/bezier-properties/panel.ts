import { h, setChildren } from '../../app/dom';
import type { LessonApi, LessonPanel, Point2 } from '../../app/lesson';
import { EXPERIMENTS, PROPERTY_NUMBER } from './experiments';
import {
  MAX_COPIES,
  MAX_ELEVATIONS,
  MAX_SPLITS,
  type MapKind,
  type PropertiesState,
  controlPoints,
} from './state';
import { radioGroup } from '../../app/panelControls';

const MAPS: { value: MapKind; label: string }[] = [
  { value: 'rotate', label: 'Rotation' },
  { value: 'scale', label: 'Scaling' },
  { value: 'shear', label: 'Shear' },
  { value: 'perspective', label: 'Perspective (projective)' },
];

const button = (label: string, onclick: () => void) =>
  h('button', { type: 'button', onclick }, label);

export function propertiesPanel(api: LessonApi<PropertiesState>): LessonPanel<PropertiesState> {
  const change = (f: (s: PropertiesState) => Partial<PropertiesState>) => {
    const s = api.get();
    api.set({ ...s, ...f(s) });
  };
  const title = h('h2', {});
  const sentence = h('p', { class: 'experiment-sentence' });
  const details = h('div', { class: 'experiment-details', 'aria-live': 'off' });

  // Controls stay the same elements across updates, so keyboard focus survives a press.
  const raise = button('Raise the degree', () =>
    change((s) => ({ k: Math.min(MAX_ELEVATIONS, s.k + 1) })),
  );
  const original = button('Back to the original degree', () => change(() => ({ k: 0 })));
  const splitAgain = button('Split every piece', () =>
    change((s) => ({ k: Math.min(MAX_SPLITS, s.k + 1) })),
  );
  const unsplit = button('Undo the splits', () => change(() => ({ k: 0 })));
  const addCopy = button('Add a copy', () => change((s) => ({ k: Math.min(MAX_COPIES, s.k + 1) })));
  const removeCopy = button('Remove a copy', () => change((s) => ({ k: Math.max(0, s.k - 1) })));
  const repeated = h('select', { id: 'repeated-point', 'aria-label': 'Repeated point' });
  repeated.addEventListener('change', () => change(() => ({ r: Number(repeated.value) })));
  const remember = button('Make this the "before" curve', () =>
    change((s) => ({ q: s.p.map((point): Point2 => [point[0], point[1]]) })),
  );
  const mapChoice = radioGroup(api, {
    name: 'map',
    choices: MAPS,
    get: (s) => s.m,
    set: (s, m) => ({ ...s, m }),
  });

  const groups = {
    elevate: h('div', { class: 'lesson-tools' }, raise, original),
    split: h('div', { class: 'lesson-tools' }, splitAgain, unsplit),
    repeat: h(
      'div',
      { class: 'lesson-tools' },
      h('label', { for: 'repeated-point' }, 'Repeat '),
      repeated,
      addCopy,
      removeCopy,
    ),
    local: h('div', { class: 'lesson-tools' }, remember),
    affine: h(
      'fieldset',
      { style: 'border:0;padding:0;margin:0' },
      h('legend', { class: 'visually-hidden' }, 'Map applied'),
      mapChoice.labels,
    ),
  };

  const element = h(
    'div',
    { class: 'lesson-text' },
    title,
    sentence,
    Object.values(groups),
    details,
    h(
      'p',
      { class: 'note' },
      'Each preset sets up one experiment. Drag the control points (or Tab to them and use the arrow keys); t moves the point P(t) and, in subdivision, where the curve is split.',
    ),
  );

  return {
    element,
    update(state) {
      const experiment = EXPERIMENTS[state.x];
      title.textContent = `${PROPERTY_NUMBER[state.x]}. ${experiment.title}`;
      sentence.textContent = experiment.sentence;
      for (const [id, group] of Object.entries(groups)) {
        group.style.display = id === state.x ? '' : 'none';
      }
      raise.disabled = state.k >= MAX_ELEVATIONS;
      original.disabled = state.k === 0;
      splitAgain.disabled = state.k >= MAX_SPLITS;
      unsplit.disabled = state.k === 0;
      addCopy.disabled = state.k >= MAX_COPIES;
      removeCopy.disabled = state.k === 0;
      addCopy.textContent = `Add a copy of P${state.r}`;
      removeCopy.textContent = `Remove a copy of P${state.r}`;
      if (repeated.options.length !== state.p.length) {
        setChildren(
          repeated,
          state.p.map((_, i) => h('option', { value: i }, `P${i}`)),
        );
      }
      repeated.value = String(state.r);
      mapChoice.update(state);
      setChildren(details, experiment.explain(state, api));
      details.dataset.controlPoints = String(controlPoints(state).length);
    },
  };
}
