import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';

export function drawHull(painter: Painter, m: ModelOf<'hull'>, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  const corners = m.hull;
  const color = painter.color(2);
  if (shown.has('hull')) {
    if (corners.length >= 3) {
      painter.polygon(corners, color, theme.tint, { color, width: theme.sizes.line });
    } else if (corners.length === 2) {
      painter.segment(corners[0], corners[1], { color, width: theme.sizes.line * 3, alpha: 0.4 });
    }
  }
  if (shown.has('polygon')) drawPolygon(painter, m.controls);
  if (shown.has('curve')) painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
  if (shown.has('point')) drawMarked(painter, m.point, 'P(t)', info);
}
