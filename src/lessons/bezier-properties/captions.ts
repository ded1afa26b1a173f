import type { Point } from '../../math';
import { sub } from '../../kit/format';

/** The control points, in words: "The 4 control points P₀ … P₃" (every experiment's step 0). */
export const pointsCaption = (p: readonly Point[]) =>
  `The ${p.length} control points P₀ … P${sub(p.length - 1)}`;

/** "1 split", "3 splits". */
export const plural = (count: number, one: string, many = `${one}s`) =>
  `${count} ${count === 1 ? one : many}`;
