import type { Point } from '../../math';
import { degenerate, repeatsText } from '../../kit/degenerate';

// Why the figure shows less than one might expect, in words.

/** Patch i is a single point: both ends and both gradients say "stay here". */
export function patchNote(
  points: readonly Point[],
  i: number,
  gradients: readonly Point[],
): string | null {
  const [a, b] = [points[i], points[i + 1]];
  const still = (d: Point) => d[0] === 0 && d[1] === 0;
  if (a[0] === b[0] && a[1] === b[1] && still(gradients[i]) && still(gradients[i + 1])) {
    return `P${i} and P${i + 1} are at one spot and both gradients are zero: four conditions that all say "stay here", so the patch is a single point. Drag a point or a gradient tip away.`;
  }
  return null;
}

/** Two points in Catmull-Rom mode, points on one spot or on one line; null if nothing. */
export function pointsNote(points: readonly Point[], straight: boolean): string | null {
  if (straight) {
    return 'Two points have no neighbours: Catmull-Rom gives both ends a zero gradient, so the patch is a straight segment. Add a point.';
  }
  const { allSame, collinear, repeats } = degenerate(points);
  if (allSame)
    return 'All points are on one spot: each patch starts and ends there, so it is a loop shaped by its gradients alone.';
  const notes: string[] = [];
  if (repeats.length)
    notes.push(
      `${repeatsText(repeats)}: that patch starts and ends on one spot, so it is a loop shaped by its two gradients (a point if both are zero).`,
    );
  if (collinear)
    notes.push(
      'The points lie on one line: the patches stay on it only where the gradients point along it too.',
    );
  return notes.length ? notes.join(' ') : null;
}
