import type { Box } from '../render/ink';
import { clearestPlace, drawScreenLabel, labelWidth } from '../render/labels';
import type { Painter } from '../render/painter';

// Marks a function plot writes beside its curves: the y-axis name and the
// values at the cursor, boxed and kept off the curves they name.

/**
 * A plot's y-axis name, boxed along the top of the plot, placed when the
 * figure's ink is all down: at the first place from the axis rightwards where
 * no curve, point or label runs under its box (a basis that starts at 1, as
 * B₀, H₀ and L₀ do, fills the corner by the axis). Failing that, where it
 * hides least. Returns the y (pixels) below its row, for the values' column.
 */
export function plotYName(
  painter: Painter,
  bounds: { minX: number; maxX: number; maxY: number },
  name: string,
): number {
  const small = painter.theme.sizes.small;
  const style = { color: painter.theme.muted, size: small * 1.1, box: true };
  const [left, top] = painter.view.toScreen([bounds.minX, bounds.maxY]);
  const [right] = painter.view.toScreen([bounds.maxX, bounds.maxY]);
  const middle = top + small * 0.9;
  if (painter.labelHidden(name)) return top + small * 2.2;
  painter.placing(() => {
    const width = labelWidth(painter, name, style);
    const pad = style.size * 0.35;
    const boxAt = (x: number): Box => ({
      x: x - pad,
      y: middle - style.size * 0.65 - pad,
      width: width + 2 * pad,
      height: style.size * 1.3 + 2 * pad,
    });
    const first = left + small * 0.8;
    const last = Math.min(right, painter.view.width) - width - small * 0.8;
    const spots = Array.from({ length: NAME_SPOTS }, (_, i) =>
      last <= first ? first : first + ((last - first) * i) / (NAME_SPOTS - 1),
    );
    const x = spots[clearestPlace(painter, spots.map(boxAt))];
    drawScreenLabel(painter, name, x, middle, style);
  });
  return top + small * 2.2;
}

/** Places tried for a plot's y-axis name along its top, from the axis to the far side. */
const NAME_SPOTS = 9;

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
  // A plot too short for the column: the values go in a row along its top
  // instead, wrapped to a second row a box's height below where it is too
  // wide, and never across the cursor's line (its dots stay in sight).
  if (top + entries.length * size * 1.75 > view.height * 0.8) {
    const style = { size, bold: true, box: true };
    const [cursorX] = view.toScreen([cursor, 0]);
    const start = Math.max(left, 0) + size * 0.8;
    const end = Math.min(far, view.width) - size * 0.4;
    const clearOfCursor = (x: number, width: number) =>
      x + width + size * 0.5 < cursorX || x - size * 0.5 > cursorX ? x : cursorX + size * 0.6;
    let x = start;
    let y = top + size * 0.6;
    for (const entry of entries) {
      const width = labelWidth(painter, entry.text, style);
      x = clearOfCursor(x, width);
      if (x > start && x + width > end) {
        y += size * 1.75;
        x = clearOfCursor(start, width);
      }
      painter.screenLabel(entry.text, x, y, { ...style, color: entry.color });
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
