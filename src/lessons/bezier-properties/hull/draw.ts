import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';
import { STAGES } from '../state';

const AT = STAGES.hull;

export function drawHull(painter: Painter, m: ModelOf<'hull'>, info: DrawInfo): void {
  const theme = painter.theme;
  const k = m.state.k;
  const corners = m.hull;
  const color = painter.color(2);
  if (k >= AT.hull) {
    if (corners.length >= 3) {
      painter.polygon(corners, color, 0.14, { color, width: theme.sizes.line });
    } else if (corners.length === 2) {
      painter.segment(corners[0], corners[1], { color, width: theme.sizes.line * 3, alpha: 0.4 });
    }
  }
  if (k >= AT.polygon) drawPolygon(painter, m.controls);
  if (k >= AT.curve) painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
  if (k >= AT.point) drawMarked(painter, m.point, 'P(t)', info);
}
