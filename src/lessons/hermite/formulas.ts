import { hermiteMatrix, type Point } from '../../math';
import { SLOT, slotPoint, texNumber } from '../../render/formula';

// The TeX shapes of the panel's live formulas: each `\val` is a number filled
// in as text, so a drag changes text, not typesetting.

const coords = (p: Point, digits: number) => p.map((v) => texNumber(v, digits));

/** A 4 × 2 column of live numbers, one point a row. */
const column = `\\begin{pmatrix}${Array.from({ length: 4 }, () => `${SLOT} & ${SLOT}`).join('\\\\')}\\end{pmatrix}`;
const unknowns = '\\begin{pmatrix}a_0\\\\a_1\\\\a_2\\\\a_3\\end{pmatrix}';
const inverse = hermiteMatrix()
  .map((row) => row.join(' & '))
  .join('\\\\');

/** Equation 7: the four conditions as a matrix, its inverse, and the coefficients. */
export const SYSTEM = `\\begin{aligned}${column} &= \\begin{pmatrix}1&0&0&0\\\\1&1&1&1\\\\0&1&0&0\\\\0&1&2&3\\end{pmatrix}${unknowns}\\\\ ${unknowns} &= \\begin{pmatrix}${inverse}\\end{pmatrix}${column}\\\\ &= ${column}\\end{aligned}`;

/** The numbers of SYSTEM: the data [Pi, Pi+1, Di, Di+1] twice, then a0 … a3. */
export function systemValues(data: readonly Point[], coefficients: readonly Point[]): string[] {
  const given = data.flatMap((q) => coords(q, 3));
  return [...given, ...given, ...coefficients.flatMap((q) => coords(q, 3))];
}

/** P(μ) from the basis on patch i: the names, the weights, the point. */
export const basisLine = (i: number) =>
  `\\begin{aligned}P(${SLOT}) &= H_0 P_{${i}} + H_1 P_{${i + 1}} + H_2 D_{${i}} + H_3 D_{${i + 1}}\\\\ &= ${SLOT}\\,P_{${i}} + ${SLOT}\\,P_{${i + 1}} + ${SLOT}\\,D_{${i}} + ${SLOT}\\,D_{${i + 1}}\\\\ &= ${slotPoint()}\\end{aligned}`;

export function basisValues(mu: number, weights: readonly number[], point: Point): string[] {
  return [texNumber(mu, 3), ...weights.map((w) => texNumber(w, 3)), ...coords(point, 3)];
}

/** B0 … B3 of the patch as a Bézier curve. */
export const BEZIER_POINTS = `\\begin{aligned}${[0, 1, 2, 3].map((k) => `B_${k} &= ${slotPoint()}`).join('\\\\ ')}\\end{aligned}`;

export const bezierValues = (bezier: readonly Point[]) => bezier.flatMap((q) => coords(q, 2));
