import { type Box, boxesMeet } from '../render/ink';
import { clearestPlace } from '../render/boxPlaces';
import type { LabelStyle } from '../render/labels';
import { drawScreenLabel } from '../render/screenLabel';
import { labelWidth } from '../render/labelWidth';
import type { Painter } from '../render/painter';
import { Viewport } from '../render/viewport';

// Names a function plot writes beside its curves: the y-axis name and the
// names of the lines drawn across it, each where no curve runs under it.
// (The values at its cursor: cursorValues.ts.)

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
    // Where the fit kept rows above the plot for the values at its cursor,
    // the name stays in the plot: moved up, it took their row (a 1366
    // presenter strip, all five L_k(t) then left out).
    const rows = painter.view instanceof Viewport && painter.view.valueRows > 0;
    drawScreenLabel(painter, name, x, middle, { ...style, stays: rows });
  });
  return top + small * 2.2;
}

/** Places tried for a plot's y-axis name along its top, from the axis to the far side. */
const NAME_SPOTS = 9;

/**
 * Names a line drawn across a plot at x = `at` (an inflection, a join, a
 * flip), against it: on the first of its sides and heights, from the top
 * down (or from the foot up), where no stroke, point, axis or label lies
 * under the name. Where there is none (a phone's crowded strip) the line goes
 * unnamed: pushed along the plot, its name stood beside the next line and
 * said nothing of its own (two "κ = 0" stacked by the end's line). A line at
 * the plot's right end is named on its left, one at the left end on its right.
 */
export function lineName(
  painter: Painter,
  at: number,
  bounds: { minX: number; maxX: number; minY: number; maxY: number },
  text: string,
  style: LabelStyle & { from?: 'top' | 'foot' } = {},
): void {
  if (painter.labelHidden(text)) return;
  const { view, theme } = painter;
  const size = style.size ?? theme.sizes.small;
  const [x, top] = view.toScreen([at, bounds.maxY]);
  const [, foot] = view.toScreen([at, bounds.minY]);
  if (x < 0 || x > view.width) return;
  const sides: ('right' | 'left')[] =
    at >= bounds.maxX - 1e-9 ? ['left'] : at <= bounds.minX + 1e-9 ? ['right'] : ['right', 'left'];
  painter.placing(() => {
    const width = labelWidth(painter, text, style);
    const gap = Math.max(4, size * 0.25);
    const rows: number[] = [];
    const [first, last] = [Math.max(top, 0) + size, Math.min(foot, view.height) - size];
    const step = Math.max(1, size * 1.4);
    for (let y = first; y <= last && rows.length < 64; y += step) rows.push(y);
    if (style.from === 'foot') rows.reverse();
    const spots = rows.flatMap((y) =>
      sides.map((side) => ({ x: side === 'right' ? x + gap : x - gap - width, y })),
    );
    if (!spots.length) return;
    // Its letters on no stroke, and a little room either side of it from
    // any label, as the placer keeps: "C²" and "κ = 0" side by side read as one.
    const apart = size * 0.3;
    const clear = spots.findIndex(({ x: left, y }) => {
      const glyphs = { x: left, y: y - size * 0.65, width, height: size * 1.3 };
      const room = { ...glyphs, x: left - apart, width: width + 2 * apart };
      return (
        !painter.ink.crosses(glyphs, false) &&
        !painter.labels.some((b) => boxesMeet(b.frame ?? b, room))
      );
    });
    if (clear < 0) return;
    drawScreenLabel(painter, text, spots[clear].x, spots[clear].y, {
      ...style,
      align: 'left',
      fixed: true,
    });
  });
}
