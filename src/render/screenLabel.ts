/**
 * A label at screen coordinates: one line placed by the label placer
 * (labelPlacer.ts), or, wider than its figure (a sentence on a laptop's
 * projector), set on lines broken between words and placed as one block.
 */
import { type Box, boxesMeet } from './ink';
import { leastHidden } from './boxPlaces';
import { type LabelStyle, labelFrame } from './labels';
import { labelLines, measureLabel } from './labelWidth';
import { drawLabelBox, insideFigure } from './labelDrawing';
import { placeLine, struckThrough } from './labelPlacer';
import { minusSigns, say } from './notation';
import type { Painter } from './painter';

/** A label at screen coordinates, kept whole inside the figure and clear of the labels placed before it. */
export const drawScreenLabel: typeof placeLine = (painter, text, x, y, style = {}) => {
  // Measured once: a single line (nearly every label, every drag frame) is placed with it.
  const measured = measureLabel(painter, text, style);
  const { size, total } = measured;
  const room = painter.view.width - 2 * size * 0.6;
  const lines = total > room && !style.around ? labelLines(painter, text, style, room) : null;
  return lines && lines.length > 1
    ? drawLines(painter, lines, x, y, style, size)
    : placeLine(painter, text, x, y, style, measured);
};

/**
 * A label set on lines (wider than its figure) as one block, lines `step`
 * apart from (x, y): moved whole, a line at a time up or down, to the first
 * place where every line is clear of the labels placed before it and of the
 * strokes; where none is, in its place with a halo, or left out whole if
 * optional. Placed a line at a time, a line that found no room was left out
 * and the rest read as another sentence ("A plane curve:" alone, its
 * "B = T × N = ±e_z, τ = 0" gone).
 */
function drawLines(
  painter: Painter,
  lines: readonly string[],
  x: number,
  y: number,
  style: LabelStyle,
  size: number,
): { width: number } {
  const { view } = painter;
  const step = size * 1.45 * (y > view.height / 2 ? -1 : 1);
  const order = step < 0 ? [...lines].reverse() : lines;
  const align = style.align ?? 'left';
  // The block kept inside the figure as a whole, its box too where it has
  // one: its lines stay a pitch apart.
  const first = Math.min(y, y + (order.length - 1) * step);
  const last = Math.max(y, y + (order.length - 1) * step);
  // Each line measured once, for every place the block is tried at.
  const measured = order.map((line) => ({
    line,
    text: minusSigns(say(line)),
    total: measureLabel(painter, line, style).total,
  }));
  const spots = (dy: number, boxed = style.box === true) => {
    const room = insideFigure(view, size, boxed);
    const up = Math.min(0, room.foot - (last + dy));
    const into = first + dy + up < room.top ? room.top - (first + dy) : up;
    return measured.map(({ line, text, total }, i) => {
      const at = align === 'center' ? x - total / 2 : align === 'left' ? x : x - total;
      return { line, text, total, left: room.left(at, total), middle: y + dy + into + i * step };
    });
  };
  const clear = (placed: ReturnType<typeof spots>) =>
    placed.every(({ text, total, left, middle }) => {
      const apart = size * 0.3;
      const here = {
        x: left - apart,
        y: middle - size * 0.65,
        width: total + 2 * apart,
        height: size * 1.3,
      };
      return (
        !painter.labels.some((b) => boxesMeet(b.frame ?? b, here)) &&
        !struckThrough(painter, text, left, middle, total, size, false)
      );
    });
  // Up and down a line at a time, to the figure's edges.
  const reach = Math.ceil(view.height / Math.abs(step));
  const shifts = [0, ...Array.from({ length: reach }, (_, k) => [-(k + 1), k + 1]).flat()].map(
    (k) => k * Math.abs(step),
  );
  const found = shifts.map((dy) => spots(dy)).find(clear);
  if (!found && style.optional) return { width: 0 };
  // Boxed (asked for, or nowhere clear), in one box: a box a line, stacked,
  // would overlap. Nowhere clear, it takes the place that hides least.
  const boxed = !found || style.box === true;
  const blocks = found ? [found] : shifts.map((dy) => spots(dy, true));
  const frames = blocks.map((block) => blockFrame(block, size));
  const pick = found ? 0 : leastHidden(painter, frames);
  const [placed, frame] = [blocks[pick], frames[pick]];
  const widest = Math.max(...placed.map((p) => p.total));
  if (boxed) {
    drawLabelBox(painter, frame, style.color);
    painter.labels.push({
      text: lines.join(' '),
      x: frame.x + size * 0.35,
      y: frame.y,
      width: widest,
      height: frame.height,
      boxed: true,
      frame,
    });
  }
  for (const { line, left, middle } of placed)
    placeLine(painter, line, left, middle, {
      ...style,
      align: 'left',
      ...(boxed ? { inBox: true, box: false } : { stays: true }),
    });
  return { width: widest };
}

/** The box round a block of lines: their frames' union. */
function blockFrame(
  block: readonly { left: number; middle: number; total: number }[],
  size: number,
): Box {
  const frames = block.map((p) => labelFrame(p.left, p.middle, p.total, size));
  const x = Math.min(...frames.map((f) => f.x));
  const y = Math.min(...frames.map((f) => f.y));
  return {
    x,
    y,
    width: Math.max(...frames.map((f) => f.x + f.width)) - x,
    height: Math.max(...frames.map((f) => f.y + f.height)) - y,
  };
}
