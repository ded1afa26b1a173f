import { fmt, h, setChildren, dataTable } from '../../app/dom';
import type { LessonApi, LessonPanel } from '../../app/lesson';
import { checkbox, pointButtons } from '../../app/panelControls';
import { extendPolygon } from '../../interact/editPoints';
import { bernstein, deCasteljau, splitBezier } from '../../math';
import { formula, renderFormula, texNumber, texPoint } from '../../render/formula';
import { type DeCasteljauState, MAX_POINTS, degree } from './state';

/** t as typed: up to four decimals, trailing zeros dropped. */
const texT = (t: number) => String(Number(t.toFixed(4)));

export function deCasteljauPanel(api: LessonApi<DeCasteljauState>): LessonPanel<DeCasteljauState> {
  const stepTitle = h('h2', {});
  const stepText = h('p', {});
  const stepFormulas = h('div', { class: 'step-formulas' });
  const split = checkbox(api, {
    id: 'split-toggle',
    label: 'Show subdivision at t: the two halves of the curve and their control polygons',
    get: (s) => s.split,
    set: (s, on) => ({ ...s, split: on }),
  });
  const splitInfo = h('div', { class: 'split-info' });
  const tableBody = h('tbody', {});
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

  return {
    element,
    update(state) {
      const n = degree(state);
      const t = state.t;
      const levels = deCasteljau(state.p, t);
      const palette = api.theme().palette;
      const r = state.step;
      split.update(state);
      pointCount.update(state);

      stepTitle.textContent =
        r === 0 ? `Step 0 of ${n}: the control points` : `Step ${r} of ${n}: level ${r}`;
      if (r === 0) {
        stepText.textContent = `Level 0 is the control polygon itself, P_{0,i} = P_i. At t = ${texT(t)} every edge will be cut ${fmt(t * 100, 0)}% of the way along. Step forward to build level 1.`;
        setChildren(stepFormulas);
      } else {
        stepText.textContent =
          r === n
            ? `The last level has a single point: it is the point on the curve at t = ${texT(t)}.`
            : `Level ${r} has ${n - r + 1} points, each between two neighbours of level ${r - 1}.`;
        const lines = levels[r].map((point, i) =>
          formula(
            `\\begin{aligned}P_{${r},${i}} &= ${texT(1 - t)}\\cdot${texPoint(levels[r - 1][i], 3)} + ${texT(t)}\\cdot${texPoint(levels[r - 1][i + 1], 3)}\\\\ &= ${texPoint(point, 3)}\\end{aligned}`,
            true,
          ),
        );
        if (r === n) {
          // The same point from the Bernstein form, as a check students can read.
          const weights = state.p.map((_, i) => bernstein(n, i, t));
          const sum = [0, 1].map((d) => weights.reduce((acc, w, i) => acc + w * state.p[i][d], 0));
          const check = h('div', {});
          renderFormula(
            check,
            `\\text{Check: } P(${texT(t)}) = \\sum_{i=0}^{${n}} W(${n},i,${texT(t)})\\,P_i = ${texPoint(sum, 3)}`,
            true,
          );
          lines.push(check);
        }
        setChildren(stepFormulas, lines);
      }

      if (state.split) {
        const [left, right] = splitBezier(state.p, t);
        setChildren(
          splitInfo,
          h(
            'p',
            {},
            h('span', { class: 'swatch', style: `background:${palette[0]}` }),
            `Left half (t from 0 to ${texT(t)}): P_{0,0}, P_{1,0}, …, P_{${n},0}`,
          ),
          formula(left.map((q) => texPoint(q, 3)).join(',\\ '), true),
          h(
            'p',
            {},
            h('span', { class: 'swatch', style: `background:${palette[1]}` }),
            `Right half (t from ${texT(t)} to 1): P_{${n},0}, P_{${n - 1},1}, …, P_{0,${n}}`,
          ),
          formula(right.map((q) => texPoint(q, 3)).join(',\\ '), true),
        );
      } else setChildren(splitInfo);

      const rows: HTMLElement[] = [];
      levels.forEach((level, k) => {
        level.forEach((point, i) => {
          const shown = k <= r;
          rows.push(
            h(
              'tr',
              { class: k === r ? 'current' : shown ? '' : 'future', 'data-level': k },
              h(
                'td',
                {},
                k > 0
                  ? h('span', {
                      class: 'swatch',
                      style: `background:${palette[(k - 1) % palette.length]}`,
                    })
                  : null,
                `P${k},${i}`,
              ),
              h('td', {}, shown ? texNumber(point[0], 4) : '—'),
              h('td', {}, shown ? texNumber(point[1], 4) : '—'),
            ),
          );
        });
      });
      setChildren(tableBody, rows);
    },
  };
}
