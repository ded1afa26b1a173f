import { hermiteMatrix, type Point } from '../../math';
import { texNumber } from '../../render/formula';
import { type FormulaParts, joined, live, livePoint, tex } from '../../render/formulaParts';

// The panel's live formulas: the numbers are written as text into a shape
// typeset once, so a drag changes text, not typesetting.

/** Four points as a 4 × 2 column, one a row. */
const column = (rows: readonly Point[]) =>
  tex`\begin{pmatrix}${joined(
    rows.map((q) =>
      joined(
        q.map((v) => live(texNumber(v, 3))),
        ' & ',
      ),
    ),
    '\\\\',
  )}\end{pmatrix}`;
const CONDITIONS = String.raw`\begin{pmatrix}1&0&0&0\\1&1&1&1\\0&1&0&0\\0&1&2&3\end{pmatrix}`;
const UNKNOWNS = String.raw`\begin{pmatrix}a_0\\a_1\\a_2\\a_3\end{pmatrix}`;
const INVERSE = `\\begin{pmatrix}${hermiteMatrix()
  .map((row) => row.join(' & '))
  .join('\\\\')}\\end{pmatrix}`;

/** The four conditions: the data [Pi, Pi+1, Di, Di+1] as a matrix times a0 … a3, its inverse, and a0 … a3. */
export const system = (data: readonly Point[], coefficients: readonly Point[]): FormulaParts =>
  tex`\begin{aligned}${column(data)} &= ${CONDITIONS}${UNKNOWNS}\\ ${UNKNOWNS} &= ${INVERSE}${column(data)}\\ &= ${column(coefficients)}\end{aligned}`;

/** H0 Pi + H1 Pi+1 + H2 Di + H3 Di+1 with the weights' numbers: signs in the shape, never "+ −". */
function basisTerms(i: number, weights: readonly number[]): FormulaParts {
  const names = [`P_{${i}}`, `P_{${i + 1}}`, `D_{${i}}`, `D_{${i + 1}}`];
  const terms = weights.map((w, term) => {
    const sign = term === 0 ? (w < 0 ? '-' : '') : w < 0 ? ' - ' : ' + ';
    return tex`${sign}${live(texNumber(Math.abs(w), 3))}\,${names[term]}`;
  });
  return joined(terms, '');
}

/** P(μ) on patch i from the basis: the names, the weights, the point. */
export const basisLine = (i: number, mu: number, weights: readonly number[], point: Point) =>
  tex`\begin{aligned}P(${live(texNumber(mu, 3))}) &= H_0 P_{${i}} + H_1 P_{${i + 1}} + H_2 D_{${i}} + H_3 D_{${i + 1}}\\ &= ${basisTerms(i, weights)}\\ &= ${livePoint(point, 3)}\end{aligned}`;

/** B0 … B3 of the patch as a Bézier curve: a column in the panel, one line in the presenter's caption. */
export function bezierPoints(bezier: readonly Point[], oneLine = false): FormulaParts {
  const eq = oneLine ? '=' : '&=';
  const points = bezier.map((q, k) => tex`B_${k} ${eq} ${livePoint(q, 2)}`);
  return oneLine
    ? joined(points, ',\\quad ')
    : tex`\begin{aligned}${joined(points, '\\\\ ')}\end{aligned}`;
}

/** The patch matrix at work, in one line for the presenter's caption: a0 … a3 = M · data = numbers. */
export const patchMatrixLine = (
  data: readonly Point[],
  coefficients: readonly Point[],
): FormulaParts => tex`${UNKNOWNS} = ${INVERSE}${column(data)} = ${column(coefficients)}`;

/** P(μ) from the basis in one line, signs in the shape: for the presenter's caption. */
export const basisOneLine = (i: number, mu: number, weights: readonly number[], point: Point) =>
  tex`P(${live(texNumber(mu, 3))}) = ${basisTerms(i, weights)} = ${livePoint(point, 3)}`;
