import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';

export function drawClosed(painter: Painter, m: ModelOf<'closed'>, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  if (shown.has('polygon')) drawPolygon(painter, m.controls);
  if (shown.has('curve')) painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
  if (shown.has('tangents')) {
    painter.arrow(m.leaving[0], m.leaving[1], {
      color: painter.color(0),
      width: theme.sizes.line * 1.3,
    });
    painter.arrow(m.arriving[0], m.arriving[1], {
      color: painter.color(2),
      width: theme.sizes.line * 1.3,
    });
  }
  // P0 = PN is named once, by its handle.
  if (shown.has('point')) drawMarked(painter, m.point, 'P(t)', info, theme.accent);
}
