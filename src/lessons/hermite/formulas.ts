import { hermiteMatrix, type Point } from '../../math';
import { HERMITE_LECTURE_INVERSE, HERMITE_LECTURE_MATRIX } from '../../math/hermite';
import { texNumber } from '../../render/formula';
import { type FormulaParts, joined, live, livePoint, tex } from '../../render/formulaParts';

// The lesson's formulas with live numbers: the numbers are written as text
// into a shape typeset once, so a drag changes text, not typesetting. The
// panel shows them in full; a step's formula (presenter view) is the same
// parts, filled in.

/** Points as a column of rows (4 × 2 for a patch's data), one point a row, to 2 decimals as points are written (at 3, equation 7 with its numbers ran up to 434 px in a laptop's 404 px panel). */
const column = (rows: readonly Point[], digits = 2) =>
  tex`\begin{pmatrix}${joined(
    rows.map((q) =>
      joined(
        q.map((v) => live(texNumber(v, digits))),
        ' & ',
      ),
    ),
    '\\\\',
  )}\end{pmatrix}`;

const matrixTex = (rows: readonly (readonly number[])[]) =>
  `\\begin{pmatrix}${rows.map((row) => row.join(' & ')).join('\\\\')}\\end{pmatrix}`;
const nameColumn = (names: readonly string[]) =>
  `\\begin{pmatrix}${names.join('\\\\')}\\end{pmatrix}`;

/** Equation 6 of the lecture as a matrix, and its inverse (equation 7): the lecture's order. */
const LECTURE_MATRIX = matrixTex(HERMITE_LECTURE_MATRIX);
const LECTURE_INVERSE = matrixTex(HERMITE_LECTURE_INVERSE);
const UNKNOWNS = nameColumn(['a_0', 'a_1', 'a_2', 'a_3']);
/** The continuation notes' inverse: (a, b, c, d) of at³ + bt² + ct + d from (x0, x1, x0′, x1′). */
const CONTINUATION_INVERSE = matrixTex(hermiteMatrix().reverse());
const CONTINUATION_UNKNOWNS = nameColumn(['a', 'b', 'c', 'd']);

/** Patch i's data by name, in the lecture's order: Pi, Di, Pi+1, Di+1. */
const lectureNames = (i: number) => [`P_{${i}}`, `D_{${i}}`, `P_{${i + 1}}`, `D_{${i + 1}}`];

/** The end data of a patch in the lecture's order: point, gradient, next point, next gradient. */
export type LectureData = readonly [Point, Point, Point, Point];

/**
 * Equation 6 with the patch's numbers: the ends at μ = 0 and μ = 1 give four
 * conditions on a0 … a3, written as the lecture writes them.
 */
export const conditions = (i: number, data: LectureData): FormulaParts => {
  const names = lectureNames(i);
  const sums = ['a_0', 'a_1', 'a_3 + a_2 + a_1 + a_0', '3a_3 + 2a_2 + a_1'];
  return tex`\begin{aligned}${joined(
    data.map((q, k) => tex`${names[k]} = ${livePoint(q, 3)} &= ${sums[k]}`),
    '\\\\ ',
  )}\end{aligned}`;
};

/** The same four conditions as one matrix times a0 … a3 (the lecture's order of the data). */
export const conditionsMatrix = (i: number, data: LectureData): FormulaParts =>
  tex`${LECTURE_MATRIX}${UNKNOWNS} = ${nameColumn(lectureNames(i))} = ${column(data)}`;

/** Equation 7 with the patch's numbers: a0 … a3 = the inverse times the data. */
export const inverted = (data: LectureData, coefficients: readonly Point[]): FormulaParts =>
  tex`${UNKNOWNS} = ${LECTURE_INVERSE}${column(data)} = ${column(coefficients)}`;

/** The four conditions as one matrix, by name: the panel's second line (its numbers are in the first). */
export const conditionsMatrixByName = (i: number): string =>
  `${LECTURE_MATRIX}${UNKNOWNS} = ${nameColumn(lectureNames(i))}`;

