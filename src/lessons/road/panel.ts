import { fmt, h, setChildren } from '../../app/dom';
import { checkbox, pointButtons } from '../../app/panelControls';
import { extendPolygon } from '../../interact/editPoints';
import type { DrawInfo, LessonApi, LessonPanel } from '../../app/lesson';
import { bezierToPowerBasis } from '../../math';
import { renderFormula, texNumber } from '../../render/formula';
import { localParameter, primaryRoad } from './figure';
import { methodSection } from './methodPanel';
import { villageNotes } from './notes';
import { solveSection } from './solvePanel';
import { MAX_VILLAGES, type RoadState, insertVillage, keepStepEnd, segmentCount } from './state';
import './road.css';

const LETTERS = ['a', 'b', 'c', 'd'];

export function roadPanel(api: LessonApi<RoadState>): LessonPanel<RoadState> {
  const method = methodSection(api);
  const solve = solveSection();

  const slider = h('input', {
    type: 'range',
    min: 0,
    step: 0.01,
    'aria-label': 'p̄ along the road',
  });
  slider.addEventListener('input', () =>
    api.set({ ...api.get(), s: Number(slider.value) }, { coalesce: 'road-s', windowMs: 1500 }),
  );
  const sliderValue = h('span', {});
  const segmentTitle = h('h2', {});
  const segmentText = h('p', { class: 'note' });
  const segmentFormula = h('div', {});

  const comb = checkbox(api, {
    id: 'road-comb',
    label: 'Curvature comb: teeth across the road as long as its curvature',
    get: (s) => s.comb,
    set: (s, on) => ({ ...s, comb: on }),
  });
  const pointCount = pointButtons(api, {
    addLabel: 'Add a village',
    removeLabel: 'Remove the last village',
    count: (s) => s.v.length,
    min: 2,
    max: MAX_VILLAGES,
    add: (s) => keepStepEnd(s, { ...s, v: insertVillage(s.v, extendPolygon(s.v)) }),
    remove: (s) => keepStepEnd(s, { ...s, v: s.v.slice(0, -1) }),
  });
  const notes = h('div', {});

  const element = h(
    'div',
    { class: 'lesson-text' },
    h(
      'p',
      {},
      'How should one specify the path of a road through a number of villages? Drag the villages (or Tab to one and use the arrow keys), double-click or long-press to add one, right-click or Delete to remove one. Choose how the road is built below, or compare several at once.',
    ),
    notes,
    method.element,
    comb.element,
    pointCount.element,
    method.explanation,
    solve.element,
    h('h2', {}, 'The parameter along the road'),
    h(
      'p',
      { class: 'note' },
      'The road is a parametric curve (x(p̄), y(p̄)). The global parameter p̄ runs from 0 at P0 to m at Pm; segment i is p̄ from i to i + 1, with local parameter p = p̄ − i from 0 to 1. Ticks mark every quarter of p̄: they crowd together on short segments.',
    ),
    h(
      'div',
      { class: 'road-marker' },
      h('span', { 'aria-hidden': 'true' }, 'p̄'),
      slider,
      sliderValue,
    ),
    h(
      'section',
      { 'aria-label': 'Segment coefficients' },
      segmentTitle,
      segmentText,
      segmentFormula,
    ),
  );

  return {
    element,
    update(state: RoadState, info: DrawInfo) {
      method.update(state);
      solve.update(state);
      comb.update(state);
      pointCount.update(state);
      const count = segmentCount(state);
      slider.max = String(count);
      if (Number(slider.value) !== state.s) slider.value = String(state.s);
      const { piece, p } = localParameter(state.s, count);
      sliderValue.textContent = `p̄ = ${fmt(state.s, 2)}: segment ${piece}, p = ${fmt(p, 2)}`;
      updateSegment(state, info, segmentTitle, segmentText, segmentFormula);
      const lines = villageNotes(state);
      setChildren(
        notes,
        lines.map((line) => h('p', { class: 'note', role: 'note' }, line)),
      );
    },
  };
}

/** The coefficients of one segment: the one under the pointer, else the one the marker is on. */
function updateSegment(
  state: RoadState,
  info: DrawInfo,
  title: HTMLElement,
  text: HTMLElement,
  formula: HTMLElement,
): void {
  const road = state.overlay ? null : primaryRoad(state);
  const pieces = road?.kind === 'pieces' ? road.pieces : [];
  if (!pieces.length) {
    title.textContent = 'Coefficients of a segment';
    text.textContent = state.overlay
      ? 'Turn off the comparison to read the coefficients of one road.'
      : 'No segment of this road is drawn yet.';
    renderFormula(formula, '', true);
    return;
  }
  // While the solve is under way only the last pieces exist, newest first.
  const offset = segmentCount(state) - pieces.length;
  const hovered = info.hover?.startsWith('seg') ? Number(info.hover.slice(3)) : NaN;
  const i =
    Number.isInteger(hovered) && hovered < pieces.length
      ? hovered
      : offset > 0
        ? 0
        : localParameter(state.s, pieces.length).piece;
  const index = offset + i;
  const coefficients = bezierToPowerBasis(pieces[i]);
  title.textContent = `Segment ${index}: from P${index} to P${(index + 1) % state.v.length}`;
  text.textContent =
    'Hover over the road, or move p̄, to choose a segment. Its coefficients, with the local parameter p from 0 to 1:';
  const power = (k: number) => (k === 0 ? '' : k === 1 ? '\\,p' : `\\,p^{${k}}`);
  const names = coefficients.map((_, k) => `${LETTERS[k]}_{${index}}${power(k)}`).join(' + ');
  const poly = (d: number) =>
    coefficients
      .map((c, k) => {
        const sign = k === 0 ? '' : c[d] < 0 ? ' - ' : ' + ';
        return `${sign}${texNumber(k === 0 ? c[d] : Math.abs(c[d]), 3)}${power(k)}`;
      })
      .join('');
  renderFormula(
    formula,
    `\\begin{aligned}P(p) &= ${names}\\\\ x(p) &= ${poly(0)}\\\\ y(p) &= ${poly(1)}\\end{aligned}`,
    true,
  );
}
