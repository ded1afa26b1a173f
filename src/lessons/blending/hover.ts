import { type Point, basisValuesAt } from '../../math';
import type { BlendingModel } from './model';
import { controlPoints } from './points';

// What is hovered, by id: a control point's handle (`p3`) or its Bernstein
// curve or row (`w3`), both meaning the same point; or a comparison
// function's curve or row (`c3`).

/** The ids of one series of hoverable things (a function's curve and its table row). */
function series(prefix: string) {
  const pattern = new RegExp(`^${prefix}(\\d+)$`);
  return {
    id: (i: number) => `${prefix}${i}`,
    /** Which function an id names, or null if it is not one of this series. */
    index(id: string | null): number | null {
      const match = id === null ? null : pattern.exec(id);
      return match ? Number(match[1]) : null;
    },
  };
}

/** W(N, i, μ): its curve on the plot and its row of the weights table. */
export const weightIds = series('w');
/** The functions of the basis compared with: their curves and rows. */
export const comparedIds = series('c');

/** The control point a hover refers to: its handle or its basis curve. */
export function highlightedIndex(hover: string | null): number | null {
  const handle = hover === null ? null : controlPoints.ref(hover);
  return handle ? handle.index : weightIds.index(hover);
}

/** The comparison function a hover refers to: its curve or its row. */
export const comparedIndex = (hover: string | null) => comparedIds.index(hover);

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
    if (i >= 0) return comparedIds.id(i);
  }
  const i = nearest(basisValuesAt(m.bernstein.samples, at[0]));
  return i >= 0 ? weightIds.id(i) : null;
}
