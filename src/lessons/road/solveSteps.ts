import { texNumber } from '../../render/formula';
import { type FormulaParts, joined, live, tex } from '../../render/formulaParts';
import type { RoadSolve } from './solve';
import type { RoadState } from './state';

// What each step of the solve says: in words, and as the formula that step
// works out, for x and for y.

/** Whole numbers as they are (the matrix's 1, 2, 4), others to four decimals. */
const t = (value: number) => (Number.isInteger(value) ? String(value) : texNumber(value, 4));
const number = (value: number) => live(t(value));
/** A number in a sum: negatives in brackets (part of the shape). */
const term = (value: number) => (value < 0 ? tex`(${number(value)})` : number(value));

export function stepText(
  state: RoadState,
  solve: RoadSolve,
  step: number,
  row: number | null,
): string {
  const n = solve.n;
  const ends =
    state.road === 'clamped'
      ? 'The first and last rows are [1 | D0] and [1 | Dm]: the given end gradients.'
      : 'The first and last rows, [2 1] and [1 2], say the second derivative is zero at the ends.';
  if (row === null) {
    return `The system for the gradients D0 … D${n - 1} at the villages: one matrix for both coordinates, a right-hand side for x and one for y. ${ends} Step forward (or press the clicker) to sweep it row by row.`;
  }
  if (step <= n) {
    return `Forward sweep, row ${row}: subtract ${row === 0 ? 'nothing (it is the first row)' : `row ${row - 1} (already [1 γ${row - 1} | Γ${row - 1}])`} and divide by the pivot, so row ${row} becomes [1 γ${row} | Γ${row}].${step === n ? ' The sweep is done: the last row reads D' + (n - 1) + ' = Γ' + (n - 1) + '.' : ''}`;
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

/** The formula of this step for a coordinate (0: x, 1: y), with its numbers live. */
export function stepFormula(
  solve: RoadSolve,
  coordinate: number,
  step: number,
  row: number | null,
  /** On one line, for the presenter's caption (the panel stacks it in lines). */
  oneLine = false,
): FormulaParts {
  const n = solve.n;
  const axis = coordinate === 0 ? 'x' : 'y';
  const { sub, diag, sup } = solve.matrix;
  const trace = solve.trace[coordinate];
  if (row === null) {
    // Step 0: one inner row of the system as it stands.
    const i = Math.min(1, n - 1);
    const left = [
      ...(i > 0 ? [tex`${number(sub[i])}\,D_{${i - 1}}`] : []),
      tex`${number(diag[i])}\,D_{${i}}`,
      ...(i < n - 1 ? [tex`${number(sup[i])}\,D_{${i + 1}}`] : []),
    ];
    return tex`\text{row } ${i},\ ${axis}:\quad ${joined(left, ' + ')} = ${number(solve.rhs[coordinate][i])}`;
  }
  const i = row;
  if (step <= n) {
    // Forward sweep: γi = ci / (bi − ai γ(i−1)), Γi = (di − ai Γ(i−1)) / (bi − ai γ(i−1)).
    const pivot = i === 0 ? diag[0] : diag[i] - sub[i] * trace.gamma[i - 1];
    const pivotTex =
      i === 0
        ? number(diag[0])
        : tex`${number(diag[i])} - ${number(sub[i])}\cdot${term(trace.gamma[i - 1])}`;
    // Lines aligned at "=" in the panel; one line, side by side, in the caption.
    const eq = oneLine ? '=' : '&=';
    const gamma =
      coordinate === 0 && i < n - 1
        ? tex`\gamma_{${i}} ${eq} \frac{${number(sup[i])}}{${pivotTex}} = ${number(trace.gamma[i])}`
        : null;
    const numerator =
      i === 0
        ? number(solve.rhs[coordinate][0])
        : tex`${number(solve.rhs[coordinate][i])} - ${number(sub[i])}\cdot${term(trace.Gamma[i - 1])}`;
    const Gamma = tex`\Gamma^{${axis}}_{${i}} ${eq} \frac{${numerator}}{${number(pivot)}} = ${number(trace.Gamma[i])}`;
    const lines = gamma ? [gamma, Gamma] : [Gamma];
    return oneLine
      ? joined(lines, ',\\qquad ')
      : tex`\begin{aligned}${joined(lines, '\\\\ ')}\end{aligned}`;
  }
  // Back substitution: D(n−1) = Γ(n−1), Di = Γi − γi D(i+1).
  if (i === n - 1)
    return tex`D^{${axis}}_{${i}} = \Gamma^{${axis}}_{${i}} = ${number(trace.solution[i])}`;
  const [eq, br] = oneLine ? ['=', ''] : ['&=', '\\\\ &'];
  const back = tex`D^{${axis}}_{${i}} ${eq} \Gamma^{${axis}}_{${i}} - \gamma_{${i}} D^{${axis}}_{${i + 1}} ${br}= ${number(trace.Gamma[i])} - ${number(trace.gamma[i])}\cdot${term(trace.solution[i + 1])} = ${number(trace.solution[i])}`;
  return oneLine ? back : tex`\begin{aligned}${back}\end{aligned}`;
}
