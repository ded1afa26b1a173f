import { texNumber, texPoint } from '../../kit/format';

/** A number in a formula: three decimals. */
export const n3 = (v: number) => texNumber(v, 3);
/** A point in a formula: two decimals. */
export const pt = (p: readonly number[]) => texPoint(p, 2);

export { superscript } from '../../kit/format';

/** A segment is named after its last control point, as the slides' c_i: Q_i blends P_{i−3} … P_i. */
export const segmentName = (first: number) => `Q${first + 3}`;
/** The same name with its subscript, for labels and TeX (`Q_{4}`). */
export const segmentLabel = (first: number) => segmentName(first).replace(/(\d+)/, '_{$1}');

/** Σ (number) P_i over the non-zero terms, e.g. `0.167\,P_{2} + 0.667\,P_{3}`. */
export function blend(values: readonly number[], names: (i: number) => string): string {
  return values
    .map((v, i) => (v === 0 ? '' : `${n3(v)}\\,${names(i)}`))
    .filter(Boolean)
    .join(' + ');
}
