import { h } from '../../app/dom';
import type { LessonApi } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { checkbox, radioGroup } from '../../app/panelControls';
import { countRows } from './countTable';
import { setHidden, setText } from '../../app/dom';
import { LiveFormula } from '../../render/formula';
import { methodFormula } from './methodFormula';
import { NAMES, TEXT } from './methods';
import type { RoadModel } from './model';
import { CURVES } from './roads';
import { keepShownToEnd, shownToEnd } from './script';
import { ROAD_METHODS, type RoadState } from './state';
import { compared } from './view';

/** Method radio buttons, overlay checkboxes, the method's explanation and the counting panel. */
export function methodSection(api: LessonApi<RoadState, RoadModel>) {
  const methods = radioGroup(api, {
    name: 'road',
    choices: ROAD_METHODS.map((method) => ({ value: method, label: NAMES[method] })),
    get: (s) => s.road,
    // Choosing a method shows its whole road (its last step); the derivation
    // and the global view are of the natural spline, so a choice leaves them.
    set: (s, road) => shownToEnd({ ...s, road, view: compared(s) ? 'compare' : 'road' }),
  });
  const methodList = h(
    'fieldset',
    { class: 'road-methods' },
    h('legend', {}, 'The road is built by'),
    methods.labels,
  );
  const overlay = checkbox(api, {
    id: 'road-overlay',
    label: 'Compare: draw several answers at once',
    get: (s) => compared(s),
    // Switching the overlay shows every answer chosen (its last step), as choosing a method does.
    set: (s, on) => shownToEnd({ ...s, view: on ? 'compare' : 'road' }),
  });
  const compareBoxes = CURVES.map((curve, index) => {
    const box = h('input', { type: 'checkbox', id: `road-compare-${curve.id}` });
    box.addEventListener('change', () => {
      const s = api.get();
      const compare = box.checked ? [...s.compare, index] : s.compare.filter((c) => c !== index);
      api.set(keepShownToEnd(s, { ...s, compare: compare.sort((x, y) => x - y) }));
    });
    const line = h('span', { class: 'road-line', 'aria-hidden': 'true' });
    const why = h('span', { class: 'note' });
    const label = h(
      'label',
      { class: 'toggle', for: box.id },
      box,
      line,
      h('span', {}, curve.name, why),
    );
    return { box, line, why, label, border: '' };
  });
  const compareList = h(
    'fieldset',
    { class: 'road-methods' },
    h('legend', {}, 'Draw side by side'),
    compareBoxes.map((c) => c.label),
  );
  const ends = checkbox(api, {
    id: 'road-ends',
    label: 'Choose the end gradients of the Hermite road (drag D0 and Dm) instead of zero',
    get: (s) => s.ends,
    set: (s, on) => ({ ...s, ends: on }),
  });
  const title = h('h2', {});
  const text = h('p', {});
  const formula = new LiveFormula(true);
  const countBody = h('tbody', {});
  const count = new LiveRows(countBody);
  const countTable = h(
    'table',
    { class: 'data-table road-count', 'aria-label': 'Counting argument' },
    countBody,
  );

  const element = h(
    'section',
    { 'aria-label': 'Method' },
    methodList,
    overlay.element,
    compareList,
  );
  const explanation = h(
    'section',
    { 'aria-label': 'How this road is built' },
    title,
    text,
    ends.element,
    formula.element,
    h('h2', {}, 'Counting the conditions'),
    countTable,
  );

  return {
    element,
    explanation,
    update(model: RoadModel, state: RoadState) {
      const palette = api.theme().palette;
      methods.update(state);
      overlay.update(state);
      setHidden(compareList, !compared(state));
      compareBoxes.forEach((c, index) => {
        c.box.checked = state.compare.includes(index);
        const road = model.overlay.find((curve) => curve.index === index)?.road;
        setText(c.why, road?.kind === 'missing' ? ` (not drawn: ${road.why})` : '');
        const border = `3px ${CURVES[index].dash.length ? 'dashed' : 'solid'} ${palette[index % palette.length]}`;
        if (c.border !== border) c.line.style.borderTop = c.border = border;
      });
      setHidden(ends.element, state.road !== 'hermite');
      ends.update(state);
      setText(title, NAMES[state.road]);
      setText(text, TEXT[state.road]);
      formula.set(methodFormula(model));
      count.set(countRows(model));
    },
  };
}
