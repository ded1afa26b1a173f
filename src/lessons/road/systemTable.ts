import { fmt, h, dataTable } from '../../app/dom';
import type { RoadSolve, SolveProgress } from './solve';
import { isFixed } from './solve';
import { markForFit } from '../../render/fit';

/** Up to this many rows the matrix is written out in full; beyond, by its three diagonals. */
export const FULL_MATRIX_ROWS = 8;
/** Rows shown at the top, the bottom and around the current row of a long system. */
const EDGE_ROWS = 3;
const AROUND_ROWS = 2;

/** Right-hand sides and gradients: three decimals. */
const number = (value: number) => fmt(value, 3);
/** Matrix entries: whole numbers as they are (2, 4, 1, 0), γ to three decimals. */
const entry = (value: number) => (Number.isInteger(value) ? String(value) : fmt(value, 3));

/**
 * The tridiagonal system with the current numbers, one table row per matrix
 * row, as it stands at this step: rows already swept read [0 1 γi | Γi],
 * gradients already fixed by back substitution fill the D columns. Both
 * coordinates share the matrix, so x and y are two right-hand-side columns.
 */
export function systemTable(solve: RoadSolve, progress: SolveProgress): HTMLElement {
  const n = solve.n;
  const full = n <= FULL_MATRIX_ROWS;
  const head = h(
    'tr',
    {},
    h('th', { scope: 'col' }, 'Row'),
    full
      ? Array.from({ length: n }, (_, j) => h('th', { scope: 'col' }, `D${j}`))
      : [
          h('th', { scope: 'col' }, 'a'),
          h('th', { scope: 'col' }, 'b'),
          h('th', { scope: 'col' }, 'c'),
        ],
    h('th', { scope: 'col', class: 'rhs' }, 'rhs x'),
    h('th', { scope: 'col' }, 'rhs y'),
  );
  const body = h('tbody', {});
  const gradients = h('tbody', {});
  let previous = -1;
  const span = full ? n + 3 : 6;
  for (const i of shownRows(n, progress.row)) {
    if (i > previous + 1) {
      body.append(gapRow(i - previous - 1, span));
      gradients.append(gapRow(i - previous - 1, 3));
    }
    body.append(matrixRow(solve, progress, i, full));
    gradients.append(gradientRow(solve, progress, i));
    previous = i;
  }
  if (previous < n - 1) {
    body.append(gapRow(n - 1 - previous, span));
    gradients.append(gapRow(n - 1 - previous, 3));
  }
  // Two tables, the system and the gradients it yields, so each fits a narrow
  // panel (and a projector) without losing columns; marked to shrink if need be.
  return markForFit(
    h(
      'div',
      { class: 'road-system' },
      h(
        'table',
        { class: 'data-table', 'aria-label': 'Tridiagonal system' },
        h('thead', {}, head),
        body,
      ),
      dataTable('Gradients found', ['Gradient', 'Dx', 'Dy'], gradients, 'road-gradients'),
    ),
  );
}

function matrixRow(
  solve: RoadSolve,
  progress: SolveProgress,
  i: number,
  full: boolean,
): HTMLElement {
  const n = solve.n;
  const { sub, diag, sup } = solve.matrix;
  const swept = i < progress.swept;
  const gamma = solve.trace[0].gamma[i];
  // After the sweep the row is [0 1 γi | Γi]: the entry left of the diagonal is eliminated.
  const a = i > 0 ? (swept ? 0 : sub[i]) : null;
  const b = swept ? 1 : diag[i];
  const c = i < n - 1 ? (swept ? gamma : sup[i]) : null;
  const rhs = [0, 1].map((k) => (swept ? solve.trace[k].Gamma[i] : solve.rhs[k][i]));
  const cells: HTMLElement[] = [];
  if (full) {
    for (let j = 0; j < n; j++) {
      const value = j === i - 1 ? a : j === i ? b : j === i + 1 ? c : 0;
      cells.push(
        h('td', { class: j === i - 1 || j === i || j === i + 1 ? '' : 'zero' }, entry(value ?? 0)),
      );
    }
  } else {
    cells.push(
      h('td', {}, a === null ? '' : entry(a)),
      h('td', {}, entry(b)),
      h('td', {}, c === null ? '' : entry(c)),
    );
  }
  const classes = [i === progress.row ? 'current' : '', swept ? 'swept' : '']
    .filter(Boolean)
    .join(' ');
  return h(
    'tr',
    {
      class: classes,
      'data-row': i,
      'data-swept': swept ? 1 : 0,
    },
    h('th', { scope: 'row' }, `row ${i}`),
    cells,
    h('td', { class: 'rhs' }, number(rhs[0])),
    h('td', {}, number(rhs[1])),
  );
}

/** Row i of the gradients table: Di for x and y once back substitution has fixed it. */
function gradientRow(solve: RoadSolve, progress: SolveProgress, i: number): HTMLElement {
  const fixed = isFixed(solve.n, progress, i);
  const current = i === progress.row && fixed;
  return h(
    'tr',
    { class: current ? 'current' : '', 'data-row': i, 'data-fixed': fixed ? 1 : 0 },
    h('th', { scope: 'row' }, `D${i}`),
    h('td', {}, fixed ? number(solve.trace[0].solution[i]) : '—'),
    h('td', {}, fixed ? number(solve.trace[1].solution[i]) : '—'),
  );
}

function gapRow(count: number, span: number): HTMLElement {
  return h(
    'tr',
    { class: 'gap' },
    h('td', { colspan: span }, `⋮ ${count} more row${count === 1 ? '' : 's'} of the same form`),
  );
}

/** Which rows a long system shows: its first and last few and those around the current row. */
function shownRows(n: number, current: number | null): number[] {
  if (n <= 3 * EDGE_ROWS + 2 * AROUND_ROWS + 1) return Array.from({ length: n }, (_, i) => i);
  const rows = new Set<number>();
  for (let i = 0; i < EDGE_ROWS; i++) {
    rows.add(i);
    rows.add(n - 1 - i);
  }
  if (current !== null) {
    for (let i = current - AROUND_ROWS; i <= current + AROUND_ROWS; i++)
      if (i >= 0 && i < n) rows.add(i);
  }
  return [...rows].sort((x, y) => x - y);
}
