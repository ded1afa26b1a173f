import { clearestPlace, edgePlaces } from '../render/boxPlaces';
import { labelLines, labelWidth } from '../render/labelWidth';
import { drawPanelBox } from '../render/note';
import type { Painter, StrokeStyle } from '../render/painter';
import type { Theme } from '../render/theme';

// A figure's key: which line is which, in a box in a corner of the figure.

export interface LegendEntry {
  text: string;
  /** The name's colour (the ink's if absent). */
  color?: string;
  /** A short sample of the line it names, drawn before the name; none for a key in words only. */
  line?: StrokeStyle;
}

/**
 * The key of a figure, boxed in a corner: a line sample and a name per entry.
 * It is placed with the labels, when the figure's ink is all down, in the
 * first of the top left (below `top`, pixels), top right, bottom left and
 * bottom right corners where no curve, point or label runs under it; failing
 * that, where it hides least (Runge's spike by the left edge, a curve that
 * starts in the corner). It is drawn over the figure, so no curve runs
 * through a name. Returns the y (pixels) below its top left place.
 */
export function drawLegend(
  painter: Painter,
  entries: readonly LegendEntry[],
  options: { top?: number; size?: number } = {},
): number {
  const { theme, view } = painter;
  const size = options.size ?? keySize(theme);
  const top = options.top ?? size * 0.4;
  // With the labels hidden (predict, then show) a key without its names says nothing.
  if (!entries.length || !painter.show.labels) return top;
  const { lineHeight, pad, left } = keyMetrics(size);
  const sample = entries.some((e) => e.line) ? size * 2.4 : 0;
  const nameAt = left + pad + (sample ? sample + size * 0.5 : 0);
  // A name too long for the figure (a laptop's projector) takes lines of its own.
  const room = view.width - 2 * left - (nameAt - left) - pad;
  const lines = entries.map((e) =>
    labelWidth(painter, e.text, { size }) > room
      ? labelLines(painter, e.text, { size }, room)
      : [e.text],
  );
  const width =
    nameAt -
    left +
    Math.max(...lines.flat().map((line) => labelWidth(painter, line, { size }))) +
    pad;
  const height = lines.flat().length * lineHeight + pad;
  // Set on lines, a key that would cover a third of a small figure (a knot
  // strip on a laptop's projector) is left out rather than hide what it names.
  if (lines.flat().length > entries.length && height > view.height / 3) return top;
  painter.placing(() => {
    const corners = edgePlaces(view, width, height, left, top);
    const { x, y } = corners[clearestPlace(painter, corners)];
    painter.labels.push({ text: 'legend', x, y, width, height, boxed: true });
    drawPanelBox(painter, { x, y, width, height }, theme.axis, Math.max(1, theme.sizes.thin * 0.5));
    const shift = x - left;
    let row = 0;
    entries.forEach((entry, i) => {
      const lineY = y + pad / 2 + (row + 0.5) * lineHeight;
      if (entry.line)
        painter.polyline(
          [
            view.toWorld([shift + left + pad, lineY]),
            view.toWorld([shift + left + pad + sample, lineY]),
          ],
          entry.line,
        );
      for (const line of lines[i])
        painter.screenLabel(line, shift + nameAt, y + pad / 2 + (row++ + 0.5) * lineHeight, {
          size,
          color: entry.color ?? theme.ink,
          inBox: true,
        });
    });
  });
  return top + height + size * 0.4;
}

/** A key's type size in `theme`, unless its figure asks for another. */
const keySize = (theme: Theme): number => theme.sizes.small * 1.05;

/** A key's line height, its box's padding and its margin from the figure's edge, at type `size`. */
const keyMetrics = (size: number) => ({
  lineHeight: size * 1.45,
  pad: size * 0.45,
  left: size * 0.4,
});

/**
 * The band at a figure's top that a key of `lines` lines takes (see
 * FigureSpec.keyLines), with the margins above and below it: what the fit
 * keeps clear of the subject.
 */
export function keyBand(theme: Theme, lines: number): number {
  if (lines <= 0) return 0;
  const size = keySize(theme);
  const { lineHeight, pad } = keyMetrics(size);
  // drawLegend's margin above the key, the key, and as much again below it.
  const margin = size * 0.4;
  return margin + lines * lineHeight + pad + margin;
}
