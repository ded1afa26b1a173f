import { h } from '../../app/dom';
import type { LessonApi } from '../../app/lesson';
import { closedCubicSystem, constraintCount } from '../../math';
import { renderFormula, texNumber, texPoint } from '../../render/formula';
import { CURVES, buildRoad, quadraticControl } from './roads';
import { ROAD_METHODS, type RoadMethod, type RoadState, keepStepEnd, stepCount } from './state';
import { checkbox, radioGroup } from '../../app/panelControls';

const NAMES: Record<RoadMethod, string> = {
  roman: 'Roman road: straight segments',
  quadratic: 'Quadratic pieces, one chosen gradient',
  hermite: 'Cubic Hermite, parabola gradients',
  natural: 'Natural cubic spline',
  clamped: 'Clamped ends: joining other roads',
  ring: 'Ring road: a closed spline',
};

/** Degree and smoothness of each method, for the counting argument. */
const SHAPE: Record<RoadMethod, { degree: number; continuity: number; closed: boolean }> = {
  roman: { degree: 1, continuity: 0, closed: false },
  quadratic: { degree: 2, continuity: 1, closed: false },
  hermite: { degree: 3, continuity: 1, closed: false },
  natural: { degree: 3, continuity: 2, closed: false },
  clamped: { degree: 3, continuity: 2, closed: false },
  ring: { degree: 3, continuity: 2, closed: true },
};

const TEXT: Record<RoadMethod, string> = {
  roman:
    'Each segment is a straight line from village to village. The road is continuous, but its direction jumps at every inner village: a traveller turns on the spot. Good enough for a legion, not for a carriage.',
  quadratic:
    'Fit one quadratic per segment. The first needs a gradient at P0: drag the square B0 = P0 + D0/2. Its gradient at P1 fixes the next quadratic, and so on: the whole road is fixed by that one choice. Each control point is the last one reflected in the village, B(i+1) = 2P(i+1) − Bi (dashed polygon), so a poor choice is handed on and the road swings from side to side. This is the C¹ quadratic Bézier spline with first control point B0.',
  hermite:
    'Cubic pieces with a gradient chosen at each village: the gradient at Pi of the parabola through P(i−1), Pi, P(i+1), which is half the chord between the neighbours (arrows). At the ends the notes take zero gradient; you can choose them instead. The joins are C¹: same position and gradient, but the curvature jumps (turn on the comb).',
  natural:
    'Ask for more: at every inner village the two cubics meet with the same position, gradient and second derivative (C²). Counting leaves two conditions free; the natural spline takes the second derivative zero at both ends. The gradients D0 … Dm then solve a tridiagonal system, once for x and once for y.',
  clamped:
    'The road must join existing roads at P0 and Pm at a given angle: drag the squares D0 and Dm (arrows show D/3). The gradients there are given instead of zero curvature, so the first and last rows of the system become [1 | D0] and [1 | Dm].',
  ring: 'A ring road through every village and back to P0: one more segment, from Pm to P0, and every village is an inner join with C² continuity. No ends, so no end conditions: every row is [1 4 1] and the rows wrap round (a cyclic system, still solved in O(m) by two tridiagonal solves).',
};

