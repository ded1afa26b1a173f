/**
 * How a stroke looks: its colour, width, dash, opacity and role, and those
 * set on the drawing surface, with the painter's fallbacks for what a style
 * leaves out.
 */
import type { DrawingSurface } from './surface';
import type { Theme } from './theme';

export interface StrokeStyle {
  color?: string;
  width?: number;
  dash?: number[];
  alpha?: number;
  /**
   * `curve`: the result the lesson is about (the spline, P(t)'s curve). The
   * presenter can hide it ("predict, then show"); mark the main curve so.
   * `grid`: a background of lines (a pixel grid), which labels may sit on as
   * they sit on the figure's own grid.
   */
  role?: 'curve' | 'grid';
}

/**
 * Sets `style` on the surface: a colour without a dash of its own takes the
 * theme's dash for it (paper), and the ends and joins are round.
 */
export function applyStroke(
  c: DrawingSurface,
  theme: Theme,
  style: StrokeStyle,
  fallbackWidth: number,
  fallbackColor: string,
): void {
  const color = style.color ?? fallbackColor;
  c.strokeStyle = color;
  c.lineWidth = style.width ?? fallbackWidth;
  c.setLineDash(style.dash ?? theme.dashOf?.(color) ?? []);
  c.globalAlpha = style.alpha ?? 1;
  c.lineCap = 'round';
  c.lineJoin = 'round';
}
