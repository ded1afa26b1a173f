/**
 * Numbers and formulas as the lessons write them: in captions (plain words
 * and Unicode, read aloud by a lecturer) and in TeX (the step's formula).
 * Every lesson formats through here, so one number reads the same everywhere.
 */

// The TeX number and point live with the formula renderer, which fills them
// into live formulas; they are offered here so a lesson has one place to look.
import { texNumber } from '../render/formula';

export { filled, texNumber, texPoint } from '../render/formula';

export { sub, subscriptNames } from './subscripts';

/**
 * A number to at most `digits` decimals, trailing zeros dropped: 0.5, not
 * 0.500. Tiny negatives come out as "0" (String(-0) is "0").
 */
export const trimmed = (value: number, digits: number) => String(Number(value.toFixed(digits)));

/** A number in a caption: up to three decimals, trailing zeros dropped, a true minus sign. */
export const words = (v: number) => trimmed(v, 3).replace('-', '−');

/**
 * Numbers that are read together, as a point's coordinates are. Exact at
 * `digits` decimals, each is written as a hand computation writes it: (0.5, 1),
 * (42, 21.5). Once one of them is rounded, all are written to `digits`, so the
 * zeros say how precise each is: (−1.962, 2.569, 9.000), not (−1.962, 2.569, 9).
 */
export function together(values: readonly number[], digits: number): string[] {
  const rounded = values.some((v) => Math.abs(Number(v.toFixed(digits)) - v) > RESIDUE);
  return values.map((v) => (rounded ? texNumber(v, digits) : trimmed(v, digits)));
}

/** A point in words, its coordinates written together: (2, −1.5), (0.333, 1.000). */
export const pointWords = (p: readonly number[]) =>
  `(${together(p, 3)
    .map((text) => text.replace('-', '−'))
    .join(', ')})`;

/** A point in TeX to at most `digits` decimals, its coordinates written together. */
export const texTogether = (p: readonly number[], digits: number) =>
  `(${together(p, digits).join(',\\ ')})`;

/** A number in a table cell of plain text: fixed `digits` decimals, a true minus sign, never "−0.0000". */
export const fixed = (v: number, digits: number) => texNumber(v, digits).replace('-', '−');

/** A parameter (t, μ) as typed: up to four decimals, trailing zeros dropped. */
export const texT = (t: number) => trimmed(t, 4);

/** Below this a difference that is zero in exact arithmetic is a rounding residue. */
export const RESIDUE = 1e-9;

/**
 * A difference that is zero in exact arithmetic, in TeX: a rounding residue
 * (8.9e-16) is written 0, as a lecturer reads it out; a true difference is
 * written to four decimals.
 */
export const texResidue = (v: number) => (Math.abs(v) < RESIDUE ? '0' : texNumber(v, 4));

const SUPERSCRIPTS = '⁰¹²³⁴⁵⁶⁷⁸⁹';
/** A whole number as Unicode superscript digits (C², 10⁻¹⁵), for captions, labels and tables. */
export const superscript = (n: number) =>
  [...String(n)].map((c) => (c === '-' ? '⁻' : SUPERSCRIPTS[Number(c)])).join('');

/**
 * A continuity as the notes write it, its order raised: "C1" → "C¹", "G2" →
 * "G²"; anything else ("none") as it is. For tables and captions of plain text.
 */
export const continuityName = (c: string) =>
  c.replace(
    /^([CG])(\d)$/,
    (_, letter: string, order: string) => letter + superscript(Number(order)),
  );

/** A tiny number as a person writes it: "0", or "3.6 × 10⁻¹⁵" (never "3.6e-15" or "0.0e+0"). */
export function smallNumber(v: number): string {
  if (v === 0) return '0';
  const [mantissa, exponent] = v.toExponential(1).split('e');
  return `${mantissa.replace('-', '−')} × 10${superscript(Number(exponent))}`;
}

/**
 * Equations in a row, `a = 1,\ b = 2`, that a narrow box breaks only between
 * them, after a comma: each is a group no break goes into. Broken after any
 * "=", "B₂(0.3) =" ended one line and "0.3482" began the next (a 1366 × 768
 * projector), and a last value stood on a line of its own.
 */
export function termRow(terms: readonly string[], space = '\\ '): string {
  return terms.map((term) => `{${term}}`).join(`,\\allowbreak${space}`);
}
