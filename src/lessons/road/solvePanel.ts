import { h, setChildren } from '../../app/dom';
import { gaussianEliminationOperationCount, thomasOperationCount } from '../../math';
import { renderFormula, texNumber } from '../../render/formula';
import { type RoadSolve, buildSolve, solveProgress } from './solve';
import { type RoadState, segmentCount } from './state';
import { systemTable } from './systemTable';

/** Whole numbers as they are (the matrix's 1, 2, 4), others to four decimals. */
const t = (value: number) => (Number.isInteger(value) ? String(value) : texNumber(value, 4));
/** A number in a sum: negatives in brackets. */
const tb = (value: number) => (value < 0 ? `(${t(value)})` : t(value));

/** The step-through of the Thomas algorithm and the cost note, for the natural and clamped roads. */
export function solveSection() {
  const title = h('h2', {});
  const text = h('p', {});
  const formulas = h('div', { class: 'step-formulas' });
  const formulaX = h('div', {});
  const formulaY = h('div', {});
  formulas.append(formulaX, formulaY);
  const table = h('div', {});
  const cost = h('p', { class: 'note' });
  const costFormula = h('div', {});
  const element = h(
    'section',
    { 'aria-label': 'Solving the system' },
    title,
    text,
    formulas,
    table,
    cost,
    costFormula,
  );

  let shownStep = -1;

  return {
    element,
    update(state: RoadState) {
      const solve = buildSolve(state);
      element.hidden = !solve;
      if (!solve) return;
      if (shownStep >= 0 && shownStep !== state.step) revealInPanel(element);
      shownStep = state.step;
      const n = solve.n;
      const progress = solveProgress(n, state.step);
      title.textContent = `Solving for the gradients: step ${state.step} of ${2 * n}`;
      text.textContent = stepText(state, solve, progress.row);
      const [x, y] = [0, 1].map((k) => stepFormula(solve, k, state.step, progress.row));
      renderFormula(formulaX, x, true);
      renderFormula(formulaY, y, true);
      setChildren(table, systemTable(solve, progress));

      const N = 4 * segmentCount(state);
      const thomas = thomasOperationCount(n, 2);
      const dense = gaussianEliminationOperationCount(N, 2);
      const inverse = gaussianEliminationOperationCount(N, N);
      cost.textContent = `Why not invert the ${N} × ${N} matrix of all 4m coefficients? Inverting it costs about 2N³ operations, and even Gaussian elimination with both right-hand sides about 2N³/3; the Thomas algorithm sweeps once down and once up the ${n} rows: O(m) against O(m³).`;
      renderFormula(
        costFormula,
        `\\underbrace{${count(thomas)}}_{\\text{Thomas, } x \\text{ and } y}\\ \\ll\\ \\underbrace{${count(dense)}}_{\\text{elimination, } ${N}\\times${N}}\\ <\\ \\underbrace{${count(inverse)}}_{\\text{inverting } ${N}\\times${N}}`,
        true,
      );
    },
  };
}

/**
 * Stepping with a clicker: bring the solve into view in the side panel, when
 * the panel scrolls on its own (wide screens); on a phone the page is left alone.
 */
function revealInPanel(section: HTMLElement): void {
  const panel = section.closest('.panel');
  if (!(panel instanceof HTMLElement) || panel.scrollHeight <= panel.clientHeight + 1) return;
  const top = section.getBoundingClientRect().top - panel.getBoundingClientRect().top;
  if (top < 0 || top > panel.clientHeight * 0.4) panel.scrollTop += top;
}

/** An operation count with thin spaces between thousands, or in powers of ten when huge. */
function count(value: number): string {
  if (value < 1e9) return Math.round(value).toLocaleString('en').replace(/,/g, '\\,');
  const exponent = Math.floor(Math.log10(value));
  return `${(value / 10 ** exponent).toFixed(1)}\\times10^{${exponent}}`;
}

