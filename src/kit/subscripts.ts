/**
 * Indices as Unicode subscripts, for plain text (captions, panel prose) that
 * names points as the figures label them. No imports: the page's element
 * builder uses it too.
 */

const SUBSCRIPTS = '₀₁₂₃₄₅₆₇₈₉';

/** 12 → "₁₂": an index as Unicode subscripts, for captions that are plain text. */
export const sub = (i: number) => [...String(i)].map((d) => SUBSCRIPTS[Number(d)]).join('');

/** A point or vector letter, not inside a word, and its index digits (two for a net's P2,1). */
const NAME_INDEX = /(?<![A-Za-z])([PDBQLH])(\d+)(?:,(\d+))?(?![\d.]\d)/g;

/** A point or vector letter with a letter for its index, as a word of its own: Pm, Di. */
const NAME_LETTER = /(?<![A-Za-z])([PDBQLH])([ijkmn])(?![\p{L}\d(])/gu;

/**
 * A name indexed in brackets, as code writes it: P(i−1), N(i,2), u(i+1). The
 * first index is a letter (so P(t), a point of the curve, and P(0) stay).
 */
const NAME_BRACKETS =
  /(?<![A-Za-z])([PDBQLHNux])\(([ijkmnrp](?:[+−]\d+)?)(?:,\s?([\dijkmnrp](?:[+−]\d+)?))?\)/g;

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
    .replace(
      NAME_INDEX,
      (_, letter: string, index: string, second: string | undefined) =>
        letter + sub(Number(index)) + (second ? ',' + sub(Number(second)) : ''),
    )
    .replace(NAME_LETTER, (_, letter: string, index: string) => letter + subscriptIndex(index))
    .replace(
      NAME_BRACKETS,
      (_, letter: string, first: string, second: string | undefined) =>
        letter + subscriptIndex(first) + (second ? ',' + subscriptIndex(second) : ''),
    );