/**
 * The continuation notes' form with the patch's numbers: the data in their
 * order (x0, x1, x0′, x1′), their inverse, and (a, b, c, d), which are the
 * lecture's a3, a2, a1, a0.
 */
export const continuationSystem = (
  data: LectureData,
  coefficients: readonly Point[],
): FormulaParts => {
  const [p0, d0, p1, d1] = data;
  return tex`${CONTINUATION_UNKNOWNS} = ${CONTINUATION_INVERSE}${column([p0, p1, d0, d1])} = ${column([...coefficients].reverse())}`;
};

/** Which column of equation 7 each of H0 … H3 is: the columns weigh Pi, Di, Pi+1, Di+1. */
const COLUMN_OF = [0, 2, 1, 3];
const POLYNOMIALS = [
  '2\\mu^3 - 3\\mu^2 + 1',
  '-2\\mu^3 + 3\\mu^2',
  '\\mu^3 - 2\\mu^2 + \\mu',
  '\\mu^3 - \\mu^2',
];

/**
 * H_k read down its column of the lecture's inverse, the column's entries
 * weighting 1, μ, μ², μ³: one line, so the figure keeps its room.
 */
export const basisFromColumns = (ks: readonly number[]): string =>
  ks
    .map((k) => {
      const column = HERMITE_LECTURE_INVERSE.map((row) => row[COLUMN_OF[k]]);
      return `H_${k} = (${column.join(',\\ ')})\\cdot(1,\\ \\mu,\\ \\mu^2,\\ \\mu^3) = ${POLYNOMIALS[k]}`;
    })
    .join(',\\qquad ');

/** H0 Pi + H1 Pi+1 + H2 Di + H3 Di+1 with the weights' numbers: signs in the shape, never "+ −". */
function weightedTerms(names: readonly string[], weights: readonly number[]): FormulaParts {
  const terms = weights.map((w, term) => {
    const sign = term === 0 ? (w < 0 ? '-' : '') : w < 0 ? ' - ' : ' + ';
    return tex`${sign}${live(texNumber(Math.abs(w), 3))}\,${names[term]}`;
  });
  return joined(terms, '');
}

/** What H0 … H3 weigh on patch i (the continuation notes' order: x0, x1, x0′, x1′). */
const basisNames = (i: number) => [`P_{${i}}`, `P_{${i + 1}}`, `D_{${i}}`, `D_{${i + 1}}`];

/** P(μ) on patch i from the basis: the names, the weights, the point. */
export const basisLine = (i: number, mu: number, weights: readonly number[], point: Point) =>
  tex`\begin{aligned}P(${live(texNumber(mu, 3))}) &= H_0 P_{${i}} + H_1 P_{${i + 1}} + H_2 D_{${i}} + H_3 D_{${i + 1}}\\ &= ${weightedTerms(basisNames(i), weights)}\\ &= ${livePoint(point, 3)}\end{aligned}`;

/** P(μ) from the basis in one line, signs in the shape: for the presenter's caption. */
export const basisOneLine = (i: number, mu: number, weights: readonly number[], point: Point) =>
  tex`P(${live(texNumber(mu, 3))}) = ${weightedTerms(basisNames(i), weights)} = ${livePoint(point, 3)}`;

/** B0 … B3 of the patch as a Bézier curve: a column in the panel, one line in the presenter's caption. */
export function bezierPoints(bezier: readonly Point[], oneLine = false): FormulaParts {
  const eq = oneLine ? '=' : '&=';
  const points = bezier.map((q, k) => tex`B_${k} ${eq} ${livePoint(q, 2)}`);
  return oneLine
    ? joined(points, ',\\quad ')
    : tex`\begin{aligned}${joined(points, '\\\\ ')}\end{aligned}`;
}

