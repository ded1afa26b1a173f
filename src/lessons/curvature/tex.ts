import type { Point } from '../../math';

/** A number in TeX: four significant digits, a true minus sign. */
export const tex = (value: number, digits = 4) => {
  const text = Number(value.toPrecision(digits)).toString();
  return text.includes('e') ? value.toExponential(2).replace('e', '\\times 10^{') + '}' : text;
};

/** A vector in TeX, each coordinate to four significant digits. */
export const vec = (v: Point) => `(${v.map((x) => tex(x)).join(',\\ ')})`;

/** Parameters in TeX, separated by commas. */
export const list = (ts: readonly number[]) => ts.map((t) => tex(t)).join(',\\ ');
