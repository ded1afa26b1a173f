import type { HandoutTable } from '../../app/lesson';
import { fixed, sub } from '../../kit/format';
import type { GlobalChange } from './globalChange';
import type { RoadModel } from './model';

/** A long system prints its first and last rows; the sweep's γ settles within a few rows. */
const EDGE_ROWS = 12;

/** Row indices to print, null where rows are left out. */
function printedRows(n: number): (number | null)[] {
  const all = Array.from({ length: n }, (_, i) => i);
  return n <= 2 * EDGE_ROWS + 1
    ? all
    : [...all.slice(0, EDGE_ROWS), null, ...all.slice(n - EDGE_ROWS)];
}

/**
 * The handout's Thomas sweep: for each row i of the system, the forward
 * sweep's γi and Γi (x and y) and the gradient Di back substitution found,
 * the numbers the panel's system table reaches at the end of the solve.
 */
export function sweepTables({ solve, globalChange }: RoadModel): HandoutTable[] {
  if (globalChange) return [movedTable(globalChange)];
  if (!solve) return [];
  const [x, y] = solve.trace;
  return [
    {
      title:
        'The Thomas algorithm: the forward sweep (γᵢ, Γᵢ) and the gradients by back substitution',
      columns: ['Row i', 'γᵢ', 'Γᵢ (x)', 'Γᵢ (y)', 'Dᵢ'],
      rows: printedRows(x.gamma.length).map((i) =>
        i === null
          ? [`⋮ ${x.gamma.length - 2 * EDGE_ROWS} more rows of the same form`, '', '', '', '']
          : [
              String(i),
              fixed(x.gamma[i], 4),
              fixed(x.Gamma[i], 4),
              fixed(y.Gamma[i], 4),
              `D${sub(i)} = (${fixed(x.solution[i], 3)}, ${fixed(y.solution[i], 3)})`,
            ],
      ),
    },
  ];
}

/** The global view's handout: every gradient before and after one village moved. */
function movedTable({ road, moved }: GlobalChange): HandoutTable {
  const point = (d: readonly number[]) => `(${fixed(d[0], 3)}, ${fixed(d[1], 3)})`;
  return {
    title: `The natural spline's gradients before and after P${sub(moved.index)} moves ${fixed(moved.shift[1], 2)} up`,
    columns: ['Gradient', 'before', 'after', '|change|'],
    rows: printedRows(road.gradients.length).map((i) =>
      i === null
        ? [`⋮ ${road.gradients.length - 2 * EDGE_ROWS} more gradients`, '', '', '']
        : [
            `D${sub(i)}`,
            point(road.gradients[i]),
            point(moved.road.gradients[i]),
            fixed(moved.changes[i], 3),
          ],
    ),
  };
}
