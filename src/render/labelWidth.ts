/**
 * How wide a label is: its fonts (the theme's size, never under its least,
 * a subscript smaller), its runs, and their widths, measured once per font
 * and text on a screen canvas.
 */
import { minusSigns, say } from './notation';
import { type LabelStyle, splitSubscripts } from './labels';
import type { Painter } from './painter';
import { SvgContext } from './svgContext';
import type { DrawingSurface } from './surface';
import type { Theme } from './theme';

/** The fonts and runs of a label, and its width in pixels. */
export function measureLabel(painter: Painter, text: string, style: LabelStyle) {
  return measureLabelOn(painter.ctx, painter.theme, text, style);
}

/** measureLabel on a surface of its own, before any painter draws (a figure's fit). */
export function measureLabelOn(c: DrawingSurface, theme: Theme, text: string, style: LabelStyle) {
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

let measuring: DrawingSurface | null = null;

/**
 * A surface to measure text on before a figure is drawn: a canvas of its
 * own in a page (its widths cached as every screen canvas's), else (a test,
 * a handout made headless) a recording, which measures its own way.
 */
export function measuringSurface(): DrawingSurface {
  measuring ??=
    (typeof document !== 'undefined' && document.createElement('canvas').getContext('2d')) ||
    new SvgContext();
  return measuring;
}

/** How wide a label will be (px), before it is placed. */
export function labelWidth(painter: Painter, text: string, style: LabelStyle = {}): number {
  return measureLabel(painter, text, style).total;
}

/**
 * A label's words on as few lines as fit `room` pixels, broken between
 * words (a word wider than the room stands on a line of its own), and the
 * lines as even as that many allow: "B = T × N" over "= −e_z, τ = 0", not a
 * full line over "= 0".
 */
export function labelLines(
  painter: Painter,
  text: string,
  style: LabelStyle,
  room: number,
): string[] {
  // Broken after a phrase (": ", ", ", "; ") where each phrase fits: not inside "B = T × N".
  const phrases = text.split(/(?<=[:,;]) /);
  if (phrases.length > 1) {
    const lines = even(painter, phrases, style, room);
    if (lines.every((line) => measureLabel(painter, line, style).total <= room)) return lines;
  }
  return even(painter, text.split(' '), style, room);
}

/** The pieces on as few lines as `room` allows, the longest line as short as that many allow. */
function even(
  painter: Painter,
  pieces: readonly string[],
  style: LabelStyle,
  room: number,
): string[] {
  const fewest = pack(painter, pieces, style, room);
  let [low, high] = [0, room];
  let best = fewest;
  for (let i = 0; i < 10; i++) {
    const mid = (low + high) / 2;
    const lines = pack(painter, pieces, style, mid);
    if (lines.length <= fewest.length) [high, best] = [mid, lines];
    else low = mid;
  }
  return best;
}

/** Pieces joined by spaces on a line until the next would pass `room`. */
function pack(
  painter: Painter,
  words: readonly string[],
  style: LabelStyle,
  room: number,
): string[] {
  const lines: string[] = [];
  let line = words[0];
  for (const word of words.slice(1)) {
    const longer = `${line} ${word}`;
    if (measureLabel(painter, longer, style).total <= room) line = longer;
    else {
      lines.push(line);
      line = word;
    }
  }
  lines.push(line);
  return lines;
}
