import type { HandoutTable } from '../../app/lesson';
import { fixed, sub, words } from '../../kit/format';
import type { DeCasteljauModel } from './model';

/** The handout's table of the construction: every point P_{r,i} at t, level by level, as the panel lists them. */
export function constructionTables({ levels, state }: DeCasteljauModel): HandoutTable[] {
  return [
    {
      title: `The points of the construction at t = ${words(state.t)}`,
      columns: ['Level r', 'Point', 'x', 'y'],
      rows: levels.flatMap((row, r) =>
        row.map((point, i) => [
          String(r),
          `P${sub(r)},${sub(i)}`,
          fixed(point[0], 4),
          fixed(point[1], 4),
        ]),
      ),
    },
  ];
}
