import type { Point } from '../../math';

// The numbers a student pastes, as x y points: whatever separates them, and how
// far each printed number may be from the value it stands for. Pure; never throws.

export type Read =
  | { ok: true; points: Point[]; slack: Point[]; transposed: boolean }
  | { ok: false; message: string };

const SEPARATORS = /[\s,;()[\]{}]+/;
const NUMBER = /^[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?$/;
// What C, C++ and Python print for a failed computation.
const NOT_FINITE = /^[+-]?(?:nan|inf|infinity)$/i;

/**
 * How far a printed number may be from the value it stands for. 0.111111
 * stands for anything within 5·10⁻⁷; a whole number such as 2, as printed by
 * C++'s default six significant digits, for anything within 5·10⁻⁶ of it.
 */
export function printedSlack(token: string): number {
  if (NOT_FINITE.test(token)) return 0;
  const [mantissa, exponent = '0'] = token.toLowerCase().split('e');
  if (mantissa.includes('.')) {
    const decimals = mantissa.split('.')[1].length - Number(exponent);
    return 0.5 * 10 ** -decimals;
  }
  const value = Math.abs(Number(token));
  return value === 0 ? 0 : 0.5 * 10 ** (Math.floor(Math.log10(value)) - 5);
}

/** A token's value: nan is NaN, inf ±Infinity (Number('inf') would be NaN). */
const valueOf = (token: string) =>
  NOT_FINITE.test(token) && !/nan/i.test(token)
    ? (token.startsWith('-') ? -1 : 1) * Infinity
    : Number(token);

const shorten = (token: string) => (token.length > 24 ? `${token.slice(0, 24)}…` : token);

/**
 * The numbers of `text` as x y points. Separators: any whitespace, commas,
 * semicolons, brackets, new lines. Two lines of `rows` numbers each are read
 * as a 2 × rows matrix (all x, then all y), as Eigen prints the transpose.
 */
export function readPoints(text: string, rows = 0): Read {
  // A true minus sign (from a document) and Windows' "-nan(ind)" read as C prints them.
  const cleaned = text.replace(/[\u2212\u2012\u2013]/g, '-').replace(/nan\([a-z]*\)/gi, 'nan');
  const lines: { numbers: number[]; tokens: string[] }[] = [];
  const all = cleaned.split(/\r\n|\r|\n/);
  for (let line = 0; line < all.length; line++) {
    const tokens = all[line].split(SEPARATORS).filter(Boolean);
    for (const token of tokens) {
      if (!NUMBER.test(token) && !NOT_FINITE.test(token))
        return {
          ok: false,
          message: `“${shorten(token)}” on line ${line + 1} is not a number. Paste only the numbers your program printed, x and y of each control point; spaces, commas, semicolons, brackets and new lines may separate them.`,
        };
    }
    if (tokens.length > 0) lines.push({ numbers: tokens.map(valueOf), tokens });
  }
  const numbers = lines.flatMap((l) => l.numbers);
  const tokens = lines.flatMap((l) => l.tokens);
  if (numbers.length === 0)
    return {
      ok: false,
      message:
        'No numbers yet: paste the control points your computeSplineC1 or computeSplineC2 printed, x and y of each.',
    };
  const transposed =
    rows > 2 &&
    lines.length === 2 &&
    lines[0].numbers.length === rows &&
    lines[1].numbers.length === rows;
  if (transposed) {
    const [xs, ys] = lines;
    return {
      ok: true,
      transposed,
      points: xs.numbers.map((x, j) => [x, ys.numbers[j]]),
      slack: xs.tokens.map((x, j) => [printedSlack(x), printedSlack(ys.tokens[j])]),
    };
  }
  if (numbers.length % 2 === 1)
    return {
      ok: false,
      message: `${numbers.length} numbers do not pair into x y points: one is missing or one too many (the last, ${shorten(tokens[tokens.length - 1])}, has no partner).`,
    };
  return {
    ok: true,
    transposed,
    points: Array.from({ length: numbers.length / 2 }, (_, j) => [
      numbers[2 * j],
      numbers[2 * j + 1],
    ]),
    slack: Array.from({ length: numbers.length / 2 }, (_, j) => [
      printedSlack(tokens[2 * j]),
      printedSlack(tokens[2 * j + 1]),
    ]),
  };
}
