import { type Point, binomial } from '../../math';
import { SLOT, slotPoint, texNumber } from '../../render/formula';
import { texMu } from './state';

// TeX for the blending lesson's formulas. A formula with live numbers is a
// shape with `\val` slots (typeset once per shape) and the numbers for them.

const coords = (p: Point, digits: number) => p.map((v) => texNumber(v, digits));

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
const power = (v: number) => texNumber(v, 4).replace(/\.?0+$/, '') || '0';

/** `W(3,1,\val) = 3\cdot \val\cdot \val^{2}`: a weight with the numbers of μ in. */
export function weightShape(n: number, i: number): string {
  const parts = [String(binomial(n, i))];
  if (i > 0) parts.push(i === 1 ? SLOT : `${SLOT}^{${i}}`);
  if (n - i > 0) parts.push(n - i === 1 ? SLOT : `${SLOT}^{${n - i}}`);
  return `W(${n},${i},${SLOT}) = ${parts.join('\\cdot ')}`;
}

export function weightValues(n: number, i: number, mu: number): string[] {
  return [texMu(mu), ...(i > 0 ? [power(mu)] : []), ...(n - i > 0 ? [power(1 - mu)] : [])];
}

/** Worked-out weights and the point stay readable on screen up to this degree. */
const SPELL_OUT_UP_TO = 6;

/** P(μ) as the weighted sum, spelt out term by term for small N. */
export function pointShape(n: number): string {
  if (n > SPELL_OUT_UP_TO)
    return `P(${SLOT}) = \\sum_{i=0}^{${n}} W(${n},i,${SLOT})\\,P_i = ${slotPoint()}`;
  const terms = Array.from({ length: n + 1 }, () => `${SLOT}\\,${slotPoint()}`);
  return `\\begin{aligned}P(${SLOT}) &= ${terms.join('\\\\ &\\quad + ')}\\\\ &= ${slotPoint()}\\end{aligned}`;
}

export function pointValues(
  mu: number,
  weights: readonly number[],
  p: readonly Point[],
  point: Point,
): string[] {
  const terms =
    p.length - 1 > SPELL_OUT_UP_TO
      ? [texMu(mu)]
      : weights.flatMap((w, i) => [texNumber(w, 4), ...coords(p[i], 2)]);
  return [texMu(mu), ...terms, ...coords(point, 4)];
}

/** The matrix M of x(u) = U M X for degree n: it depends on n alone. */
export function matrixFormTex(matrix: readonly (readonly number[])[]): string {
  const n = matrix.length - 1;
  const powers = Array.from({ length: n + 1 }, (_, k) =>
    k === 0 ? '1' : k === 1 ? 'u' : `u^{${k}}`,
  );
  const names = Array.from({ length: n + 1 }, (_, i) => `x_{${i}}`);
  const rows = matrix.map((row) => row.join(' & ')).join('\\\\');
  return `\\begin{aligned}x(u) &= U\\,M\\,X,\\qquad U = \\begin{pmatrix}${powers.join(' & ')}\\end{pmatrix},\\\\ X &= \\begin{pmatrix}${names.join(' & ')}\\end{pmatrix}^{T},\\\\ M &= \\begin{pmatrix}${rows}\\end{pmatrix}\\end{aligned}`;
}

/** U·M at u = μ: the weights again, as a row. */
export const rowShape = (count: number) =>
  `\\text{at } u = ${SLOT}:\\quad U M = \\begin{pmatrix}${Array.from({ length: count }, () => SLOT).join(' & ')}\\end{pmatrix}`;

export const rowValues = (mu: number, weights: readonly number[]) => [
  texMu(mu),
  ...weights.map((w) => texNumber(w, 4)),
];

/** x(½) = Σ C(N, i)/2ᴺ xᵢ: the "centre-weighted centroid", then its value. */
export function centroidShape(n: number): string {
  const terms = Array.from(
    { length: n + 1 },
    (_, i) => `\\tfrac{${binomial(n, i)}}{${2 ** n}}x_{${i}}`,
  );
  return `\\begin{aligned}x(0.5) &= ${terms.join(' + ')}\\\\ &= ${slotPoint()}\\end{aligned}`;
}

export const centroidValues = (centre: Point) => coords(centre, 4);
