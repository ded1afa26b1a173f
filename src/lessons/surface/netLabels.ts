import type { Point } from '../../app/lesson';
import type { LabelBox, Painter } from '../../render/painter';

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

/** Distance from (x, y) to the box (0 inside it). */
const distanceTo = (b: Box, x: number, y: number) =>
  Math.hypot(
    Math.max(b.left - x, 0, x - (b.left + b.width)),
    Math.max(b.top - y, 0, y - (b.top + b.height)),
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
  const points = net.flat();
  const screen = points.map((p) => painter.view.toScreen(p));
  const taken: Box[] = painter.labels.map((b: LabelBox) => ({
    left: b.x,
    top: b.y,
    width: b.width,
    height: b.height,
  }));
  const crowd = ([x, y]: readonly number[]) =>
    screen.reduce((sum, [qx, qy]) => sum + 1 / (1 + Math.hypot(qx - x, qy - y)), 0);
  const order = screen
    .map((p, i) => ({ i, crowd: crowd(p) }))
    .sort((a, b) => b.crowd - a.crowd || a.i - b.i);
  for (const { i } of order) {
    if (!named(i)) continue;
    const [x, y] = screen[i];
    if (x < 0 || y < 0 || x > viewWidth || y > viewHeight) continue;
    const m = Math.floor(i / 4);
    const n = i % 4;
    const text = `P_{${m},${n}}`;
    // The name's box as the painter draws it: "P" and a subscript of three characters.
    const width = size * 0.7 + size * 0.45 * 3;
    const height = size * 1.3;
    let best: { cost: number; box: Box } | null = null;
    for (const ring of RINGS) {
      for (const angle of ANGLES) {
        const reach = radius + ring * height;
        const cx = x + Math.cos(angle) * (width / 2 + reach);
        const cy = y - Math.sin(angle) * (height / 2 + reach);
        const box = { left: cx - width / 2, top: cy - height / 2, width, height };
        let cost = ring * 4 + (Math.sin(angle) < 0 ? 1 : 0);
        for (const other of taken) cost += overlap(box, other) * 10;
        screen.forEach(([px, py], k) => {
          const d = distanceTo(box, px, py);
          if (d < radius) cost += 1e4;
          // Nearer another point than its own: it would name the wrong one.
          if (k !== i && Math.hypot(px - cx, py - cy) < Math.hypot(x - cx, y - cy)) cost += 40;
        });
        if (
          box.left < 0 ||
          box.top < 0 ||
          box.left + width > viewWidth ||
          box.top + height > viewHeight
        )
          cost += 1e5;
        if (!best || cost < best.cost) best = { cost, box };
      }
    }
    if (!best) continue;
    const before = painter.labels.length;
    painter.screenLabel(text, best.box.left, best.box.top + best.box.height / 2, {
      color: theme.ink,
      halo: true,
      bold: true,
      align: 'left',
    });
    // What the painter drew (its measured box), else the estimate.
    const drawn = painter.labels[before] as LabelBox | undefined;
    taken.push(
      drawn ? { left: drawn.x, top: drawn.y, width: drawn.width, height: drawn.height } : best.box,
    );
  }
}
