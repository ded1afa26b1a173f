import { h, setChildren, setHidden, setText } from '../../app/dom';
import { LiveRows } from '../../app/liveTable';
import { texNumber } from '../../render/formula';
import { shownRow } from './basisFigure';
import type { BSplineModel } from './model';
import { type BSplineState, isUniformPart } from './state';

/**
 * The Cox–de Boor triangle at the cursor: one column per degree r, up to the
 * column the step shows, and one row per basis function i. Set this way it
 * is as wide as the degree, not as the number of points: row by row, the
 * seven columns i = 0 … 6 of the knots scene ran 535 px in a laptop's 404.
 */
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
  let columns = -2;
  return {
    element,
    update(m: BSplineModel, state: BSplineState, palette: readonly string[]) {
      const hidden = isUniformPart(state.part);
      setHidden(element, hidden);
      if (hidden) return;
      const count = m.table[0].length;
      const last = shownRow(m) ?? -1;
      if (last !== columns) {
        columns = last;
        setChildren(
          head,
          h('th', { scope: 'col' }, 'i'),
          Array.from({ length: last + 1 }, (_, r) =>
            h('th', { scope: 'col', class: r === last ? 'current' : '' }, `N(i,${r})`),
          ),
        );
      }
      setText(
        caption,
        last < 0
          ? 'Step on: the columns appear one by one, from N(i,0) to N(i,p).'
          : `u = ${texNumber(m.u, 4)}; each column from the one before it; the last column sums to ${texNumber(
              m.basis.reduce((a, b) => a + b, 0),
              4,
            )}.`,
      );
      rows.set(
        last < 0
          ? []
          : Array.from({ length: count }, (_, i) => ({
              heading: true,
              cells: [
                String(i),
                ...m.table.slice(0, last + 1).map((row) =>
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
