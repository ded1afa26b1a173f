import { h, setChildren, setDisabled, setText } from '../../app/dom';
import type { Point } from '../../app/lesson';
import { radioGroup } from '../../app/panelControls';
import type { PanelApi } from './experimentPanel';
import type { PropertiesModel } from './model';
import { scriptOf } from './scripts';
import {
  type ExperimentId,
  MAX_COPIES,
  MAX_ELEVATIONS,
  MAX_SPLITS,
  type MapKind,
  type PropertiesState,
} from './state';

/** The step each experiment repeats, once per elevation, split or copy. */
const REPEATED = { elevate: 'elevation', split: 'split', repeat: 'copy' } as const;

/** Elevations, splits or copies the steps so far show (none in other experiments). */
function done(m: PropertiesModel): number {
  if (m.kind === 'elevate') return m.shown.count('elevation');
  if (m.kind === 'split') return m.shown.count('split');
  if (m.kind === 'repeat') return m.shown.count('copy');
  return 0;
}

/** The step that shows `count` elevations, splits or copies: the curve alone for none. */
function stepShowing(state: PropertiesState, count: number): number {
  const script = scriptOf(state);
  const name = REPEATED[state.experiment as keyof typeof REPEATED];
  return count === 0 ? script.stepOf(state, 'curve') : script.stepOf(state, name, count);
}

const MAPS: { value: MapKind; label: string }[] = [
  { value: 'rotate', label: 'Rotation' },
  { value: 'scale', label: 'Scaling' },
  { value: 'shear', label: 'Shear' },
  { value: 'perspective', label: 'Perspective (projective)' },
];

const button = (label: string, onclick: () => void) =>
  h('button', { type: 'button', onclick }, label);

/**
 * The controls some experiments have of their own (raise the degree, split,
 * repeat a point, keep a "before" curve, choose a map): made once, so keyboard
 * focus survives a press; only the experiment's own group is shown.
 */
export function experimentTools(api: PanelApi) {
  const change = (f: (s: PropertiesState) => Partial<PropertiesState>) => {
    const s = api.get();
    api.set({ ...s, ...f(s) });
  };
  // Each press is one step of the experiment: one elevation, split or copy more or less.
  const showing = (count: (now: number) => number) => () =>
    change((s) => ({ step: stepShowing(s, count(done(api.model()))) }));
  const raise = button(
    'Raise the degree',
    showing((now) => Math.min(MAX_ELEVATIONS, now + 1)),
  );
  const original = button(
    'Back to the original degree',
    showing(() => 0),
  );
  const splitAgain = button(
    'Split every piece',
    showing((now) => Math.min(MAX_SPLITS, now + 1)),
  );
  const unsplit = button(
    'Undo the splits',
    showing(() => 0),
  );
  const addCopy = button(
    'Add a copy',
    showing((now) => Math.min(MAX_COPIES, now + 1)),
  );
  const removeCopy = button(
    'Remove a copy',
    showing((now) => Math.max(0, now - 1)),
  );
  const repeated = h('select', { id: 'repeated-point', 'aria-label': 'Repeated point' });
  repeated.addEventListener('change', () => change(() => ({ repeated: Number(repeated.value) })));
  const remember = button('Make this the "before" curve', () =>
    change((s) => ({ before: s.points.map((point): Point => [...point]) })),
  );
  const mapChoice = radioGroup(api, {
    name: 'map',
    choices: MAPS,
    get: (s) => s.map,
    set: (s, map) => ({ ...s, map }),
  });

  const groups: Partial<Record<ExperimentId, HTMLElement>> = {
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
  let shownX: ExperimentId | null = null;

  return {
    elements: Object.values(groups),
    update(m: PropertiesModel, state: PropertiesState) {
      if (state.experiment !== shownX) {
        shownX = state.experiment;
        for (const [id, group] of Object.entries(groups))
          group.style.display = id === state.experiment ? '' : 'none';
      }
      const count = done(m);
      setDisabled(raise, count >= MAX_ELEVATIONS);
      setDisabled(original, count === 0);
      setDisabled(splitAgain, count >= MAX_SPLITS);
      setDisabled(unsplit, count === 0);
      setDisabled(addCopy, count >= MAX_COPIES);
      setDisabled(removeCopy, count === 0);
      setText(addCopy, `Add a copy of P${state.repeated}`);
      setText(removeCopy, `Remove a copy of P${state.repeated}`);
      if (repeated.options.length !== state.points.length) {
        setChildren(
          repeated,
          state.points.map((_, i) => h('option', { value: i }, `P${i}`)),
        );
      }
      repeated.value = String(state.repeated);
      mapChoice.update(state);
    },
  };
}
