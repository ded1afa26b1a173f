import { texNumber } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import type { BSplineModel, KnotModel } from './model';
import { blend, n3, pt, superscript } from './notation';
import type { BSplineState } from './state';
import { equalSpacing, pieceAt, pieceTex, uniformPieces } from './uniformPieces';

/** What the steps of the knot scenes reveal, by name: a row of Cox–de Boor per press. */
export type KnotReveal = 'points' | 'knots' | 'row' | 'curve';

/**
 * The Cox–de Boor triangle up to row r at u: the non-zero columns i = span − p … span.
 * With `sum`, a last column Σᵢ holds the last row's sum (1 on the curve's interval):
 * beside the table rather than after it, so the caption stays narrow enough (#19).
 */
export function triangleTex(m: BSplineModel, r: number, sum = false): string {
  const p = m.degree;
  const span = m.table[0].indexOf(1);
  const columns = Array.from({ length: p + 1 }, (_, k) => span - p + k);
  const head = columns.map((i) => `i = ${i}`).join(' & ') + (sum ? ' & \\sum_i' : '');
  const rows = m.table.slice(0, r + 1).map((row, q) => {
    const cells = columns.map((i) => (i >= 0 && i < row.length ? n3(row[i]) : ''));
    if (sum) cells.push(q === r ? n3(row.reduce((a, b) => a + b, 0)) : '');
    return `N_{i,${q}} & ${cells.join(' & ')}`;
  });
  const align = `r|${'c'.repeat(p + 1)}${sum ? '|c' : ''}`;
  return `u = ${n3(m.u)}:\\quad\\begin{array}{${align}} & ${head} \\\\ \\hline ${rows.join(' \\\\ ')}\\end{array}`;
}

/** The span [u_j, u_{j+1}) of the cursor: the column where row 0 is 1. */
const spanOf = (m: BSplineModel) => m.table[0].indexOf(1);

/**
 * Row r at the cursor written out, when the knots it reads (u_{j−r} … u_{j+r+1})
 * are equally spaced: each non-zero N_{i,r} as its polynomial piece in the local
 * t = (u − u_j)/h, with its value. Null on other knots (the triangle says it then).
 */
export function piecesTex(m: BSplineModel, r: number): string | null {
  const j = spanOf(m);
  const h = j < 0 ? null : equalSpacing(m.knots, j - r, j + r + 1);
  if (h === null) return null;
  const t = (m.u - m.knots[j]) / h;
  const local =
    h === 1
      ? `t = u - u_{${j}} = ${n3(t)}`
      : `t = \\frac{u - u_{${j}}}{${texNumber(h, 3)}} = ${n3(t)}`;
  // Row 0's one piece is the constant 1: no value to add.
  const lines = uniformPieces(r).map(
    (piece, k) =>
      `N_{${j - r + k},${r}} &= ${pieceTex(piece)}${r === 0 ? '' : ` = ${n3(pieceAt(piece, t))}`}`,
  );
  const rows: string[] = [];
  for (let k = 0; k < lines.length; k += 2) rows.push(lines.slice(k, k + 2).join(' & '));
  return `u = ${n3(m.u)},\\ ${local}:\\quad\\begin{aligned}${rows.join(' \\\\ ')}\\end{aligned}`;
}

/** Row r's caption: row 0's rule, the blend, and on equal knots the uniform B-spline's pieces. */
function rowCaption(m: BSplineModel, r: number): string {
  const p = m.degree;
  if (r === 0) return 'Row 0 of Cox–de Boor: N(i,0) = 1 on [u(i), u(i+1)), else 0';
  if (r === p && piecesTex(m, r) !== null)
    return p === 3
      ? 'Row 3 on equal knots: its pieces are the cubic bases B0(t) … B3(t)'
      : `Row ${p} on equal knots: its ${p + 1} pieces are the uniform bases of degree ${p}`;
  return `Row ${r}: each N(i,${r}) blends N(i,${r - 1}) and N(i+1,${r - 1})`;
}

/**
 * A general B-spline on its knots (uniform, clamped or repeated knots): the
 * points, the knot vector, the rows 0 … p of Cox–de Boor, the curve.
 */
export const knotScript = script<BSplineState, KnotModel, KnotReveal>(
  step('points', ({ state }) => {
    const n = state.points.length;
    return `The m + 1 = ${n} control points P0 … P${n - 1}, for a curve of degree p = ${state.degree}`;
  }),
  step(
    'knots',
    ({ state }) => {
      const n = state.points.length;
      const p = state.degree;
      return `The knot vector u0 … u${n + p}: m + p + 2 = ${n + p + 1} knots on the strip`;
    },
    ({ model: m }) => `u = (${m.knots.map((v) => texNumber(v, 2)).join(',\\ ')})`,
  ),
  // Row r = 0 … p, one press each: on equally spaced knots each row's pieces are
  // written out, so the presses derive the uniform bases (row 3: B0(t) … B3(t)).
  repeat(
    'row',
    (state) => state.degree + 1,
    ({ model, index }) => rowCaption(model, index - 1),
    ({ model: m, index, times }) => {
      const last = index === times;
      const pieces = piecesTex(m, index - 1);
      // The last row sums to 1: after the pieces, or in the triangle's own Σ column.
      if (pieces === null) return triangleTex(m, index - 1, last);
      const sum = `\\quad \\textstyle\\sum_i N_{i,${m.degree}} = ${n3(m.basis.reduce((a, b) => a + b, 0))}`;
      return last ? pieces + sum : pieces;
    },
  ),
  step(
    'curve',
    ({ state }) => {
      const n = state.points.length;
      const p = state.degree;
      return state.part === 'clamped'
        ? `The curve of degree ${p}: with p + 1 = ${p + 1} equal end knots it starts at P0 and ends at P${n - 1}`
        : `The curve of degree ${p}: at a knot of multiplicity k it is C${superscript(p)}⁻ᵏ`;
    },
    ({ model: m }) => `P(${n3(m.u)}) = ${blend(m.basis, (i) => `P_{${i}}`)} = ${pt(m.point)}`,
  ),
);
