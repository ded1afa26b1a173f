import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawPolygon } from '../painting';

export function drawLocal(painter: Painter, m: ModelOf<'local'>, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  if (shown.has('before')) {
    drawPolygon(painter, m.before, { alpha: 0.45 });
    painter.polylineFlat(m.beforeCurve, {
      color: theme.curveFaint,
      width: theme.sizes.curve,
      dash: [8, 6],
    });
  }
  if (shown.has('curve')) {
    drawPolygon(painter, m.controls);
    painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
  }
  const { from, to, distance } = m.largest;
  if (shown.has('largest') && distance > 0) {
    painter.arrow(from, to, { color: theme.accent, width: theme.sizes.line * 1.3 });
    if (!info.thumbnail) {
      painter.label(`max ${distance.toFixed(3)}`, to, {
        dx: 8,
        dy: -theme.sizes.label * 0.8,
        color: theme.accent,
        halo: true,
        bold: true,
      });
    }
  }
  if (!shown.has('moved')) return;
  for (const i of m.moved) {
    painter.arrow(m.before[i], m.controls[i], {
      color: theme.muted,
      width: theme.sizes.thin,
      dash: [4, 4],
    });
    painter.dot(m.before[i], theme.curveFaint, theme.sizes.point);
  }
}
