import { type Point, pointsShape } from '../../math';

/**
 * What the construction does with degenerate control points, in words (null
 * when there is nothing to say): the figure would otherwise draw them
 * without a word.
 */
export function degenerateNote(p: readonly Point[]): string | null {
  const shape = pointsShape(p);
  switch (shape.kind) {
    case 'one spot':
      return 'All control points are on one spot: every level is that spot, and the “curve” is a single point.';
    case 'one line':
      return 'The control points lie on one line: every level stays on it, so the curve is a piece of that line (it may run back over itself).';
    case 'neighbours on one spot':
      return `P${shape.index} and P${shape.index + 1} are on one spot: their edge has length 0, so its point on every level is that spot.`;
    case 'general':
      return null;
  }
}
