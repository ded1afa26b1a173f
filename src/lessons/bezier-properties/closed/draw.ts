import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';
import { STAGES } from '../state';

const AT = STAGES.closed;

export function drawClosed(painter: Painter, m: ModelOf<'closed'>, info: DrawInfo): void {
  const theme = painter.theme;
  const k = m.state.k;
  if (k >= AT.polygon) drawPolygon(painter, m.controls);
  if (k >= AT.curve) painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
  if (k >= AT.tangents) {
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
  if (k >= AT.point) drawMarked(painter, m.point, 'P(t)', info, theme.accent);
}
