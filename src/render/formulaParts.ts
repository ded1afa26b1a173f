import { SLOT, texNumber } from './formula';

/**
 * A formula for a LiveFormula: its TeX shape, with `\val` where each live
 * number goes, and the numbers' texts in order. The shape is typeset once;
 * new numbers are only written as text.
 */
export interface FormulaParts {
  shape: string;
  values: string[];
}

/** One live number, as the text it shows. */
export const live = (text: string): FormulaParts => ({ shape: SLOT, values: [text] });

/**
 * TeX with live parts: `tex\`x = ${live('1.00')}\``. The template is read raw
 * (as String.raw does), so TeX is written as TeX: `\frac`, `\\` for a new
 * line. Strings and numbers go into the shape as they are; FormulaParts
 * bring their shape and their values.
 */
export function tex(
  strings: TemplateStringsArray,
  ...parts: (string | number | FormulaParts)[]
): FormulaParts {
  let shape = strings.raw[0];
  const values: string[] = [];
  parts.forEach((part, i) => {
    if (typeof part === 'object') {
      shape += part.shape;
      values.push(...part.values);
    } else shape += String(part);
    shape += strings.raw[i + 1];
  });
  return { shape, values };
}

/** Parts one after another, with `separator` (TeX) between them. */
export function joined(parts: readonly FormulaParts[], separator: string): FormulaParts {
  return {
    shape: parts.map((part) => part.shape).join(separator),
    values: parts.flatMap((part) => part.values),
  };
}

/** A point with live coordinates to `digits` decimals: `(\val,\ \val)`. */
export const livePoint = (p: readonly number[], digits = 2): FormulaParts =>
  tex`(${joined(
    p.map((v) => live(texNumber(v, digits))),
    ',\\ ',
  )})`;

/**
 * A TeX formula written with its numbers in it, split for a LiveFormula: each
 * decimal number (digits, a point, digits, perhaps an exponent) becomes a slot, so a drag that
 * only changes the numbers writes text instead of typesetting again. Signs
 * stay in the shape (a binary and a unary minus are spaced differently), and
 * so do integers (indices, counts: they change the shape when they change)
 * and lengths in TeX units (`\kern0.5em`).
 */
export function slotNumbers(texText: string): FormulaParts {
  const values: string[] = [];
  const shape = texText.replace(NUMBER, (number: string) => {
    values.push(number);
    return SLOT;
  });
  return { shape, values };
}

const NUMBER = /(?<![\d.])\d+\.\d+(?:e[-+]?\d+)?(?![\d.]|\s*(?:em|ex|mu|pt|px|cm|mm|in|bp|pc)\b)/g;
