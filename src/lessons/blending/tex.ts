import { binomial } from '../../math';
import { texNumber } from '../../render/formula';

// TeX for the blending lesson's formulas, built from numbers the maths module computed.

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

/** `3 \cdot 0.3^{1} \cdot 0.7^{2}`: the term with the numbers of μ in. */
export function blendingNumbersTex(n: number, i: number, mu: number): string {
  const m = texNumber(mu, 4).replace(/\.?0+$/, '') || '0';
  const s = texNumber(1 - mu, 4).replace(/\.?0+$/, '') || '0';
  const parts = [String(binomial(n, i))];
  if (i > 0) parts.push(i === 1 ? m : `${m}^{${i}}`);
  if (n - i > 0) parts.push(n - i === 1 ? s : `${s}^{${n - i}}`);
  return parts.join('\\cdot ');
}

/** A matrix as a TeX pmatrix. */
export function matrixTex(matrix: readonly (readonly number[])[]): string {
  return `\\begin{pmatrix}${matrix.map((row) => row.join(' & ')).join('\\\\')}\\end{pmatrix}`;
}

/** A row vector of numbers, e.g. the weights U·M at μ. */
export function rowTex(values: readonly number[], digits = 4): string {
  return `\\begin{pmatrix}${values.map((v) => texNumber(v, digits)).join(' & ')}\\end{pmatrix}`;
}