function stepText(state: RoadState, solve: RoadSolve, row: number | null): string {
  const n = solve.n;
  const ends =
    state.road === 'clamped'
      ? 'The first and last rows are [1 | D0] and [1 | Dm]: the given end gradients.'
      : 'The first and last rows, [2 1] and [1 2], say the second derivative is zero at the ends.';
  if (row === null) {
    return `The system for the gradients D0 … D${n - 1} at the villages: one matrix for both coordinates, a right-hand side for x and one for y. ${ends} Step forward (or press the clicker) to sweep it row by row.`;
  }
  if (state.step <= n) {
    return `Forward sweep, row ${row}: subtract ${row === 0 ? 'nothing (it is the first row)' : `row ${row - 1} (already [1 γ${row - 1} | Γ${row - 1}])`} and divide by the pivot, so row ${row} becomes [1 γ${row} | Γ${row}].${state.step === n ? ' The sweep is done: the last row reads D' + (n - 1) + ' = Γ' + (n - 1) + '.' : ''}`;
  }
  const rule =
    row === n - 1
      ? `D${row} = Γ${row}: the last row has no γ`
      : `D${row} = Γ${row} − γ${row}·D${row + 1}`;
  const drawn =
    row === n - 1
      ? 'One more gradient and the first piece of road can be drawn.'
      : `With D${row} and D${row + 1} known, segment ${row} of the road is drawn.`;
  return `Back substitution: ${rule}. ${drawn}${row === 0 ? ' Every gradient is known: the whole road is built.' : ''}`;
}

function stepFormula(solve: RoadSolve, k: number, step: number, row: number | null): string {
  const n = solve.n;
  const axis = k === 0 ? 'x' : 'y';
  const { sub, diag, sup } = solve.matrix;
  const trace = solve.trace[k];
  if (row === null) {
    const i = Math.min(1, n - 1);
    const left = [
      i > 0 ? `${t(sub[i])}\\,D_{${i - 1}}` : '',
      `${t(diag[i])}\\,D_{${i}}`,
      i < n - 1 ? `${t(sup[i])}\\,D_{${i + 1}}` : '',
    ]
      .filter(Boolean)
      .join(' + ');
    return `\\text{row } ${i},\\ ${axis}:\\quad ${left} = ${t(solve.rhs[k][i])}`;
  }
  if (step <= n) {
    const i = row;
    const pivot = i === 0 ? diag[0] : diag[i] - sub[i] * trace.gamma[i - 1];
    const pivotTex =
      i === 0 ? t(diag[0]) : `${t(diag[i])} - ${t(sub[i])}\\cdot${tb(trace.gamma[i - 1])}`;
    const gamma =
      k === 0 && i < n - 1
        ? `\\gamma_{${i}} &= \\frac{${t(sup[i])}}{${pivotTex}} = ${t(trace.gamma[i])}\\\\ `
        : '';
    const numerator =
      i === 0
        ? t(solve.rhs[k][0])
        : `${t(solve.rhs[k][i])} - ${t(sub[i])}\\cdot${tb(trace.Gamma[i - 1])}`;
    return `\\begin{aligned}${gamma}\\Gamma^{${axis}}_{${i}} &= \\frac{${numerator}}{${t(pivot)}} = ${t(trace.Gamma[i])}\\end{aligned}`;
  }
  const i = row;
  if (i === n - 1) return `D^{${axis}}_{${i}} = \\Gamma^{${axis}}_{${i}} = ${t(trace.solution[i])}`;
  return `\\begin{aligned}D^{${axis}}_{${i}} &= \\Gamma^{${axis}}_{${i}} - \\gamma_{${i}} D^{${axis}}_{${i + 1}}\\\\ &= ${t(trace.Gamma[i])} - ${t(trace.gamma[i])}\\cdot${tb(trace.solution[i + 1])} = ${t(trace.solution[i])}\\end{aligned}`;
}
