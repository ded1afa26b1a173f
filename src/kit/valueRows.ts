import { boxesMeet } from '../render/ink';
import { drawScreenLabel } from '../render/screenLabel';
import { labelWidth, measureLabelOn, measuringSurface } from '../render/labelWidth';
import type { Painter } from '../render/painter';
import type { Theme } from '../render/theme';

// The values at a plot's cursor in rows above it (cursorValues.ts chooses
// where they go): how many rows they take at a plot's width and the room
// those take, which the fit keeps (app/headless.ts fitFigure), and their
// drawing there. One layout serves both, so the fit keeps what they take.

/** A row of values above a plot: its pitch, and its foot's gap above the plot, at type `size`. */
const ROW = { pitch: 1.95, foot: 0.25 } as const;

/** The values at a plot's cursor, as the fit keeps room for them (FigureSpec.cursorValues). */
export interface CursorValues {
  /** How many, at most, in the scene's fullest step. */
  count: number;
  /** The widest of them at its number format, e.g. `H_3 = −0.000 (× D_{i+1})`. */
  widest: string;
}

/** The gap between two values in a row, at type `size`. */
const gapAt = (size: number) => size * 1.2;

/**
 * Boxes of these widths in rows from `start`, left to right and wrapped
 * before `end` as a paragraph is: each one's x and row; null where one is
 * wider than the room. The fit's reserve and the drawing share it.
 */
export function valueSpots(
  widths: readonly number[],
  start: number,
  end: number,
  size: number,
): { x: number; row: number }[] | null {
  const spots: { x: number; row: number }[] = [];
  let x = start;
  let row = 0;
  for (const width of widths) {
    if (x > start && x + width > end) [x, row] = [start, row + 1];
    if (x + width > end) return null;
    spots.push({ x, row });
    x += width + gapAt(size);
  }
  return spots;
}

/** Where a row of values starts and ends over a plot whose ends are at `left` and `far` (px). */
const rowEnds = (left: number, far: number, width: number, size: number) => ({
  start: Math.max(left, 0) + size * 0.4,
  end: Math.min(far, width) - size * 0.4,
});

/**
 * The rows' ends: over the plot, or over the figure's whole width where that
 * takes fewer rows (a 1366 presenter strip: five L_k(t) wanted two rows over
 * the plot, more room than the strip has, and were all left out; across the
 * figure they take one). The fit's reserve and the drawing share it.
 */
function rowSpan(
  widths: readonly number[],
  plot: { left: number; far: number },
  width: number,
  size: number,
): { start: number; end: number } {
  const over = rowEnds(plot.left, plot.far, width, size);
  const across = rowEnds(0, width, width, size);
  const rows = (ends: { start: number; end: number }) =>
    valueSpots(widths, ends.start, ends.end, size)?.at(-1)?.row ?? Infinity;
  return rows(across) < rows(over) ? across : over;
}

/**
 * How many rows `values` take over a plot fitted `padX` in from each side of
 * a view `width` wide (a plot spans its view's width): 0 where one is wider
 * than the plot (they go in a column then).
 */
export function valueRowsOver(
  theme: Theme,
  values: CursorValues,
  width: number,
  padX: number,
): number {
  if (values.count <= 0) return 0;
  const size = theme.sizes.small;
  const style = { size, bold: true, box: true, fixed: true } as const;
  const one = measureLabelOn(measuringSurface(), theme, values.widest, style).total;
  const widths = Array<number>(values.count).fill(one);
  const { start, end } = rowSpan(widths, { left: padX, far: width - padX }, width, size);
  const spots = valueSpots(widths, start, end, size);
  return spots ? spots[spots.length - 1].row + 1 : 0;
}

/**
 * The room above a plot that `rows` rows of values at its cursor take
 * (FigureSpec.cursorValues), beyond the `padding` the fit keeps there anyway:
 * what `valueColumn` needs to write them there.
 */
export function valueBand(theme: Theme, rows: number, padding: number): number {
  if (rows <= 0) return 0;
  const size = theme.sizes.small;
  // The foot's gap, a box (its letters and padding), the rows above it, 2 px from the edge.
  const room = size * (ROW.foot + 1.3 + 0.7) + (rows - 1) * size * ROW.pitch + 2;
  return Math.max(0, Math.ceil(room - padding));
}

/**
 * The values in rows above the plot, left to right from its left edge,
 * where there is room for them whole between the figure's top and the
 * plot's (the room the fit keeps for them, FigureSpec.cursorValues), and
 * right of a label already there (the plot's y name): there no curve,
 * peak or cursor line runs under them. In presenter
 * view's short strips they stood in a row inside the plot, boxed over the
 * very peaks of L₁ and H₁ (#19). False, drawing nothing, where they do not
 * fit. Called as the labels are placed.
 */
export function valuesAbove(
  painter: Painter,
  range: { minX: number; maxX: number; maxY?: number },
  entries: readonly { text: string; color: string }[],
): boolean {
  if (range.maxY === undefined) return false;
  const { view, theme } = painter;
  const size = theme.sizes.small;
  const style = { size, bold: true, box: true, fixed: true } as const;
  const pad = size * 0.35;
  const [left, plotTop] = view.toScreen([range.minX, range.maxY]);
  const [far] = view.toScreen([range.maxX, range.maxY]);
  const shown = entries.filter((entry) => !painter.labelHidden(entry.text));
  const widths = shown.map((entry) => labelWidth(painter, entry.text, style));
  const ends = rowSpan(widths, { left, far }, view.width, size);
  // Right of any label already up there at its start, reaching into the rows'
  // band (a y name set above the axis' top). The y name plotYName sets just
  // inside the plot ends below the rows' foot, and pushed the rows right of
  // it: at a 1366 presenter strip they no longer fitted in one row, and all
  // five L_k(t) were left out.
  const foot = plotTop - size * ROW.foot;
  const names = painter.labels.filter((b) => b.y < foot && b.x < ends.start + size);
  const start = Math.max(ends.start, ...names.map((b) => b.x + b.width + size * 0.6));
  // Left to right, wrapped to rows as a paragraph is, in the order given.
  const spots = valueSpots(widths, start, ends.end, size);
  if (!spots || !spots.length) return false;
  const row = spots[spots.length - 1].row;
  // The last row's foot just above the plot (the top tick's number, half
  // above it, stands left of the axis, where the rows do not reach).
  const line = size * ROW.pitch;
  const last = plotTop - size * ROW.foot - pad - size * 0.65;
  if (last - row * line - size * 0.65 - pad < 2) return false;
  const boxes = shown.map((_, i) => ({
    x: spots[i].x - pad,
    y: last - (row - spots[i].row) * line - size * 0.65 - pad,
    width: widths[i] + 2 * pad,
    height: size * 1.3 + 2 * pad,
  }));
  // On another label (one the figure put up there): in the plot instead.
  if (boxes.some((box) => painter.labels.some((b) => boxesMeet(b.frame ?? b, box)))) return false;
  shown.forEach((entry, i) => {
    const y = last - (row - spots[i].row) * line;
    drawScreenLabel(painter, entry.text, spots[i].x, y, { ...style, color: entry.color });
  });
  return true;
}
