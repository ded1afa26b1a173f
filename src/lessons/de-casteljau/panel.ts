import { dataTable, h, setChildren, setHidden, setText } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { LiveRows } from '../../app/liveTable';
import { checkbox } from '../../app/panelControls';
import { LiveFormula, SLOT, formula, slotPoint, texNumber } from '../../render/formula';
import { texT, words } from '../../kit/format';
import { curvatureLink } from '../../kit/lessonLinks';
import { halfColour, levelColour } from '../../kit/seriesColours';
import type { DeCasteljauModel } from './model';
import { controlPoints } from './points';
import type { DeCasteljauState } from './state';
import { walkPanel } from './walkPanel';
import { scriptOf } from './walks';
import { gestures } from '../../kit/gestures';

const coords = (p: readonly number[]) => p.map((v) => texNumber(v, 3));

/** P_{r,i} = (1−t)·P_{r−1,i} + t·P_{r−1,i+1} = P, with live numbers. */
const levelShape = (r: number, i: number) =>
  `\\begin{aligned}P_{${r},${i}} &= ${SLOT}\\cdot${slotPoint()} + ${SLOT}\\cdot${slotPoint()}\\\\ &= ${slotPoint()}\\end{aligned}`;

export function deCasteljauPanel(
  api: LessonApi<DeCasteljauState, DeCasteljauModel>,
): LessonPanel<DeCasteljauState, DeCasteljauModel> {
  const stepTitle = h('h2', {});
  const stepText = h('p', {});
  const note = h('p', { class: 'warning', role: 'note' });
  const stepFormulas = h('div', { class: 'step-formulas' });
  // One live formula per point of a level (at most n of them), typeset when its shape changes.
  const levelFormulas: LiveFormula[] = [];
  const check = new LiveFormula(true);
  const split = checkbox(api, {
    id: 'split-toggle',
    label: 'Show subdivision at t: the two halves of the curve and their control polygons',
    get: (s) => s.mode === 'halves',
    set: (s, on): DeCasteljauState => ({ ...s, mode: on ? 'halves' : 'construction' }),
  });
  const splitText = h('p', {});
  const halvesBody = h('tbody', {});
  const halves = new LiveRows(halvesBody);
  const splitInfo = h(
    'div',
    { class: 'split-info' },
    splitText,
    dataTable('Control points of the two halves', ['Half', 'Point', 'x', 'y'], halvesBody),
  );
  const tableBody = h('tbody', {});
  const table = new LiveRows(tableBody);
  const pointCount = controlPoints.buttons(api);
  const walks = walkPanel();

  const curvature = curvatureLink();
  const element = h(
    'div',
    { class: 'lesson-text' },
    h(
      'p',
      {},
      'A Bézier curve of degree n is built from its n + 1 control points by nothing but repeated linear interpolation. The parameter is t, from 0 to 1 (the slider below the figure). Fix t; cut every edge of the control polygon in the ratio t : (1 − t); join the new points and cut again. After n levels one point is left: the point P(t) on the curve.',
    ),
    formula(
      '\\begin{aligned}P_{r,i} &= (1-t)\\,P_{r-1,i} + t\\,P_{r-1,i+1},\\\\ &\\qquad r = 1,\\dots,n,\\quad i = 0,\\dots,n-r\\end{aligned}',
      true,
    ),
    h(
      'p',
      { class: 'note' },
      `To move a control point, ${gestures().move}; to add one, ${gestures().add}; to remove one, ${gestures().remove}. Step through the construction with Back and Next, or a clicker.`,
    ),
    stepTitle,
    stepText,
    note,
    stepFormulas,
    ...walks.elements,
    split.element,
    splitInfo,
    pointCount.element,
    curvature.element,
    h('h2', {}, 'Every constructed point'),
    dataTable('Constructed points', ['Point', 'x', 'y'], tableBody),
  );
  let shownKey = '';

  return {
    element,
    update(m, state) {
      const { n, levels, shown } = m;
      const t = state.t;
      const palette = api.theme().palette;
      const r = shown.count('level');
      split.update(state);
      setHidden(split.element, state.mode !== 'construction' && state.mode !== 'halves');
      walks.update(m);
      pointCount.update(state);
      curvature.update({ src: 'bezier', p: state.p, t: state.t });

      setText(stepTitle, `Step ${state.step} of ${shown.lastStep}`);
      setText(stepText, `${scriptOf(state).caption(state, m, state.step)}.`);
      setText(note, m.note ?? '');
      setHidden(note, m.note === null);
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
      }
      if (r === n) {
        // The same point from the Bernstein form, as a check students can read.
        check.set(
          `\\text{Check: } P(${SLOT}) = \\sum_{i=0}^{${n}} W(${n},i,${SLOT})\\,P_i = ${slotPoint()}`,
          [texT(t), texT(t), ...coords(m.bernsteinPoint)],
        );
      }
      // The list of formulas changes only when the level or the degree does.
      const key = `${r}/${n}`;
      if (key !== shownKey) {
        shownKey = key;
        const formulas = r === 0 ? [] : levelFormulas.slice(0, levels[r].length);
        setChildren(
          stepFormulas,
          formulas.map((f) => f.element),
          r === n ? check.element : null,
        );
      }

      setHidden(splitInfo, state.mode !== 'halves');
      if (state.mode === 'halves') {
        setText(
          splitText,
          `Cut at t = ${words(t)}, the curve is two Bézier curves of degree ${n}. The left half (t from 0 to ${words(t)}) has the first point of every level as its control points, the right half (t from ${words(t)} to 1) the last point of every level, from level ${n} back to level 0.`,
        );
        const row = (half: 0 | 1, name: string, point: readonly number[]) => ({
          cells: [
            { text: half === 0 ? 'Left' : 'Right', swatch: halfColour(palette, half) },
            name,
            texNumber(point[0], 4),
            texNumber(point[1], 4),
          ],
        });
        halves.set([
          ...m.left.map((point, i) => row(0, `P${i},0`, point)),
          ...m.right.map((point, i) => row(1, `P${n - i},${i}`, point)),
        ]);
      }

      table.set(
        levels.flatMap((row, level) =>
          row.map((point, i) => {
            const visible = i < m.computed[level];
            const current = m.current.some(([a, b]) => a === level && b === i);
            return {
              className: current ? 'current' : visible ? '' : 'future',
              data: { level: String(level) },
              cells: [
                {
                  text: `P${level},${i}`,
                  swatch: level > 0 ? levelColour(palette, level) : undefined,
                },
                visible ? texNumber(point[0], 4) : '—',
                visible ? texNumber(point[1], 4) : '—',
              ],
            };
          }),
        ),
      );
    },
  };
}
