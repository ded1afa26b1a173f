import { dataTable, h } from '../../app/dom';
import { LiveRows } from '../../app/liveTable';
import { texT } from '../../kit/format';
import { LiveFormula, SLOT, slotPoint, texNumber } from '../../render/formula';
import type { QuadraticModel } from './model';

/** Every digit a reader may want to check by hand (12 significant). */
const allDigits = (v: number) => String(Number(v.toPrecision(12)));
const coords = (p: readonly number[], digits: number) => p.map((v) => texNumber(v, digits));

// Equation 2 of the notes: the three conditions.
const CONDITIONS = `\\begin{aligned}P(0) &= a_0 = P_0 = ${slotPoint()}\\\\ P(${SLOT}) &= a_2\\cdot ${SLOT}^2 + a_1\\cdot ${SLOT} + a_0 = P_1 = ${slotPoint()}\\\\ P(1) &= a_2 + a_1 + a_0 = P_2 = ${slotPoint()}\\end{aligned}`;
// Equation 3: their solution.
const SOLUTION = `\\begin{aligned}a_0 &= P_0 = ${slotPoint()}\\\\ a_2 &= \\frac{P_1 - P_0 - \\mu_1 (P_2 - P_0)}{\\mu_1(\\mu_1 - 1)} = ${slotPoint()}\\\\ a_1 &= P_2 - P_0 - a_2 = ${slotPoint()}\\end{aligned}`;
const CHECK = `\\text{Check: } P(${SLOT}) = ${slotPoint()} = P_1`;

/** "The parametric quadratic": equations 2 and 3 with the numbers, and every digit in a table. */
export function parametricSection() {
  const conditions = new LiveFormula(true);
  const solution = new LiveFormula(true);
  const check = new LiveFormula(true);
  const digitsBody = h('tbody', {});
  const digits = new LiveRows(digitsBody);
  return {
    element: h(
      'section',
      {},
      h('h2', {}, 'The parametric quadratic'),
      h('div', {}, conditions.element, solution.element, check.element),
      h(
        'details',
        {},
        h('summary', {}, 'All digits of the coefficients'),
        dataTable('Coefficients, all digits', ['Vector', 'x', 'y'], digitsBody),
      ),
    ),
    update(m: QuadraticModel) {
      const [p0, p1, p2] = m.state.points;
      const mu = texT(m.state.mu);
      const { coefficients, atMu } = m.parametric;
      const [a0, a1, a2] = coefficients;
      conditions.set(CONDITIONS, [
        ...coords(p0, 3),
        mu,
        mu,
        mu,
        ...coords(p1, 3),
        ...coords(p2, 3),
      ]);
      solution.set(SOLUTION, [...coords(a0, 4), ...coords(a2, 4), ...coords(a1, 4)]);
      check.set(CHECK, [mu, ...coords(atMu, 4)]);
      const rows: [string, readonly number[]][] = [
        ['a0', a0],
        ['a1', a1],
        ['a2', a2],
        [`P(${mu})`, atMu],
      ];
      digits.set(rows.map(([name, v]) => ({ cells: [name, allDigits(v[0]), allDigits(v[1])] })));
    },
  };
}
