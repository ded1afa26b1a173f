/**
 * Where a label may go near the point it names: the spots beside a drawn
 * point, the rings of spots farther out, the point of a box a leader line
 * ends at, and whether a spot is nearer its own point than any other (a name
 * nearer another point is read as that point's).
 */
import type { Box } from './ink';

/** Squared distance from (x, y) to the nearest point of a box. */
function distanceToBox2(x: number, y: number, box: Box): number {
  const dx = Math.max(box.x - x, 0, x - (box.x + box.width));
  const dy = Math.max(box.y - y, 0, y - (box.y + box.height));
  return dx * dx + dy * dy;
}

/**
 * Is a label's box at least as near its own point (ax, ay) as any of the
 * other points? A name nearer another point is read as that point's.
 */
export function nearestIsOwn(
  box: Box,
  ax: number,
  ay: number,
  others: readonly (readonly [number, number])[],
): boolean {
  const own = distanceToBox2(ax, ay, box);
  for (const [x, y] of others) {
    if (x === ax && y === ay) continue;
    // Cheap reject first: a point farther off on either axis cannot be nearer.
    const dx = Math.max(box.x - x, 0, x - (box.x + box.width));
    if (dx * dx >= own) continue;
    const dy = Math.max(box.y - y, 0, y - (box.y + box.height));
    if (dx * dx + dy * dy < own) return false;
  }
  return true;
}

/**
 * Places beside a point drawn with radius `r` at (x, y), in the order tried:
 * [left, middle] of the label.
 */
export function spotsAround(x: number, y: number, r: number, total: number, size: number) {
  const spots: [number, number][] = [];
  // Close beside the point first, then a little farther out (past a ring or
  // a line that hugs it).
  for (const far of [0, size * 0.7]) {
    const d = r * 0.75 + 3 + far;
    const up = y - d - size * 0.45;
    const down = y + d + size * 0.45;
    spots.push(
      [x + d, up],
      [x + d, down],
      [x - d - total, up],
      [x - d - total, down],
      [x + r + far + size * 0.3, y],
      [x - r - far - size * 0.3 - total, y],
      [x - total / 2, y - r - far - size * 0.75],
      [x - total / 2, y + r + far + size * 0.75],
    );
  }
  return spots;
}

/** How far out the rings of farther places go, in label heights from the anchor. */
export const NEAR_RINGS = [1.6, 2.4, 3.4] as const;
/**
 * A label on a leader line may go farther still: the leader says whose it is
 * (bezier-properties' "curve of the mapped points", at a 1366 × 768
 * projector, found no clear place within 3.4 heights and was boxed over both
 * curves, with the clear band under them 5 heights down).
 */
export const LEADER_RINGS = [...NEAR_RINGS, 4.6, 6] as const;

/**
 * Places farther from a label's anchor (its centre at (ax, ay)), ring after
 * ring, each ring's twelve directions from above round clockwise: [left,
 * middle] of the label.
 */
export function farSpots(
  ax: number,
  ay: number,
  total: number,
  height: number,
  rings: readonly number[] = NEAR_RINGS,
): [number, number][] {
  const spots: [number, number][] = [];
  for (const reach of rings) {
    for (let k = 0; k < 12; k++) {
      const angle = -Math.PI / 2 + (k * Math.PI) / 6;
      const cx = ax + Math.cos(angle) * (reach * height + total / 2);
      const cy = ay + Math.sin(angle) * reach * height;
      spots.push([cx - total / 2, cy]);
    }
  }
  return spots;
}

/** The point of a box nearest to (x, y). */
export function nearestOnBox(x: number, y: number, box: Box): [number, number] {
  return [
    Math.max(box.x, Math.min(x, box.x + box.width)),
    Math.max(box.y, Math.min(y, box.y + box.height)),
  ];
}
