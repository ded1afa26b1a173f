import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';

export function drawSplit(painter: Painter, m: ModelOf<'split'>, info: DrawInfo): void {
  const theme = painter.theme;
  if (!m.shown.has('curve')) return;
  const splits = m.levels.length - 1;
  drawPolygon(painter, m.controls, splits > 0 ? { width: theme.sizes.thin, alpha: 0.6 } : {});
  painter.polylineFlat(m.curve, { color: theme.curve, width: theme.sizes.curve, role: 'curve' });
  if (splits > 0) {
    m.levels[splits].forEach((piece, j) => {
      const color = painter.color(j % 2 === 0 ? 0 : 2);
      painter.polyline(piece, {
        color,
        width: theme.sizes.line * 1.2,
        alpha: 0.9,
        dash: j % 2 === 0 ? undefined : [10, 4],
      });
      for (const point of piece) {
        painter.dot(point, color, theme.sizes.point * (splits > 2 ? 0.6 : 0.9));
      }
    });
  }
  // Where the curve is split.
  drawMarked(painter, m.point, 'P(t)', info);
}
