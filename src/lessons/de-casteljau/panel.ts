import { dataTable, fmt, h, setChildren } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { checkbox, pointButtons } from '../../app/panelControls';
import { extendPolygon } from '../../interact/editPoints';
import { LiveFormula, SLOT, formula, slotPoint, texNumber } from '../../render/formula';
import type { DeCasteljauModel } from './model';
import { type DeCasteljauState, MAX_POINTS, degree } from './state';

/** t as typed: up to four decimals, trailing zeros dropped. */
const texT = (t: number) => String(Number(t.toFixed(4)));
const coords = (p: readonly number[]) => p.map((v) => texNumber(v, 3));

/** P_{r,i} = (1−t)·P_{r−1,i} + t·P_{r−1,i+1} = P, with live numbers. */
const levelShape = (r: number, i: number) =>
  `\\begin{aligned}P_{${r},${i}} &= ${SLOT}\\cdot${slotPoint()} + ${SLOT}\\cdot${slotPoint()}\\\\ &= ${slotPoint()}\\end{aligned}`;

export function deCasteljauPanel(
  api: LessonApi<DeCasteljauState, DeCasteljauModel>,
): LessonPanel<DeCasteljauState, DeCasteljauModel> {
  const stepTitle = h('h2', {});
  const stepText = h('p', {});
  const stepFormulas = h('div', { class: 'step-formulas' });
  // One live formula per point of a level (at most n of them), typeset when its shape changes.
  const levelFormulas: LiveFormula[] = [];
  const check = new LiveFormula(true);
  const split = checkbox(api, {
    id: 'split-toggle',
    label: 'Show subdivision at t: the two halves of the curve and their control polygons',
    get: (s) => s.split,
    set: (s, on) => ({ ...s, split: on }),
  });
  const splitInfo = h('div', { class: 'split-info' });
  const leftTitle = h('p', {});
  const rightTitle = h('p', {});
  const leftPoints = new LiveFormula(true);
  const rightPoints = new LiveFormula(true);
  const leftSwatch = h('span', { class: 'swatch' });
  const rightSwatch = h('span', { class: 'swatch' });
  const tableBody = h('tbody', {});
  const table = new LiveRows(tableBody);
  const pointCount = pointButtons(api, {
    addLabel: 'Add a control point',
    removeLabel: 'Remove the last control point',
    count: (s) => s.p.length,
    min: 2,
    max: MAX_POINTS,
    // A construction shown to its end stays shown to its end.
    add: (s) => ({
      ...s,
      p: [...s.p, extendPolygon(s.p)],
      step: s.step === degree(s) ? s.p.length : s.step,
    }),
    remove: (s) => ({ ...s, p: s.p.slice(0, -1) }),
  });

  const element = h(
    'div',
    { class: 'lesson-text' },
    h(
      'p',
      {},
      'A Bézier curve of degree n is built from its n + 1 control points by nothing but repeated linear interpolation. Fix t; cut every edge of the control polygon in the ratio t : (1 − t); join the new points and cut again. After n levels one point is left: the point P(t) on the curve.',
    ),
    formula(
      '\\begin{aligned}P_{r,i} &= (1-t)\\,P_{r-1,i} + t\\,P_{r-1,i+1},\\\\ &\\qquad r = 1,\\dots,n,\\quad i = 0,\\dots,n-r\\end{aligned}',
      true,
    ),
    h(
      'p',
      { class: 'note' },
      'Drag a control point, move it with Tab and the arrow keys, double-click to add one, right-click or Delete to remove one. Step through the levels with the buttons or a clicker.',
    ),
    stepTitle,
    stepText,
    stepFormulas,
    split.element,
    splitInfo,
    pointCount.element,
    h('h2', {}, 'Every constructed point'),
    dataTable('Constructed points', ['Point', 'x', 'y'], tableBody),
  );
  let shownLevel = -1;
  let shownSplit: boolean | null = null;

  return {
    element,
    update(m, state) {
      const { n, levels } = m;
      const t = state.t;
      const palette = api.theme().palette;
      const r = state.step;
      split.update(state);
      pointCount.update(state);

      stepTitle.textContent =
        r === 0 ? `Step 0 of ${n}: the control points` : `Step ${r} of ${n}: level ${r}`;
      stepText.textContent =
        r === 0
          ? `Level 0 is the control polygon itself: P0,i = Pi. At t = ${texT(t)} every edge will be cut ${fmt(t * 100, 0)}% of the way along. Step forward to build level 1.`
          : r === n
            ? `The last level has a single point: it is the point on the curve at t = ${texT(t)}.`
            : `Level ${r} has ${n - r + 1} points, each between two neighbours of level ${r - 1}.`;
      if (r > 0) {
        levels[r].forEach((point, i) => {
          levelFormulas[i] ??= new LiveFormula(true);
          levelFormulas[i].set(levelShape(r, i), [
            texT(1 - t),
            ...coords(levels[r - 1][i]),
            texT(t),
            ...coords(levels[r - 1][i + 1]),
            ...coords(point),
          ]);
        });
        if (r === n) {
          // The same point from the Bernstein form, as a check students can read.
          check.set(
            `\\text{Check: } P(${SLOT}) = \\sum_{i=0}^{${n}} W(${n},i,${SLOT})\\,P_i = ${slotPoint()}`,
            [texT(t), texT(t), ...coords(m.bernsteinPoint)],
          );
        }
      }
      // The list of formulas changes only when the level or the degree does.
      const levelKey = r === 0 ? 0 : r * 100 + n;
      if (levelKey !== shownLevel) {
        shownLevel = levelKey;
        const shown = r === 0 ? [] : levelFormulas.slice(0, levels[r].length).map((f) => f.element);
        setChildren(stepFormulas, shown, r === n && r > 0 ? check.element : null);
      }

      if (state.split !== shownSplit) {
        shownSplit = state.split;
        setChildren(
          splitInfo,
          state.split
            ? [
                h('p', {}, leftSwatch, leftTitle),
                leftPoints.element,
                h('p', {}, rightSwatch, rightTitle),
                rightPoints.element,
              ]
            : [],
        );
      }
      if (state.split) {
        leftSwatch.style.background = palette[0];
        rightSwatch.style.background = palette[1];
        leftTitle.textContent = `Left half (t from 0 to ${texT(t)}): P0,0, P1,0, …, P${n},0`;
        rightTitle.textContent = `Right half (t from ${texT(t)} to 1): P${n},0, P${n - 1},1, …, P0,${n}`;
        const list = (half: readonly (readonly number[])[]) =>
          half.map(() => slotPoint()).join(',\\ ');
        leftPoints.set(list(m.left), m.left.flatMap(coords));
        rightPoints.set(list(m.right), m.right.flatMap(coords));
      }

      table.set(
        levels.flatMap((level, k) =>
          level.map((point, i) => {
            const shown = k <= r;
            return {
              className: k === r ? 'current' : shown ? '' : 'future',
              data: { level: String(k) },
              cells: [
                {
                  text: `P${k},${i}`,
                  swatch: k > 0 ? palette[(k - 1) % palette.length] : undefined,
                },
                shown ? texNumber(point[0], 4) : '—',
                shown ? texNumber(point[1], 4) : '—',
              ],
            };
          }),
        ),
      );
    },
  };
}
