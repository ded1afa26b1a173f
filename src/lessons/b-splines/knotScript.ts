import { texNumber } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import type { BSplineModel, KnotModel } from './model';
import { blend, n3, pt, superscript } from './notation';
import type { BSplineState } from './state';

/** What the steps of the knot scenes reveal, by name: a row of Cox–de Boor per press. */
export type KnotReveal = 'points' | 'knots' | 'row' | 'curve';

/** The Cox–de Boor triangle up to row r at u: the non-zero columns i = span − p … span. */
export function triangleTex(m: BSplineModel, r: number): string {
  const p = m.degree;
  const span = m.table[0].indexOf(1);
  const columns = Array.from({ length: p + 1 }, (_, k) => span - p + k);
  const head = columns.map((i) => `i = ${i}`).join(' & ');
  const rows = m.table
    .slice(0, r + 1)
    .map(
      (row, q) =>
        `N_{i,${q}} & ${columns.map((i) => (i >= 0 && i < row.length ? n3(row[i]) : '')).join(' & ')}`,
    );
  return `u = ${n3(m.u)}:\\quad\\begin{array}{r|${'c'.repeat(p + 1)}} & ${head} \\\\ \\hline ${rows.join(' \\\\ ')}\\end{array}`;
}

/**
 * A general B-spline on its knots (uniform, clamped or repeated knots): the
 * points, the knot vector, the rows 0 … p of Cox–de Boor, the curve.
 */
export const knotScript = script<BSplineState, KnotModel, KnotReveal>(
  step('points', ({ state }) => {
    const n = state.points.length;
    return `The n = ${n} control points x0 … x${n - 1}`;
  }),
  step(
    'knots',
    ({ state }) => {
      const n = state.points.length;
      const p = state.degree;
      return `The knot vector u0 … u${n + p}: n + p + 1 = ${n + p + 1} knots on the strip`;
    },
    ({ model: m }) => `u = (${m.knots.map((v) => texNumber(v, 2)).join(',\\ ')})`,
  ),
  // Row r = 0 … p, one press each.
  repeat(
    'row',
    (state) => state.degree + 1,
    ({ index }) => {
      const r = index - 1;
      return r === 0
        ? 'Row 0 of Cox–de Boor: N(i,0) = 1 on [u(i), u(i+1)), else 0'
        : `Row ${r}: each N(i,${r}) blends N(i,${r - 1}) and N(i+1,${r - 1})`;
    },
    ({ model: m, index, times }) => {
      const p = m.degree;
      const sum =
        index === times
          ? `\\quad \\textstyle\\sum_i N_{i,${p}} = ${n3(m.basis.reduce((a, b) => a + b, 0))}`
          : '';
      return triangleTex(m, index - 1) + sum;
    },
  ),
  step(
    'curve',
    ({ state }) => {
      const n = state.points.length;
      const p = state.degree;
      return state.part === 'clamped'
        ? `The curve of degree ${p}: with p + 1 = ${p + 1} equal end knots it starts at x0 and ends at x${n - 1}`
        : `The curve of degree ${p}: at a knot of multiplicity k it is C${superscript(p)}⁻ᵏ`;
    },
    ({ model: m }) => `C(${n3(m.u)}) = ${blend(m.basis, (i) => `x_{${i}}`)} = ${pt(m.point)}`,
  ),
);
