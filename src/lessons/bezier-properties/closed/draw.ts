import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';

export function drawClosed(painter: Painter, m: ModelOf<'closed'>, info: DrawInfo): void {
  const theme = painter.theme;
  drawPolygon(painter, m.controls);
  painter.polylineFlat(m.curve, { color: theme.curve });
  painter.arrow(m.leaving[0], m.leaving[1], {
    color: painter.color(0),
    width: theme.sizes.line * 1.3,
  });
  painter.arrow(m.arriving[0], m.arriving[1], {
    color: painter.color(1),
    width: theme.sizes.line * 1.3,
  });
  drawMarked(painter, m.controls[0], `P_0 = P_{${m.n}}`, info, theme.accent);
  drawMarked(painter, m.point, 'P(t)', info, painter.color(2));
}
