import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawPolygon } from '../painting';

/** Above this many control points, the points are drawn smaller and unlabelled. */
const LABEL_UP_TO = 10;

export function drawElevate(painter: Painter, m: ModelOf<'elevate'>, info: DrawInfo): void {
  const theme = painter.theme;
  if (!m.shown.has('curve')) return;
  const raised = m.polygons.length > 1;
  const color = painter.color(0);
  if (raised) drawPolygon(painter, m.state.points, { alpha: 0.5 });
  else drawPolygon(painter, m.state.points);
  painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
  if (!raised) return;
  painter.polyline(m.controls, { color, width: theme.sizes.line });
  const small = m.controls.length > LABEL_UP_TO;
  m.controls.forEach((point, i) => {
    painter.dot(point, color, theme.sizes.point * (small ? 0.7 : 1));
    if (!info.thumbnail && !small) {
      painter.label(`Q_{${i}}`, point, {
        dx: -4,
        dy: theme.sizes.label * 0.9,
        align: 'right',
        color,
        halo: true,
        size: theme.sizes.small,
      });
    }
  });
}
