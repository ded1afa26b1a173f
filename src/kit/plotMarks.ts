import type { Painter } from '../render/painter';

// Marks a function plot writes beside its curves: the y-axis name and the
// values at the cursor, boxed and kept off the curves they name.

/**
 * A plot's y-axis name, boxed just right of the axis at the top, so neither
 * the axis nor a curve runs through it. Returns the y (pixels) below it.
 */
export function plotYName(painter: Painter, minX: number, maxY: number, name: string): number {
  const small = painter.theme.sizes.small;
  const [x, y] = painter.view.toScreen([minX, maxY]);
  painter.screenLabel(name, x + small * 0.8, y + small * 0.9, {
    color: painter.theme.muted,
    size: small * 1.1,
    box: true,
  });
  return y + small * 2.2;
}

/**
 * The values at a plot's cursor, as a boxed column in the top corner away
 * from the cursor: never written over their own curves.
 */
export function valueColumn(
  painter: Painter,
  cursor: number,
  range: { minX: number; maxX: number },
  top: number,
  entries: readonly { text: string; color: string }[],
): void {
  const { view, theme } = painter;
  const size = theme.sizes.small;
  const [left] = view.toScreen([range.minX, 0]);
  const [far] = view.toScreen([range.maxX, 0]);
  const right = cursor < (range.minX + range.maxX) / 2;
  const edge = right ? Math.min(far, view.width) - size * 0.8 : Math.max(left, 0) + size * 0.8;
  // A plot too short for the column: the values go in a row along its top instead.
  if (top + entries.length * size * 1.75 > view.height * 0.8) {
    let x = Math.max(left, 0) + size * 0.8;
    for (const entry of entries) {
      const { width } = painter.screenLabel(entry.text, x, top + size * 0.6, {
        color: entry.color,
        size,
        bold: true,
        box: true,
      });
      x += width + size * 1.2;
    }
    return;
  }
  entries.forEach((entry, i) => {
    painter.screenLabel(entry.text, edge, top + size * 0.6 + i * size * 1.75, {
      color: entry.color,
      size,
      bold: true,
      box: true,
      align: right ? 'right' : 'left',
    });
  });
}