/** Method radio buttons, overlay checkboxes, the method's explanation and the counting panel. */
export function methodSection(api: LessonApi<RoadState>) {
  const methods = radioGroup(api, {
    name: 'road',
    choices: ROAD_METHODS.map((method) => ({ value: method, label: NAMES[method] })),
    get: (s) => s.road,
    set: (s, road) => keepStepEnd(s, { ...s, road, step: stepCount({ ...s, road }) }),
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
    get: (s) => s.overlay,
    set: (s, on) => ({ ...s, overlay: on }),
  });
  const compareBoxes = CURVES.map((curve, index) => {
    const box = h('input', { type: 'checkbox', id: `road-compare-${curve.id}` });
    box.addEventListener('change', () => {
      const s = api.get();
      const compare = box.checked ? [...s.compare, index] : s.compare.filter((c) => c !== index);
      api.set({ ...s, compare: compare.sort((x, y) => x - y) });
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
    return { box, line, why, label };
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
  const formula = h('div', {});
  const countTitle = h('h2', {}, 'Counting the conditions');
  const countBody = h('tbody', {});
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
    formula,
    countTitle,
    countTable,
  );

  return {
    element,
    explanation,
    update(state: RoadState) {
      const palette = api.theme().palette;
      methods.update(state);
      overlay.update(state);
      compareList.hidden = !state.overlay;
      compareBoxes.forEach((c, index) => {
        c.box.checked = state.compare.includes(index);
        const road = state.overlay && c.box.checked ? buildRoad(CURVES[index].id, state) : null;
        c.why.textContent = road?.kind === 'missing' ? ` (not drawn: ${road.why})` : '';
        c.line.style.borderTop = `3px ${CURVES[index].dash.length ? 'dashed' : 'solid'} ${palette[index % palette.length]}`;
      });
      ends.element.hidden = state.road !== 'hermite';
      ends.update(state);
      title.textContent = NAMES[state.road];
      text.textContent = TEXT[state.road];
      renderFormula(formula, methodFormula(state), true);
      fillCount(countBody, state);
    },
  };
}

/** The method's defining formula with the current numbers where it has some. */
function methodFormula(state: RoadState): string {
  const v = state.v;
  const m = v.length - 1;
  switch (state.road) {
    case 'roman':
      return 'P(\\bar p) = (1-p)\\,P_i + p\\,P_{i+1},\\quad i = \\lfloor \\bar p \\rfloor,\\ p = \\bar p - i';
    case 'quadratic': {
      const road = buildRoad('quadratic', state);
      const controls = road.kind === 'pieces' ? road.pieces.map((piece) => piece[1]) : [];
      const shown = controls
        .slice(1, 3)
        .map((b, k) => `B_{${k + 1}} &= 2P_{${k + 1}} - B_{${k}} = ${texPoint(b, 2)}`);
      const lines = [
        `D_0 &= ${texPoint(state.q, 2)}`,
        `B_0 &= P_0 + \\tfrac12 D_0 = ${texPoint(quadraticControl(state), 2)}`,
        ...shown,
      ];
      return `\\begin{aligned}${lines.join('\\\\ ')}${controls.length > 3 ? '\\\\ &\\ \\vdots' : ''}\\end{aligned}`;
    }
    case 'hermite':
      return `D_i = \\tfrac12\\,(P_{i+1} - P_{i-1}),\\qquad D_0 = ${state.ends ? texPoint(state.a, 2) : '0'},\\ D_{${m}} = ${state.ends ? texPoint(state.b, 2) : '0'}`;
    case 'natural':
      return `\\begin{aligned}P''(0) = 0:&\\quad 2D_0 + D_1 = 3(P_1 - P_0)\\\\ P''(${m}) = 0:&\\quad D_{${m - 1}} + 2D_{${m}} = 3(P_{${m}} - P_{${m - 1}})\\end{aligned}`;
    case 'clamped':
      return `D_0 = ${texPoint(state.a, 2)},\\quad D_{${m}} = ${texPoint(state.b, 2)}`;
    case 'ring': {
      if (v.length < 3) return '\\text{needs at least three villages}';
      const rhs = closedCubicSystem(v.map((p) => p[0])).rhs[0];
      return `D_{${m}} + 4D_0 + D_1 = 3(P_1 - P_{${m}}),\\quad \\text{for } x:\\ ${texNumber(rhs, 2)}`;
    }
  }
}

function fillCount(body: HTMLElement, state: RoadState): void {
  const shape = SHAPE[state.road];
  const villages = state.v.length;
  if (shape.closed && villages < 3) {
    body.replaceChildren(h('tr', {}, h('td', {}, 'A ring road needs at least three villages.')));
    return;
  }
  const c = constraintCount(villages, shape.degree, shape.continuity, shape.closed);
  const k = shape.degree + 1;
  const perJoin = 2 + shape.continuity;
  const joins = shape.closed ? 'villages' : 'inner villages';
  const why =
    state.road === 'roman'
      ? 'nothing left to choose'
      : state.road === 'quadratic'
        ? 'the gradient at P0'
        : state.road === 'hermite'
          ? 'a gradient at every village (from the parabolas)'
          : state.road === 'natural'
            ? 'P″ = 0 at both ends'
            : state.road === 'clamped'
              ? 'the gradients at both ends'
              : 'nothing: a ring has no ends';
  const rows: [string, string][] = [
    [`Segments${shape.closed ? ' (m + 1, closed)' : ' m'}`, `${c.segments}`],
    [`Unknowns: ${k} coefficients per segment`, `${k}·${c.segments} = ${c.unknowns}`],
    [
      `${perJoin} conditions at each of the ${c.inner / perJoin || 0} ${joins} (position twice${shape.continuity >= 1 ? ', gradient' : ''}${shape.continuity >= 2 ? ', 2nd derivative' : ''})`,
      `${c.inner}`,
    ],
    ['Positions at the two ends', `${c.ends}`],
    [`Left to choose: ${why}`, `${c.free}`],
  ];
  body.replaceChildren(
    ...rows.map(([label, value]) => h('tr', {}, h('td', {}, label), h('td', {}, value))),
  );
}
