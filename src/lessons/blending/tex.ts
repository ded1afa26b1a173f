import { superscript, texT } from '../../kit/format';
import { type Point, binomial } from '../../math';
import { texNumber } from '../../render/formula';
import { type FormulaParts, joined, live, livePoint, tex } from '../../render/formulaParts';

// TeX for the blending lesson's formulas. A formula with live numbers is
// FormulaParts: a shape typeset once per N, and the numbers written into it.

/** `3\mu^2(1-\mu)`: the term C(n, i) μⁱ (1−μ)ⁿ⁻ⁱ with the coefficient worked out. */
export function blendingTermTex(n: number, i: number): string {
  const c = binomial(n, i);
  const mu = i === 0 ? '' : i === 1 ? '\\mu' : `\\mu^{${i}}`;
  const rest = n - i === 0 ? '' : n - i === 1 ? '(1-\\mu)' : `(1-\\mu)^{${n - i}}`;
  const body = `${mu}${rest}`;
  return `${c === 1 && body ? '' : c}${body}`;
}

/** The whole expansion `P(μ) = (1−μ)³P₀ + 3μ(1−μ)²P₁ + …` for degree n. */
export function expansionTex(n: number, termsPerLine = Infinity): string {
  const terms = Array.from({ length: n + 1 }, (_, i) => `${blendingTermTex(n, i)}\\,P_{${i}}`);
  if (terms.length <= termsPerLine) return `P(\\mu) = ${terms.join(' + ')}`;
  // A long expansion (N = 6, 10) wraps, a few terms a line, aligned on "=".
  const lines: string[] = [];
  for (let i = 0; i < terms.length; i += termsPerLine)
    lines.push(terms.slice(i, i + termsPerLine).join(' + '));
  return `\\begin{aligned}P(\\mu) &= ${lines.join('\\\\ &\\quad + ')}\\end{aligned}`;
}

/** μ and 1 − μ as typed into a power: four decimals at most, no trailing zeros. */
const base = (v: number) => texNumber(v, 4).replace(/\.?0+$/, '') || '0';
const liveMu = (mu: number) => live(texT(mu));

/** W(n, i, μ) = C(n, i) μⁱ (1 − μ)ⁿ⁻ⁱ as its bases and powers, a power 0 left out. */
function powersOf(n: number, i: number, mu: number): [base: string, power: number][] {
  const powers: [string, number][] = [[String(binomial(n, i)), 1]];
  if (i > 0) powers.push([base(mu), i]);
  if (n - i > 0) powers.push([base(1 - mu), n - i]);
  return powers;
}

/** `W(3,1,0.3) = 3\cdot 0.3\cdot 0.7^{2}`: a weight with the numbers of μ in. */
export function weightFormula(n: number, i: number, mu: number): FormulaParts {
  const [binomialFactor, ...rest] = powersOf(n, i, mu);
  const factors = [
    tex`${binomialFactor[0]}`,
    ...rest.map(([b, k]) => (k === 1 ? live(b) : tex`${live(b)}^{${k}}`)),
  ];
  return tex`W(${n},${i},${liveMu(mu)}) = ${joined(factors, '\\cdot ')}`;
}

/**
 * The same weight as plain text, `W(3, 1, 0.3) = 3 · 0.3 · 0.7²`, for the
 * weights table: a typeset formula in each row was laid out again on every
 * frame of a μ drag (4 ms of a 20 ms frame, with N + 1 rows of them).
 */
export function weightText(n: number, i: number, mu: number): string {
  const factors = powersOf(n, i, mu).map(([b, k]) => (k === 1 ? b : b + superscript(k)));
  return `W(${n}, ${i}, ${texT(mu)}) = ${factors.join(' · ')}`;
}

/** Worked-out weights and the point stay readable on screen up to this degree. */
const SPELL_OUT_UP_TO = 6;

/**
 * P(μ) as the weighted sum, spelt out term by term for small N: the terms on
 * two lines (half of them each), then the point. One term a line, N = 6 took
 * eight lines, and in presenter view the caption crowded the figure (#19).
 */
export function pointFormula(
  mu: number,
  weights: readonly number[],
  p: readonly Point[],
  point: Point,
  flowing = false,
): FormulaParts {
  const n = p.length - 1;
  if (n > SPELL_OUT_UP_TO)
    return tex`P(${liveMu(mu)}) = \sum_{i=0}^{${n}} W(${n},i,${liveMu(mu)})\,P_i = ${livePoint(point, 4)}`;
  const terms = weights.map((w, i) => tex`${live(texNumber(w, 4))}\,${livePoint(p[i], 2)}`);
  // In the panel, one line the box breaks after a + where it must (a
  // laptop's panel fits two terms a line, a phone's one).
  if (flowing) return tex`P(${liveMu(mu)}) = ${joined(terms, ' + ')} = ${livePoint(point, 4)}`;
  const perLine = Math.ceil(terms.length / 2);
  const lines = [terms.slice(0, perLine), terms.slice(perLine)].map((line) => joined(line, ' + '));
  return tex`\begin{aligned}P(${liveMu(mu)}) &= ${joined(lines, '\\\\ &\\quad + ')}\\ &= ${livePoint(point, 4)}\end{aligned}`;
}

/** The matrix M of P(μ) = U M P for degree n (the lecture slides' matrix form, in μ): it depends on n alone. */
export function matrixFormTex(matrix: readonly (readonly number[])[]): string {
  const n = matrix.length - 1;
  const powers = Array.from({ length: n + 1 }, (_, power) =>
    power === 0 ? '1' : power === 1 ? '\\mu' : `\\mu^{${power}}`,
  );
  const names = Array.from({ length: n + 1 }, (_, i) => `P_{${i}}`);
  const head = `\\begin{aligned}P(\\mu) &= U\\,M\\,\\mathbf{P},\\qquad U = \\begin{pmatrix}${powers.join(' & ')}\\end{pmatrix},\\\\ \\mathbf{P} &= \\begin{pmatrix}${names.join(' & ')}\\end{pmatrix}^{T},\\\\ `;
  // Past degree 6 the numbers of M are unreadable (and a 13 × 13 matrix takes a
  // whole frame to typeset): its entries are given by their rule instead.
  if (n > SPELL_OUT_UP_TO)
    return `${head}M_{ji} &= (-1)^{j-i}\\binom{${n}}{j}\\binom{j}{i}\\ (j \\ge i),\\quad M_{ji} = 0\\ (j < i)\\end{aligned}`;
  const rows = matrix.map((row) => row.join(' & ')).join('\\\\');
  return `${head}M &= \\begin{pmatrix}${rows}\\end{pmatrix}\\end{aligned}`;
}

/**
 * U·M at μ: the weights again, as a row, its entries apart by commas so the
 * panel may break the row after one (seven entries of four decimals are wider
 * than a laptop's panel).
 */
export const rowFormula = (mu: number, weights: readonly number[]) =>
  tex`\text{at } \mu = ${liveMu(mu)}:\quad U M = (${joined(
    weights.map((w) => live(texNumber(w, 4))),
    ',\\allowbreak\\ ',
  )})`;

/** P(½) = Σ C(N, i)/2ᴺ Pᵢ: the "centre-weighted centroid", then its value. */
export function centroidFormula(n: number, centre: Point): FormulaParts {
  const terms = Array.from(
    { length: n + 1 },
    (_, i) => `\\tfrac{${binomial(n, i)}}{${2 ** n}}P_{${i}}`,
  );
  // One line, broken after a + where the panel must (N = 10: 584 px).
  return tex`P(0.5) = ${terms.join(' + ')} = ${livePoint(centre, 4)}`;
}
