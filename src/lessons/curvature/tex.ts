import { texNumber, texPoint, texT } from '../../kit/format';
import type { Point } from '../../math';

// The lesson's numbers in TeX, each kind to its own fixed digits through the
// kit (so a rounding residue such as 2.7·10⁻¹⁶ reads 0, never as a power of ten).

/** κ, τ, R, a length: three decimals. */
export const value = (v: number) => texNumber(v, 3);

/** A point or a velocity: two decimals per coordinate. */
export const point = (p: Point) => texPoint(p, 2);

/** A unit vector (T, N, B): three decimals per coordinate. */
export const unit = (v: Point) => texPoint(v, 3);

/** The cursor t as it is set (up to four decimals). */
export const parameter = (t: number) => texT(t);

/** Parameters the model found (inflections, cusps, flips), two decimals, separated by commas. */
export const list = (ts: readonly number[]) => ts.map((t) => texNumber(t, 2)).join(',\\ ');
