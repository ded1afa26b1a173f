import { drawPanelBox, labelWidth } from '../render/labels';
import type { Painter, StrokeStyle } from '../render/painter';

// A figure's key: which line is which, in a box in its top left corner.

export interface LegendEntry {
  text: string;
  /** The name's colour (the ink's if absent). */
  color?: string;
  /** A short sample of the line it names, drawn before the name; none for a key in words only. */
  line?: StrokeStyle;
}

/**
 * The key of a figure, boxed in its top left corner below `top` (pixels): a
 * line sample and a name per entry. Its box is claimed at once, so every
 * label of the frame keeps off it, and it is drawn over the figure with the
 * labels, so no curve runs through a name. Returns the y (pixels) below it.
 */
export function drawLegend(
  painter: Painter,
  entries: readonly LegendEntry[],
  options: { top?: number; size?: number } = {},
): number {
  const { theme, view } = painter;
  const size = options.size ?? theme.sizes.small * 1.05;
  const top = options.top ?? size * 0.4;
  // With the labels hidden (predict, then show) a key without its names says nothing.
  if (!entries.length || !painter.show.labels) return top;
  const lineHeight = size * 1.45;
  const pad = size * 0.45;
  const left = size * 0.4;
  const sample = entries.some((e) => e.line) ? size * 2.4 : 0;
  const nameAt = left + pad + (sample ? sample + size * 0.5 : 0);
  const width =
    nameAt - left + Math.max(...entries.map((e) => labelWidth(painter, e.text, { size }))) + pad;
  const height = entries.length * lineHeight + pad;
  painter.labels.push({ text: 'legend', x: left, y: top, width, height, boxed: true });
  painter.placing(() => {
    drawPanelBox(
      painter,
      { x: left, y: top, width, height },
      theme.axis,
      Math.max(1, theme.sizes.thin * 0.5),
    );
    entries.forEach((entry, i) => {
      const y = top + pad / 2 + (i + 0.5) * lineHeight;
      if (entry.line)
        painter.polyline(
          [view.toWorld([left + pad, y]), view.toWorld([left + pad + sample, y])],
          entry.line,
        );
      painter.screenLabel(entry.text, nameAt, y, {
        size,
        color: entry.color ?? theme.ink,
        inBox: true,
      });
    });
  });
  return top + height + size * 0.4;
}
