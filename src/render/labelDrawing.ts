/**
 * What a label draws besides its letters: the box of a boxed label, and the
 * leader line back to its point when it had to move away from it.
 */
import { type Box } from './ink';
import { nearestOnBox } from './labelSpots';
import type { Painter } from './painter';
import type { Projection } from './projection';

/**
 * Where a label of type `size` stays whole inside the figure, its box too
 * where it has one: its margin, the highest and lowest middles of a line,
 * and a line's left edge kept in for its width `total`. The single-line
 * placer and the block of lines share it.
 */
export function insideFigure(view: Projection, size: number, boxed: boolean) {
  const margin = 2 + (boxed ? size * 0.35 : 0);
  return {
    margin,
    top: size * 0.7 + margin,
    foot: view.height - size * 0.7 - margin,
    left: (l: number, total: number) => Math.max(margin, Math.min(l, view.width - total - margin)),
  };
}

/** A thin line from a label's anchor to the nearest point of its box (when it had to move away). */
export function drawLeader(
  painter: Painter,
  [ax, ay]: [number, number],
  box: Box,
  color?: string,
): void {
  const [ex, ey] = nearestOnBox(ax, ay, box);
  // It stops a little short of the label's box.
  const length = Math.hypot(ex - ax, ey - ay);
  const k = length > 4 ? (length - 4) / length : 0;
  const [bx, by] = [ax + (ex - ax) * k, ay + (ey - ay) * k];
  const c = painter.ctx;
  c.save();
  c.setLineDash([]);
  c.globalAlpha = 0.7;
  c.strokeStyle = color ?? painter.theme.ink;
  c.lineWidth = Math.max(1, painter.theme.sizes.thin * 0.6);
  c.beginPath();
  c.moveTo(ax, ay);
  c.lineTo(bx, by);
  c.stroke();
  c.restore();
  painter.ink.segment(ax, ay, bx, by, c.lineWidth / 2);
}

/** A boxed label's box: all but opaque, its border in the label's colour. */
export function drawLabelBox(painter: Painter, frame: Box, color?: string): void {
  const c = painter.ctx;
  const box = [frame.x, frame.y, frame.width, frame.height] as const;
  c.save();
  c.setLineDash([]);
  c.fillStyle = painter.theme.labelHalo;
  c.globalAlpha = 0.92;
  c.fillRect(...box);
  c.globalAlpha = 1;
  c.strokeStyle = color ?? painter.theme.ink;
  c.lineWidth = Math.max(1, painter.theme.sizes.thin);
  c.beginPath();
  c.rect(...box);
  c.stroke();
  c.restore();
}
