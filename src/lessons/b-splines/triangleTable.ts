import { h, setChildren, setHidden, setText } from '../../app/dom';
import { LiveRows } from '../../app/liveTable';
import { texNumber } from '../../render/formula';
import { shownRow } from './basisFigure';
import type { BSplineModel } from './model';
import { type BSplineState, isUniformPart } from './state';

/** The Cox–de Boor triangle at the cursor, one row per degree r up to the row the step shows. */
export function triangleTable() {
  const head = h('tr', {});
  const body = h('tbody', {});
  const rows = new LiveRows(body);
  const caption = h('p', { class: 'note' });
  const table = h(
    'table',
    { class: 'data-table', 'aria-label': 'Cox–de Boor triangle' },
    h('thead', {}, head),
    body,
  );
  const element = h('div', {}, h('h2', {}, 'The Cox–de Boor triangle at u'), caption, table);
  let columns = -1;
  return {
    element,
    update(m: BSplineModel, state: BSplineState, palette: readonly string[]) {
      const hidden = isUniformPart(state.part);
      setHidden(element, hidden);
      if (hidden) return;
      const count = m.table[0].length;
      if (count !== columns) {
        columns = count;
        setChildren(
          head,
          h('th', { scope: 'col' }, 'row'),
          Array.from({ length: count }, (_, i) => h('th', { scope: 'col' }, `i=${i}`)),
        );
      }
      const last = shownRow(m) ?? -1;
      setText(
        caption,
        last < 0
          ? 'Step on: the rows appear one by one, from N(i,0) to N(i,p).'
          : `u = ${texNumber(m.u, 4)}; each row from the one above; the last row sums to ${texNumber(
              m.basis.reduce((a, b) => a + b, 0),
              4,
            )}.`,
      );
      rows.set(
        m.table.slice(0, last + 1).map((row, r) => ({
          className: r === last ? 'current' : '',
          cells: [
            `N(i,${r})`,
            ...Array.from({ length: count }, (_, i) =>
              i < row.length
                ? {
                    text: row[i] === 0 ? '0' : texNumber(row[i], 4),
                    swatch: row[i] > 0 ? palette[i % palette.length] : undefined,
                  }
                : '',
            ),
          ],
        })),
      );
    },
  };
}
