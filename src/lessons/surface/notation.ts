import { texTogether, trimmed } from '../../kit/format';
import type { Continuity } from '../../math';
import { texNumber } from '../../render/formula';
import type { JoinReport } from './model';

// How the captions and formulas write numbers, points, matrices and joins.

/** A parameter value with up to two decimals: 0.3, 0.65. */
export const num = (value: number) => trimmed(value, 2);
/** A point to three decimals, written together (kit/format): (0.9, 1.8, 0.895), (1.962, 2.569, 9.000). */
export const point = (p: readonly number[]) => texTogether(p, 3);
/** Numbers as one row of a TeX matrix. */
export const list = (values: readonly number[], digits = 4) =>
  values.map((value) => texNumber(value, digits)).join(' & ');
/** A TeX matrix of its rows. */
export const matrix = (rows: readonly (readonly number[])[], digits = 4) =>
  `\\begin{bmatrix}${rows.map((row) => list(row, digits)).join('\\\\')}\\end{bmatrix}`;

/** P(u, v) with its parameters, in TeX. */
export const pointAt = (state: { u: number; v: number }) =>
  `\\mathbf{P}(${num(state.u)},${num(state.v)})`;
/** The patch as the slides' double sum. */
export const DOUBLE_SUM = '\\sum_{m=0}^{3}\\sum_{n=0}^{3} f_m(u)\\,f_n(v)\\,\\mathbf{P}_{m,n}';

/** A continuity class as the notes write it. */
export const continuityName = (c: Continuity): string =>
  ({ none: 'gap', C0: 'C⁰', G1: 'G¹', C1: 'C¹', G2: 'G²', C2: 'C²' })[c];

/** In words, how the joined patches meet. */
export function joinVerdict(report: JoinReport): string {
  switch (report.weakest) {
    case 'none':
      return 'the edges no longer meet: not even C⁰, there is a gap';
    case 'C0':
      return 'the legs across the edge are not collinear: C⁰ only, a crease';
    case 'G1':
      return 'the legs are collinear but of unequal length: G¹, smooth but not C¹';
    default:
      return 'the legs are collinear and equally long: C¹, the surface is smooth across';
  }
}
