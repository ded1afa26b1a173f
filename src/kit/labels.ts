import type { Point } from '../math';
import type { Painter } from '../render/painter';
import type { LabelBox, LabelStyle } from '../render/labels';

/** Offsets tried around a point, as multiples of the label's size: right, left, above, below, corners. */
const SPOTS: [number, number][] = [
  [0.6, 0.9],
  [0.6, -0.9],
  [-0.6, 0.9],
  [-0.6, -0.9],
  [0.7, 0],
  [-0.7, 0],
  [0, 1.4],
  [0, -1.4],
];

/**
 * A label beside `p` at the first spot where it covers no label placed so far
 * in this frame and no point of `avoid` (the construction's points): the
 * construction's labels no longer land on one another where levels bunch up.
 */
export function placeLabel(
  painter: Painter,
  text: string,
  p: Point,
  avoid: readonly Point[],
  style: LabelStyle = {},
  taken: readonly LabelBox[] = [],
): void {
  const [x, y] = painter.view.toScreen(p);
  if (x < 0 || y < 0 || x > painter.view.width || y > painter.view.height) return;
  const size = style.size ?? painter.theme.sizes.label;
  // Subscripts are smaller: count them at about two thirds.
  const plain = text.replace(/[_{}]/g, '');
  const width = size * 0.55 * plain.length;
  const height = size * 1.3;
  const obstacles = avoid.map((q) => painter.view.toScreen(q));
  const radius = painter.theme.sizes.handle;
  let best: { cost: number; left: number; top: number } | null = null;
  for (const [sx, sy] of SPOTS) {
    const cx = x + sx * size + Math.sign(sx) * (width / 2);
    const cy = y + sy * size;
    const left = cx - width / 2;
    const top = cy - height / 2;
    let cost = 0;
    for (const box of [...taken, ...painter.labels]) {
      const w = Math.min(left + width, box.x + box.width) - Math.max(left, box.x);
      const h = Math.min(top + height, box.y + box.height) - Math.max(top, box.y);
      if (w > 0 && h > 0) cost += w * h;
    }
    for (const [ox, oy] of obstacles) {
      const dx = Math.max(left - ox, 0, ox - (left + width));
      const dy = Math.max(top - oy, 0, oy - (top + height));
      if (Math.hypot(dx, dy) < radius) cost += radius * radius;
    }
    if (cx - width / 2 < 0 || cx + width / 2 > painter.view.width) cost += width * height;
    if (!best || cost < best.cost) best = { cost, left, top };
    if (cost === 0) break;
  }
  if (!best) return;
  // It names the point at (x, y): moved on from the spot chosen here, it is
  // tried round that point and a leader goes back to it (de Casteljau's P₂,₀
  // hung from a leader to the spot, beside a sample dot, not to its point).
  painter.screenLabel(text, best.left, best.top + height / 2, {
    ...style,
    align: 'left',
    names: true,
    of: [x, y],
  });
}

/**
 * Where the shell will put the labels of handles at `points` (right of and
 * above each, drawn after the figure): boxes for `placeLabel` to keep clear of.
 */
export function handleLabelBoxes(painter: Painter, points: readonly Point[]): LabelBox[] {
  const { handle, label } = painter.theme.sizes;
  return points.map((p) => {
    const [x, y] = painter.view.toScreen(p);
    return {
      text: '',
      x: x + handle + 4,
      y: y - handle - label * 0.45 - label * 0.65,
      width: label * 1.4,
      height: label * 1.3,
    };
  });
}

/**
 * Handle labels for points that may share a spot: the first of each stack is
 * named for all of them (`P_0 = P_1 = P_2`), the others carry no label of
 * their own, so names never pile up on one another. Each keeps its own name
 * for screen readers.
 */
export function stackedLabels(points: readonly Point[], name: (i: number) => string) {
  // Grouped by spot in one pass: 500 villages are 500 steps, not 250 000 comparisons.
  const spots = new Map<string, number[]>();
  points.forEach((point, i) => {
    const key = point.join(',');
    const same = spots.get(key);
    if (same) same.push(i);
    else spots.set(key, [i]);
  });
  return points.map((point, i) => {
    const same = spots.get(point.join(','))!;
    return same[0] === i
      ? { label: same.map(name).join(' = '), showLabel: true }
      : { label: name(i), showLabel: false };
  });
}
