import { type Box, boxesMeet } from '../render/ink';
import { firstClear, leastHidden } from '../render/boxPlaces';
import { drawScreenLabel } from '../render/screenLabel';
import { labelWidth } from '../render/labelWidth';
import type { Painter } from '../render/painter';
import { Viewport } from '../render/viewport';
import { valuesAbove } from './valueRows';

// The values a function plot writes at its cursor (L₀(t) = 0.36, H₁ = 0.216):
// in rows above the plot, where the figure keeps room for them; else boxed
// in a column in the top corner away from the cursor; on a strip too short
// for either (a phone's), in a row along its top wherever no curve runs
// under them. Never over the curves they read. (The rows and the room the
// fit keeps for them: valueRows.ts. The plot's names: plotMarks.ts.)

/** Places tried for the column along the plot's top, from its corner towards the cursor. */
const SPOTS = 9;

/**
 * The values at a plot's cursor: above the plot in rows, where the fit kept
 * room for them (FigureSpec.cursorValues: the view's `valueRows`) and they
 * fit; else as a boxed column in the top corner away from the cursor, never
 * written over their own curves.
 */
export function valueColumn(
  painter: Painter,
  cursor: number,
  range: { minX: number; maxX: number; maxY?: number },
  top: number,
  entries: readonly { text: string; color: string }[],
): void {
  // Decided when the labels are placed, seeing those placed before (the
  // plot's own y name, where the rows would start).
  painter.placing(() => {
    const kept = painter.view instanceof Viewport && painter.view.valueRows > 0;
    if (!kept || !valuesAbove(painter, range, entries))
      valuesInPlot(painter, cursor, range, top, entries);
  });
}

/** The values inside the plot: a boxed column in its top corner, or on a short strip a row along its top. */
function valuesInPlot(
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
  // A plot too short for the column (a phone's strip): the values go in a
  // row along its top, wrapped to a second row a box's height below where it
  // is too wide, never across the cursor's line, and each only where no
  // curve, point, handle or label lies under it: a value that would hide the
  // curves it reads is left out (the dots at the cursor still show it, and
  // the lesson's panel says it in numbers).
  if (top + entries.length * size * 1.75 > view.height * 0.8) {
    const style = { size, bold: true, box: true } as const;
    const [cursorX] = view.toScreen([cursor, 0]);
    const start = Math.max(left, 0) + size * 0.8;
    const end = Math.min(far, view.width) - size * 0.4;
    const pad = size * 0.35;
    const clearOfCursor = (x: number, width: number) =>
      x + width + size * 0.5 < cursorX || x - size * 0.5 > cursorX ? x : cursorX + size * 0.6;
    painter.placing(() => {
      let x = start;
      let y = Math.max(top + size * 0.6, size * 0.65 + pad + 2);
      for (const entry of entries) {
        if (painter.labelHidden(entry.text)) continue;
        const width = labelWidth(painter, entry.text, style);
        x = clearOfCursor(x, width);
        if (x > start && x + width > end) {
          y += size * 1.75;
          x = clearOfCursor(start, width);
        }
        const box = {
          x: x - pad,
          y: y - size * 0.65 - pad,
          width: width + 2 * pad,
          height: size * 1.3 + 2 * pad,
        };
        const inside =
          box.x >= 2 &&
          box.y >= 2 &&
          box.x + box.width <= view.width - 2 &&
          box.y + box.height <= view.height - 2;
        if (inside && firstClear(painter, [box]) === 0)
          drawScreenLabel(painter, entry.text, x, y, { ...style, color: entry.color, stays: true });
        x += width + size * 1.2;
      }
    });
    return;
  }
  // Hidden with the labels (presenter key A), or with the numbers.
  const shown = entries.filter((entry) => !painter.labelHidden(entry.text));
  if (shown.length === 0) return;
  const style = { size, bold: true, box: true, align: right ? 'right' : 'left' } as const;
  // In the corner away from the cursor; where a curve runs under it there (a
  // peak of κ under the box), the first place towards the cursor where none
  // does, short of the cursor's line.
  painter.placing(() => {
    const width = Math.max(...shown.map((e) => labelWidth(painter, e.text, style)));
    const pad = size * 0.35;
    const [cursorX] = view.toScreen([cursor, 0]);
    const column = (at: number): Box => ({
      x: (right ? at - width : at) - pad,
      y: top + size * 0.6 - size * 0.65 - pad,
      width: width + 2 * pad,
      height: (shown.length - 1) * size * 1.75 + size * 1.3 + 2 * pad,
    });
    const towards = right ? -1 : 1;
    const spots = Array.from({ length: SPOTS }, (_, i) => edge + towards * i * width * 0.5);
    // Whole inside the figure (else a value pushed in from the edge lands on
    // the one above it), and on one side of the cursor's line.
    const clearOfCursor = spots.filter((at) => {
      const box = column(at);
      const within = box.x >= 2 && box.y >= 2 && box.x + box.width <= view.width - 2;
      return (
        within &&
        box.y + box.height <= view.height - 2 &&
        (box.x > cursorX + size * 0.5 || box.x + box.width < cursorX - size * 0.5)
      );
    });
    // None clear (a phone's strip, its lines closer than a box is wide): of
    // those over no label, point or handle, the one over fewest strokes (a
    // dashed line rather than the curve), and there it stays (moved by the
    // placer, it went across the cursor's line). Else the placer finds room.
    const boxes = clearOfCursor.map(column);
    const clear = firstClear(painter, boxes);
    const bare = boxes.filter(
      (box) =>
        painter.ink.hits(box).discs === 0 &&
        painter.ink.handlesUnder(box) === 0 &&
        !painter.labels.some((b) => boxesMeet(b.frame ?? b, box)),
    );
    const least = bare[leastHidden(painter, bare)];
    const pick = clear >= 0 ? clear : least ? boxes.indexOf(least) : -1;
    const at = pick >= 0 ? clearOfCursor[pick] : edge;
    shown.forEach((entry, i) => {
      drawScreenLabel(painter, entry.text, at, top + size * 0.6 + i * size * 1.75, {
        ...style,
        color: entry.color,
        stays: pick >= 0,
      });
    });
  });
}
