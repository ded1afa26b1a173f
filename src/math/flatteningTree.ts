import { splitBezier } from './bezier';
import { checkPoints } from './checkPoints';
import { flatness, flatteningDepth } from './flatten';
import { checkNumber } from './validate';
import type { Point } from './vec';

// The recursion of flattenBezier, kept: every piece it looks at, with its
// parameter range, its flatness n(n−1)/8 · max‖P(i+2) − 2P(i+1) + Pi‖ (the
// bound on its distance from its chord, Wang 1984) and whether it was split
// at t = ½. Same test and same depth limit as flattenBezier, so the leaves'
// end points are exactly flattenBezier's polyline.

/** One piece of the curve that the flattening looked at. */
export interface FlatteningNode {
  /** Index in visiting order (depth first, left half first). */
  index: number;
  /** Index of the piece it is a half of, or −1 for the whole curve. */
  parent: number;
  depth: number;
  /** Its parameter range on the whole curve. */
  t0: number;
  t1: number;
  /** Its control points (de Casteljau's halves). */
  points: Point[];
  /** n(n−1)/8 · max‖Δ²P‖: how far the piece can be from its chord. */
  flatness: number;
  /** Split into two halves (not flat enough), or kept as one segment. */
  split: boolean;
  /** Kept because the depth limit was reached, not because it was flat enough. */
  cut: boolean;
}

/**
 * Every piece adaptive flattening visits, in the order it visits them: a
 * piece within `tolerance` of its chord becomes one segment, any other is
 * split at t = ½ (de Casteljau) and its halves are flattened, left first.
 */
export function flatteningTree(points: readonly Point[], tolerance: number): FlatteningNode[] {
  const caller = 'flatteningTree';
  checkPoints(caller, 'points', points, 2);
  checkNumber(caller, 'tolerance', tolerance);
  if (!(tolerance > 0)) {
    throw new RangeError(`${caller}: tolerance = ${tolerance}; it must be a positive distance.`);
  }
  // flattenBezier's own split test and depth limit.
  const maximumDepth = flatteningDepth(points, tolerance);
  const nodes: FlatteningNode[] = [];
  const visit = (piece: Point[], parent: number, depth: number, t0: number, t1: number) => {
    const bound = flatness(piece);
    const flat = bound <= tolerance;
    const split = !flat && depth < maximumDepth;
    const node: FlatteningNode = {
      index: nodes.length,
      parent,
      depth,
      t0,
      t1,
      points: piece,
      flatness: bound,
      split,
      cut: !flat && !split,
    };
    nodes.push(node);
    if (!split) return;
    const [left, right] = splitBezier(piece, 0.5);
    const middle = (t0 + t1) / 2;
    visit(left, node.index, depth + 1, t0, middle);
    visit(right, node.index, depth + 1, middle, t1);
  };
  visit(
    points.map((p) => p.slice()),
    -1,
    0,
    0,
    1,
  );
  return nodes;
}
