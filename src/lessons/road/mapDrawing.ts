import type { Point } from '../../math';
import { drawLegend as drawKey } from '../../kit/legend';
import type { Painter } from '../../render/painter';
import type { OverlayCurve } from './model';
import { type CurvatureComb, TICK_STRIDE } from './roadMarks';
import { CURVES } from './roads';

// How the map draws what the model found: pixel sizes and colours come from
// the theme here, every position from the model.

/** A road drawn as a road: dark casing, coloured surface, dashed centre line. */
export function drawRoadway(
  painter: Painter,
  cubics: readonly Point[][],
  color: string,
  /** The road the lesson builds (the presenter may hide it), not one it joins. */
  main = false,
): void {
  const { theme } = painter;
  const w = theme.sizes.curve;
  const role = main ? ('curve' as const) : undefined;
  painter.cubicSegments(cubics, { color: theme.ink, width: w * 3.4, role });
  painter.cubicSegments(cubics, { color, width: w * 2.4, role });
  painter.cubicSegments(cubics, {
    color: theme.background,
    width: Math.max(1, theme.sizes.thin),
    dash: [w * 2.5, w * 2.5],
    role,
  });
}

/** The overlay's line style of curve `index`: its colour, and a dash so curves differ in print too. */
function overlayStyle(painter: Painter, index: number) {
  return {
    color: painter.color(index),
    width: painter.theme.sizes.curve * 0.9,
    dash: CURVES[index].dash.map((d) => d * painter.theme.sizes.line * 0.6),
    role: 'curve' as const,
  };
}

/** One curve of the overlay. */
export function drawOverlayCurve(painter: Painter, curve: OverlayCurve): void {
  const style = overlayStyle(painter, curve.index);
  if (curve.cubics) painter.cubicSegments(curve.cubics, style);
  else if (curve.road.kind === 'polyline') painter.polylineFlat(curve.road.coords, style);
}

/** The legend of the overlay, top left: a line sample and the name of each curve. Returns the y below it. */
export function drawLegend(painter: Painter, curves: readonly OverlayCurve[]): number {
  const theme = painter.theme;
  return drawKey(
    painter,
    curves.map((curve) => ({
      text: CURVES[curve.index].name + (curve.road.kind === 'missing' ? ' (not drawn)' : ''),
      color: curve.road.kind === 'missing' ? theme.muted : theme.ink,
      line: overlayStyle(painter, curve.index),
    })),
  );
}

/** The ticks of p̄ across the road (see parameterTicks): long at the villages, short between. */
export function drawParameterTicks(painter: Painter, ticks: Float64Array): void {
  const { theme, view } = painter;
  const major = view.worldLength(theme.sizes.curve * 2.4);
  const minor = view.worldLength(theme.sizes.curve * 1.7);
  const style = { color: theme.ink, width: Math.max(1.5, theme.sizes.thin * 1.5) };
  for (let k = 0; k < ticks.length; k += TICK_STRIDE) {
    const [x, y, nx, ny] = [ticks[k], ticks[k + 1], ticks[k + 2], ticks[k + 3]];
    const length = ticks[k + 4] ? major : minor;
    painter.segment([x - nx * length, y - ny * length], [x + nx * length, y + ny * length], style);
  }
}

/** The curvature comb: the line through the tips of each piece, then the teeth. */
export function drawCurvatureComb(painter: Painter, comb: CurvatureComb, color: string): void {
  for (const envelope of comb.envelopes)
    painter.polylineFlat(envelope, { color, width: painter.theme.sizes.line });
  painter.polylineFlat(comb.teeth, {
    color,
    width: Math.max(1, painter.theme.sizes.thin),
    alpha: 0.7,
  });
}

/** Boxed sentences at the top of the figure (wrapped to its width): why something looks as it does. */
export function drawFigureNote(painter: Painter, lines: readonly string[], top?: number): void {
  let y = top;
  for (const line of lines) y = painter.note(line, { top: y });
}
