import type { HandoutTable } from '../../app/lesson';
import { fixed, words } from '../../kit/format';
import { shownRow } from './basisFigure';
import type { BSplineModel } from './model';
import { isUniformPart } from './state';

/**
 * The handout's Cox–de Boor triangle at the cursor: row r holds N(i,r)(u) for
 * every i, down to the row the scene's last step shows, as the panel lists it.
 * The uniform scenes have no triangle (their basis is the fixed matrix).
 */
export function triangleTables(m: BSplineModel): HandoutTable[] {
  if (isUniformPart(m.state.part)) return [];
  const last = shownRow(m) ?? m.table.length - 1;
  const count = m.table[0].length;
  return [
    {
      title: `The Cox–de Boor triangle at u = ${words(m.u)}: row r holds N(i,r)(u)`,
      columns: ['Row r', ...Array.from({ length: count }, (_, i) => `i = ${i}`)],
      rows: m.table
        .slice(0, last + 1)
        .map((row, r) => [
          String(r),
          ...Array.from({ length: count }, (_, i) =>
            i < row.length ? (row[i] === 0 ? '0' : fixed(row[i], 4)) : '',
          ),
        ]),
    },
  ];
}