const BLEND = String.raw`(1-\mu)^3 B_0 + 3\mu(1-\mu)^2 B_1 + 3\mu^2(1-\mu) B_2 + \mu^3 B_3`;

/** The cubic Bézier curve as a blend of its control points, with their numbers. */
export const bezierBlend = (bezier: readonly Point[]): FormulaParts =>
  tex`\begin{gathered}P(\mu) = ${BLEND}\\ ${bezierPoints(bezier, true)}\end{gathered}`;

/** Its ends: P(0) = B0 = Pi and P(1) = B3 = Pi+1. */
export const bezierEnds = (i: number, bezier: readonly Point[]): FormulaParts =>
  tex`P(0) = B_0 = P_{${i}} = ${livePoint(bezier[0], 2)},\quad P(1) = B_3 = P_{${i + 1}} = ${livePoint(bezier[3], 2)}`;

/** Its end gradients, three times its end legs: the patch's gradients Di and Di+1. */
export const bezierGradients = (i: number, data: LectureData): FormulaParts =>
  tex`\begin{aligned}P'(0) &= 3(B_1 - B_0) = D_{${i}} = ${livePoint(data[1], 2)}\\ P'(1) &= 3(B_3 - B_2) = D_{${i + 1}} = ${livePoint(data[3], 2)}\end{aligned}`;

/** The Bézier curve's Hermite data, in the lecture's order. */
const BEZIER_DATA = nameColumn(['B_0', '3(B_1 - B_0)', 'B_3', '3(B_3 - B_2)']);

/**
 * "Bézier is a Hermite patch": equation 7 times (B0, 3(B1 − B0), B3,
 * 3(B3 − B2)), with the numbers, gives a0 … a3. Three lines in the panel
 * (two ran 409 px in a laptop's 404 with the long scene's gradients of 15).
 * In the presenter's caption one line, the product in numbers only (the
 * step's words name the column): with the product by name too, the line was
 * wider than the screen at 28 px, and set on two lines it took the figure's room.
 */
export const bezierProduct = (
  data: LectureData,
  coefficients: readonly Point[],
  oneLine = false,
): FormulaParts =>
  oneLine
    ? tex`${UNKNOWNS} = ${LECTURE_INVERSE}${column(data)} = ${column(coefficients)}`
    : tex`\begin{aligned}${UNKNOWNS} &= ${LECTURE_INVERSE}${BEZIER_DATA}\\ &= ${LECTURE_INVERSE}${column(data)}\\ &= ${column(coefficients)}\end{aligned}`;

/** The Bézier curve multiplied out (the lecture's a0 … a3 from its control points), with numbers. */
export const bezierExpanded = (power: readonly Point[]): FormulaParts => {
  const sums = ['B_0', '3B_1 - 3B_0', '3B_2 - 6B_1 + 3B_0', 'B_3 - 3B_2 + 3B_1 - B_0'];
  return tex`\begin{aligned}${joined(
    power.map((a, k) => tex`a_${k} &= ${sums[k]} = ${livePoint(a, 3)}`),
    '\\\\ ',
  )}\end{aligned}`;
};

/** One curve written two ways: the Bézier blend and the Hermite blend. */
export const bothBlends = (i: number) =>
  String.raw`P(\mu) = ${BLEND} = H_0 P_{${i}} + H_1 P_{${i + 1}} + H_2 D_{${i}} + H_3 D_{${i + 1}}`;

/** P(μ) from both blends with their weights' numbers: one point. */
export const bothBlendsAt = (
  i: number,
  mu: number,
  bernsteinWeights: readonly number[],
  hermiteWeights: readonly number[],
  point: Point,
): FormulaParts =>
  tex`\begin{aligned}P(${live(texNumber(mu, 3))}) &= ${weightedTerms(['B_0', 'B_1', 'B_2', 'B_3'], bernsteinWeights)}\\ &= ${weightedTerms(basisNames(i), hermiteWeights)}\\ &= ${livePoint(point, 3)}\end{aligned}`;
