import { type Point, basisValuesAt } from '../../math';
import type { BlendingModel } from './model';

// What is hovered, by id: a control point's handle `p3` or its Bernstein curve
// `w3` (the same point), or a comparison function's curve or row `c3`.

/** The control point a hover refers to: its handle `p3` or its basis curve `w3`. */
export function highlightedIndex(hover: string | null): number | null {
  const match = hover ? /^[pw](\d+)$/.exec(hover) : null;
  return match ? Number(match[1]) : null;
}

/** The comparison function a hover refers to: its curve or its row, `c2`. */
export function comparedIndex(hover: string | null): number | null {
  const match = hover ? /^c(\d+)$/.exec(hover) : null;
  return match ? Number(match[1]) : null;
}

/** Which function's curve passes within `reach` of `at` in the plot: `c2` or `w1`, or null. */
export function curveNear(m: BlendingModel, at: Point, reach: number): string | null {
  const nearest = (values: readonly number[]) => {
    let best = -1;
    let bestDistance = reach;
    values.forEach((v, i) => {
      if (Math.abs(v - at[1]) <= bestDistance) {
        best = i;
        bestDistance = Math.abs(v - at[1]);
      }
    });
    return best;
  };
  if (m.compared) {
    const i = nearest(basisValuesAt(m.compared.samples, at[0]));
    if (i >= 0) return `c${i}`;
  }
  const i = nearest(basisValuesAt(m.bernstein.samples, at[0]));
  return i >= 0 ? `w${i}` : null;
}
