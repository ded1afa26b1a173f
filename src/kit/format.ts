/**
 * Numbers and formulas as the lessons write them: in captions (plain words
 * and Unicode, read aloud by a lecturer) and in TeX (the step's formula).
 * Every lesson formats through here, so one number reads the same everywhere.
 */

// The TeX number and point live with the formula renderer, which fills them
// into live formulas; they are offered here so a lesson has one place to look.
import { texNumber } from '../render/formula';

export { filled, texNumber, texPoint } from '../render/formula';

const SUBSCRIPTS = '₀₁₂₃₄₅₆₇₈₉';

/** 12 → "₁₂": an index as Unicode subscripts, for captions that are plain text. */
export const sub = (i: number) => [...String(i)].map((d) => SUBSCRIPTS[Number(d)]).join('');

/** A point or vector letter, not inside a word, and its index digits. */
const NAME_INDEX = /(?<![A-Za-z])([PDBQLH])(\d+)(?![\d.]\d)/g;

/** A point or vector letter with a letter for its index, as a word of its own: Pm, Di. */
const NAME_LETTER = /(?<![A-Za-z])([PDBQLH])([ijkmn])(?![\p{L}\d(])/gu;

/**
 * A name indexed in brackets, as code writes it: P(i−1), N(i,2), u(i+1). The
 * first index is a letter (so P(t), a point of the curve, and P(0) stay).
 */
const NAME_BRACKETS =
  /(?<![A-Za-z])([PDBQLHNux])\(([ijkmnr](?:[+−]\d+)?)(?:,\s?([\dijkmnrp](?:[+−]\d+)?))?\)/g;

const SUBSCRIPT_OF: Record<string, string> = {
  i: 'ᵢ',
  j: 'ⱼ',
  k: 'ₖ',
  m: 'ₘ',
  n: 'ₙ',
  p: 'ₚ',
  r: 'ᵣ',
  '+': '₊',
  '−': '₋',
};

/** "i+1" → "ᵢ₊₁": an index of letters, signs and digits as Unicode subscripts. */
const subscriptIndex = (index: string) =>
  [...index].map((c) => SUBSCRIPT_OF[c] ?? SUBSCRIPTS[Number(c)]).join('');

/**
 * A caption's point and vector names with their indices as subscripts, as the
 * figure labels them: "P0 … P4" reads "P₀ … P₄", "H0P1" reads "H₀P₁", "Pm"
 * reads "Pₘ", and "N(i,2)" and "P(i−1)" read "Nᵢ,₂" and "Pᵢ₋₁". The
 * letters are those of points, gradients and weights (P, D, B, Q, L, H);
 * continuity (C1, G1) is a superscript the lessons write themselves.
 */
export const subscriptNames = (text: string) =>
  text
    .replace(NAME_INDEX, (_, letter: string, index: string) => letter + sub(Number(index)))
    .replace(NAME_LETTER, (_, letter: string, index: string) => letter + subscriptIndex(index))
    .replace(
      NAME_BRACKETS,
      (_, letter: string, first: string, second: string | undefined) =>
        letter + subscriptIndex(first) + (second ? ',' + subscriptIndex(second) : ''),
    );

/**
 * A number to at most `digits` decimals, trailing zeros dropped: 0.5, not
 * 0.500. Tiny negatives come out as "0" (String(-0) is "0").
 */
export const trimmed = (value: number, digits: number) => String(Number(value.toFixed(digits)));

/** A number in a caption: up to three decimals, trailing zeros dropped, a true minus sign. */
export const words = (v: number) => trimmed(v, 3).replace('-', '−');

/** A point in words: (2, −1.5). */
export const pointWords = (p: readonly number[]) => `(${p.map(words).join(', ')})`;

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
