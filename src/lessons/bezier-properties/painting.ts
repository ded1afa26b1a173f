import type { DrawInfo } from '../../app/lesson';
import type { Painter, StrokeStyle } from '../../render/painter';

/** The control polygon, dashed. */
export function drawPolygon(
  painter: Painter,
  points: readonly (readonly number[])[],
  style: StrokeStyle = {},
): void {
  painter.polyline(points, {
    color: painter.theme.polygon,
    width: painter.theme.sizes.line,
    dash: [6, 5],
    ...style,
  });
}

/** A point on the curve with a label, skipped in thumbnails. */
export function drawMarked(
  painter: Painter,
  point: readonly number[],
  text: string,
  info: DrawInfo,
  color = painter.theme.accent,
): void {
  // The accent's point is the one the step is about: over the handles (P(0) = P₀).
  if (color === painter.theme.accent) painter.movingPoint(point, 1.3);
  else painter.dot(point, color, painter.theme.sizes.point * 1.3);
  if (info.thumbnail) return;
  painter.label(text, point, {
    dx: painter.theme.sizes.point + 5,
    dy: painter.theme.sizes.label * 0.9,
    color,
    halo: true,
    bold: true,
  });
}
