/**
 * What the points do to the polynomial, in words: points on one spot or on
 * one line, and chord length given up for equally spaced values.
 */
import type { Point } from '../../math';
import { degenerate, repeatsText } from '../../kit/degenerate';
import type { LagrangeModel } from './model';

/** Coincident or collinear points, in words: what the polynomial does through them. */
export function noteFor(points: readonly Point[], collapsed: boolean): string | null {
  const { allSame, collinear, repeats } = degenerate(points);
  if (allSame) return 'All points are on one spot: the polynomial through them is that one point.';
  const notes: string[] = [];
  if (collinear)
    notes.push(
      'The points lie on one line: so does the polynomial, but it may overshoot a point and run back along the line.',
    );
  if (repeats.length && !collapsed)
    notes.push(
      `${repeatsText(repeats)}: the polynomial must be at that spot at two values of t, so it stops there or makes a loop.`,
    );
  return notes.length ? notes.join(' ') : null;
}

/** Why the values are uniform after all (two neighbours coincide): on the figure, and in the panel. */
export function collapsedNotes(
  collapsed: [number, number] | null,
): Pick<LagrangeModel, 'collapsedNote' | 'collapsedWarning'> {
  return {
    collapsedNote: collapsed
      ? `P${collapsed[0]} and P${collapsed[1]} coincide, so chord length gives them the same t, and no polynomial is at two places at one t: equally spaced values are used instead.`
      : null,
    collapsedWarning: collapsed
      ? `P${collapsed[0]} and P${collapsed[1]} are the same point, so chord length gives them the same parameter value and no polynomial can pass both "at once". The curve uses equally spaced values until you move one of them.`
      : null,
  };
}
