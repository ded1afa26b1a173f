import { h, setChildren } from '../../app/dom';
import type { Point } from '../../app/lesson';
import { radioGroup } from '../../app/panelControls';
import type { PanelApi } from './experimentPanel';
import {
  type ExperimentId,
  MAX_COPIES,
  MAX_ELEVATIONS,
  MAX_SPLITS,
  type MapKind,
  type PropertiesState,
  amount,
  stepFor,
} from './state';

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
  const more = (most: number) => (s: PropertiesState) => ({
    k: stepFor(Math.min(most, amount(s) + 1)),
  });
  const raise = button('Raise the degree', () => change(more(MAX_ELEVATIONS)));
  const original = button('Back to the original degree', () => change(() => ({ k: stepFor(0) })));
  const splitAgain = button('Split every piece', () => change(more(MAX_SPLITS)));
  const unsplit = button('Undo the splits', () => change(() => ({ k: stepFor(0) })));
  const addCopy = button('Add a copy', () => change(more(MAX_COPIES)));
  const removeCopy = button('Remove a copy', () =>
    change((s) => ({ k: stepFor(Math.max(0, amount(s) - 1)) })),
  );
  const repeated = h('select', { id: 'repeated-point', 'aria-label': 'Repeated point' });
  repeated.addEventListener('change', () => change(() => ({ r: Number(repeated.value) })));
  const remember = button('Make this the "before" curve', () =>
    change((s) => ({ q: s.p.map((point): Point => [...point]) })),
  );
  const mapChoice = radioGroup(api, {
    name: 'map',
    choices: MAPS,
    get: (s) => s.m,
    set: (s, m) => ({ ...s, m }),
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
    update(state: PropertiesState) {
      if (state.x !== shownX) {
        shownX = state.x;
        for (const [id, group] of Object.entries(groups))
          group.style.display = id === state.x ? '' : 'none';
      }
      const done = amount(state);
      raise.disabled = done >= MAX_ELEVATIONS;
      original.disabled = done === 0;
      splitAgain.disabled = done >= MAX_SPLITS;
      unsplit.disabled = done === 0;
      addCopy.disabled = done >= MAX_COPIES;
      removeCopy.disabled = done === 0;
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
    },
  };
}
