import type { Point } from '../../app/lesson';
import { memoLast } from '../../kit/memoOn';
import type { LabelBox } from '../../render/labels';
import type { Painter } from '../../render/painter';

/** Directions tried around a point, and how far out (in label heights past the point's dot). */
const ANGLES = Array.from({ length: 16 }, (_, k) => (k * Math.PI) / 8);
const RINGS = [0, 0.35, 0.8, 1.4];

interface Box {
  left: number;
  top: number;
  width: number;
  height: number;
}

const overlap = (a: Box, b: Box) =>
  Math.max(0, Math.min(a.left + a.width, b.left + b.width) - Math.max(a.left, b.left)) *
  Math.max(0, Math.min(a.top + a.height, b.top + b.height) - Math.max(a.top, b.top));

/** A place a point's name may go, and what it costs apart from the names placed before it. */
interface Spot {
  readonly box: Box;
  readonly cost: number;
}

/**
 * Where each named point's name may go, and at what cost, from the points on
 * screen alone: in the order the names choose (crowded points first), each
 * named point in view with its 64 spots. It depends on the net and the view,
 * not on what else is labelled, so a drag of (u, v) across the patch reuses
 * it (16 points × 64 spots × 16 points: 2.4 ms of each frame before).
 */
const spotsFor = memoLast(
  (
    screen: readonly (readonly [number, number])[],
    named: readonly boolean[],
    viewWidth: number,
    viewHeight: number,
    size: number,
    radius: number,
  ): { i: number; spots: Spot[] }[] => {
    const crowd = ([x, y]: readonly number[]) =>
      screen.reduce((sum, [qx, qy]) => sum + 1 / (1 + Math.hypot(qx - x, qy - y)), 0);
    const order = screen
      .map((p, i) => ({ i, crowd: crowd(p) }))
      .sort((a, b) => b.crowd - a.crowd || a.i - b.i);
    // The name's box as the painter draws it: "P" and a subscript of three characters.
    const width = size * 0.7 + size * 0.45 * 3;
    const height = size * 1.3;
    return order.flatMap(({ i }) => {
      const [x, y] = screen[i];
      if (!named[i] || x < 0 || y < 0 || x > viewWidth || y > viewHeight) return [];
      const spots: Spot[] = [];
      for (const ring of RINGS) {
        for (const angle of ANGLES) {
          const reach = radius + ring * height;
          const cx = x + Math.cos(angle) * (width / 2 + reach);
          const cy = y - Math.sin(angle) * (height / 2 + reach);
          const box = { left: cx - width / 2, top: cy - height / 2, width, height };
          let cost = ring * 4 + (Math.sin(angle) < 0 ? 1 : 0);
          // Squared distances, compared as the distances are (16 × 64 × 16 of them a frame while a point moves).
          const own = (x - cx) ** 2 + (y - cy) ** 2;
          const right = box.left + width;
          const bottom = box.top + height;
          for (let k = 0; k < screen.length; k++) {
            const [px, py] = screen[k];
            const dx = Math.max(box.left - px, 0, px - right);
            const dy = Math.max(box.top - py, 0, py - bottom);
            if (dx * dx + dy * dy < radius * radius) cost += 1e4;
            // Nearer another point than its own: it would name the wrong one.
            if (k !== i && (px - cx) ** 2 + (py - cy) ** 2 < own) cost += 40;
          }
          if (
            box.left < 0 ||
            box.top < 0 ||
            box.left + width > viewWidth ||
            box.top + height > viewHeight
          )
            cost += 1e5;
          spots.push({ box, cost });
        }
      }
      return [{ i, spots }];
    });
  },
);

/**
 * The names Pₘ,ₙ of the points `named`, each where it covers no name placed before it and no
 * point of the net, and lies nearer its own point than any other: seen from
 * the side, the points of a row crowd together, and names at one fixed offset
 * ran into one another and over the next point. Crowded points choose first.
 */
export function placeNetLabels(
  painter: Painter,
  net: readonly (readonly Point[])[],
  named: (i: number) => boolean,
): void {
  const theme = painter.theme;
  const { width: viewWidth, height: viewHeight } = painter.view;
  const size = theme.sizes.label;
  const radius = theme.sizes.handle * 0.5 + 2;
  const screen = net.flat().map((p) => painter.view.toScreen(p));
  const flags = screen.map((_, i) => named(i));
  const spots = spotsFor.keyed(
    [viewWidth, viewHeight, size, radius, ...screen.flat(), ...flags],
    screen,
    flags,
    viewWidth,
    viewHeight,
    size,
    radius,
  );
  const taken: Box[] = painter.labels.map((b: LabelBox) => ({
    left: b.x,
    top: b.y,
    width: b.width,
    height: b.height,
  }));
  for (const { i, spots: around } of spots) {
    let best: { cost: number; box: Box } | null = null;
    for (const { box, cost: alone } of around) {
      let cost = alone;
      for (const other of taken) cost += overlap(box, other) * 10;
      if (!best || cost < best.cost) best = { cost, box };
    }
    if (!best) continue;
    const before = painter.labels.length;
    painter.screenLabel(
      `P_{${Math.floor(i / 4)},${i % 4}}`,
      best.box.left,
      best.box.top + best.box.height / 2,
      {
        color: theme.ink,
        halo: true,
        bold: true,
        align: 'left',
        names: true,
      },
    );
    // What the painter drew (its measured box), else the estimate.
    const drawn = painter.labels[before] as LabelBox | undefined;
    taken.push(
      drawn ? { left: drawn.x, top: drawn.y, width: drawn.width, height: drawn.height } : best.box,
    );
  }
}
