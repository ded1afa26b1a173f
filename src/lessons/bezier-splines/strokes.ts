import type { Point } from '../../math';
import type { Painter } from '../../render/painter';

// The strokes every part draws with: dashed control polygons and small labels.

export const dashed = (painter: Painter) => ({
  color: painter.theme.polygon,
  width: painter.theme.sizes.line,
  dash: [6, 5],
});

export const labelAt = (painter: Painter, text: string, p: Point, color?: string) =>
  painter.label(text, p, {
    dx: 10,
    dy: -10,
    color: color ?? painter.theme.ink,
    halo: true,
    size: painter.theme.sizes.label * 0.9,
  });

/** The control polygon of every piece, dashed, and its inner control points as dots. */
export function polygons(painter: Painter, pieces: readonly Point[][], dots = true) {
  for (const piece of pieces) {
    painter.polyline(piece, dashed(painter));
    if (dots) for (const q of piece.slice(1, -1)) painter.dot(q, painter.theme.accent);
  }
}
