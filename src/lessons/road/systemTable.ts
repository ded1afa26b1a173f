import { dataTable, fmt, h, setChildren, setClass } from '../../app/dom';
import { type RowSpec, LiveRows } from '../../app/liveTable';
import { markForFit } from '../../render/fit';
import type { RoadSolve, SolveProgress } from './solve';
import { isFixed } from './solve';

/** Up to this many rows the matrix is written out in full; beyond, by its three diagonals. */
const FULL_MATRIX_ROWS = 8;
/** Rows shown at the top, the bottom and around the current row of a long system. */
const EDGE_ROWS = 3;
const AROUND_ROWS = 2;

/** Right-hand sides and gradients: three decimals. */
const number = (value: number) => fmt(value, 3);
/** Matrix entries: whole numbers as they are (2, 4, 1, 0), γ to three decimals. */
const entry = (value: number) => fmt(value, Number.isInteger(value) ? 0 : 3);

/**
 * The tridiagonal system with the current numbers, one table row per matrix
 * row, as it stands at this step: rows already swept read [0 1 γi | Γi],
 * gradients already fixed by back substitution fill the D columns. Both
 * coordinates share the matrix, so x and y are two right-hand-side columns.
 * Beside it, the gradients it yields. The tables keep their rows and cells;
 * a step or a drag writes only the texts and classes that changed.
 */
export function systemTables() {
  const head = h('tr', {});
  const body = h('tbody', {});
  const gradientBody = h('tbody', {});
  const rows = new LiveRows(body);
  const gradients = new LiveRows(gradientBody);
  // Two tables, the system and the gradients it yields, so each fits a narrow
  // panel (and a projector) without losing columns; marked to shrink if need be.
  const element = h(
    'div',
    { class: 'road-system' },
    h(
      'table',
      { class: 'data-table', 'aria-label': 'Tridiagonal system' },
      h('thead', {}, head),
      body,
    ),
    dataTable('Gradients found', ['Gradient', 'Dx', 'Dy'], gradientBody, 'road-gradients'),
  );
  let shownColumns = '';
  let shownLayout = '';
  let shownWidths = '';

  return {
    element,
    update(solve: RoadSolve, progress: SolveProgress) {
      const n = solve.n;
      const full = n <= FULL_MATRIX_ROWS;
      const columns = full ? Array.from({ length: n }, (_, j) => `D${j}`) : ['a', 'b', 'c'];
      if (columns.join() !== shownColumns) {
        shownColumns = columns.join();
        setChildren(
          head,
          h('th', { scope: 'col' }, 'Row'),
          columns.map((name) => h('th', { scope: 'col' }, name)),
          h('th', { scope: 'col', class: 'rhs' }, 'rhs x'),
          h('th', { scope: 'col' }, 'rhs y'),
        );
      }
      const matrix: RowSpec[] = [];
      const found: RowSpec[] = [];
      let previous = -1;
      const gap = (count: number) => {
        const text = `⋮ ${count} more row${count === 1 ? '' : 's'} of the same form`;
        matrix.push({ className: 'gap', cells: [text] });
        found.push({ className: 'gap', cells: [text] });
      };
      for (const i of shownRows(n, progress.row)) {
        if (i > previous + 1) gap(i - previous - 1);
        matrix.push(matrixRow(solve, progress, i, full));
        found.push(gradientRow(solve, progress, i));
        previous = i;
      }
      if (previous < n - 1) gap(n - 1 - previous);
      rows.set(matrix);
      gradients.set(found);
      // Which matrix row sits in which table row: cell styles change only with it.
      const layout = `${shownColumns}|${matrix.map((row) => row.data?.row ?? 'gap').join()}`;
      if (layout !== shownLayout) {
        shownLayout = layout;
        styleCells(body, full, columns.length + 3);
        styleCells(gradientBody, false, 3);
      }
      // The tables are monospaced: their width follows the longest text of each column.
      const widths = `${columnWidths(matrix)}|${columnWidths(found)}`;
      if (widths !== shownWidths) {
        shownWidths = widths;
        markForFit(element);
      }
    },
  };
}

function matrixRow(solve: RoadSolve, progress: SolveProgress, i: number, full: boolean): RowSpec {
  const n = solve.n;
  const { sub, diag, sup } = solve.matrix;
  const swept = i < progress.swept;
  const gamma = solve.trace[0].gamma[i];
  // After the sweep the row is [0 1 γi | Γi]: the entry left of the diagonal is eliminated.
  const a = i > 0 ? (swept ? 0 : sub[i]) : null;
  const b = swept ? 1 : diag[i];
  const c = i < n - 1 ? (swept ? gamma : sup[i]) : null;
  const rhs = [0, 1].map((k) => (swept ? solve.trace[k].Gamma[i] : solve.rhs[k][i]));
  const entries = full
    ? Array.from({ length: n }, (_, j) =>
        entry((j === i - 1 ? a : j === i ? b : j === i + 1 ? c : 0) ?? 0),
      )
    : [a === null ? '' : entry(a), entry(b), c === null ? '' : entry(c)];
  return {
    heading: true,
    className: [i === progress.row ? 'current' : '', swept ? 'swept' : '']
      .filter(Boolean)
      .join(' '),
    data: { row: String(i), swept: swept ? '1' : '0' },
    cells: [`row ${i}`, ...entries, number(rhs[0]), number(rhs[1])],
  };
}

/** Row i of the gradients table: Di for x and y once back substitution has fixed it. */
function gradientRow(solve: RoadSolve, progress: SolveProgress, i: number): RowSpec {
  const fixed = isFixed(solve.n, progress, i);
  return {
    heading: true,
    className: i === progress.row && fixed ? 'current' : '',
    data: { row: String(i), fixed: fixed ? '1' : '0' },
    cells: [
      `D${i}`,
      fixed ? number(solve.trace[0].solution[i]) : '—',
      fixed ? number(solve.trace[1].solution[i]) : '—',
    ],
  };
}

/**
 * What LiveRows does not set: a gap row spans the table; in a full matrix
 * the entries off the three diagonals are faint zeros; the right-hand side
 * for x is set off by a rule.
 */
function styleCells(body: HTMLTableSectionElement, full: boolean, span: number): void {
  for (const row of body.rows) {
    if (row.classList.contains('gap')) {
      if (row.cells[0].colSpan !== span) row.cells[0].colSpan = span;
      continue;
    }
    if (span === 3) continue;
    const i = Number(row.dataset.row);
    const cells = row.cells;
    for (let c = 1; c < cells.length; c++) {
      const j = c - 1;
      const zero = full && j < span - 3 && Math.abs(j - i) > 1;
      const rhs = c === cells.length - 2;
      setClass(cells[c], zero ? 'zero' : rhs ? 'rhs' : '');
    }
  }
}

/** The longest text of each column, as a key: a monospaced table is as wide as these. */
function columnWidths(rows: readonly RowSpec[]): string {
  const widths: number[] = [];
  for (const row of rows) {
    if (row.className === 'gap') continue;
    row.cells.forEach((cell, c) => {
      const text = typeof cell === 'string' ? cell : cell.text;
      widths[c] = Math.max(widths[c] ?? 0, text.length);
    });
  }
  return widths.join(',');
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
