/**
 * How wide a label is: its fonts (the theme's size, never under its least,
 * a subscript smaller), its runs, and their widths, measured once per font
 * and text on a screen canvas.
 */
import { minusSigns, say } from './notation';
import { type LabelStyle, splitSubscripts } from './labels';
import type { Painter } from './painter';
import type { DrawingSurface } from './surface';

/** The fonts and runs of a label, and its width in pixels. */
export function measureLabel(painter: Painter, text: string, style: LabelStyle) {
  const theme = painter.theme;
  const c = painter.ctx;
  // No text under the theme's least size, subscripts included.
  const least = theme.sizes.minText ?? 0;
  const size = Math.max(style.size ?? theme.sizes.label, least);
  const runs = splitSubscripts(minusSigns(say(text)));
  const weight = style.bold ? 'bold ' : '';
  const mainFont = `${weight}${size}px ${theme.fontFamily}`;
  const subFont = `${weight}${Math.max(Math.round(size * 0.78), least)}px ${theme.fontFamily}`;
  const widths = runs.map((run) => textWidth(c, run.sub ? subFont : mainFont, run.text));
  const total = widths.reduce((a, b) => a + b, 0);
  return { size, runs, mainFont, subFont, widths, total };
}

/**
 * Widths of text on screen canvases, by font and text: the same on every
 * canvas (system fonts, nothing loaded later), and a label is measured on
 * every frame it is drawn (a surface's 20 names: 1 ms of a drag frame). An
 * SVG export or a test's recording measures its own way, every time.
 */
const screenWidths = new Map<string, number>();
const MAX_WIDTHS = 4096;

/** The width of `text` in `font` (px) on the surface `c`; its font is left as it was. */
export function textWidth(c: DrawingSurface, font: string, text: string): number {
  const screen =
    typeof CanvasRenderingContext2D !== 'undefined' && c instanceof CanvasRenderingContext2D;
  const key = `${font}\n${text}`;
  const known = screen ? screenWidths.get(key) : undefined;
  if (known !== undefined) return known;
  c.save();
  c.font = font;
  const width = c.measureText(text).width;
  c.restore();
  if (screen) {
    if (screenWidths.size >= MAX_WIDTHS) screenWidths.clear();
    screenWidths.set(key, width);
  }
  return width;
}

/** How wide a label will be (px), before it is placed. */
export function labelWidth(painter: Painter, text: string, style: LabelStyle = {}): number {
  return measureLabel(painter, text, style).total;
}
