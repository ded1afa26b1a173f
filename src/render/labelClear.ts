/**
 * A label on whichever side of its point lies farthest from the points it
 * must keep away from, then placed as every label is.
 */
import type { LabelStyle } from './labels';
import { drawScreenLabel } from './screenLabel';
import type { Painter } from './painter';

/**
 * A label beside the screen point `at` on whichever of four sides
 * (above/below, right/left) lies farthest from the `avoid` points (world).
 */
export function drawLabelClear(
  painter: Painter,
  text: string,
  at: readonly [number, number],
  avoid: readonly (readonly number[])[],
  style: LabelStyle = {},
): void {
  const [x, y] = at;
  const size = style.size ?? painter.theme.sizes.label;
  const width = size * 0.6 * text.length;
  const gap = size * 0.7;
  const candidates: [number, number, CanvasTextAlign][] = [
    [gap, -size, 'left'],
    [gap, size, 'left'],
    [-gap, -size, 'right'],
    [-gap, size, 'right'],
  ];
  const obstacles = avoid.map((q) => painter.view.toScreen(q));
  let best = candidates[0];
  let bestClearance = -Infinity;
  for (const candidate of candidates) {
    const [dx, dy, align] = candidate;
    const cx = x + dx + (align === 'left' ? width / 2 : -width / 2);
    const cy = y + dy;
    let clearance = Infinity;
    for (const [ox, oy] of obstacles) clearance = Math.min(clearance, Math.hypot(ox - cx, oy - cy));
    if (clearance > bestClearance + 1e-9) {
      bestClearance = clearance;
      best = candidate;
    }
  }
  drawScreenLabel(painter, text, x + best[0], y + best[1], { ...style, align: best[2] });
}
