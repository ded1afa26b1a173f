import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';

export function drawRepeat(painter: Painter, m: ModelOf<'repeat'>, info: DrawInfo): void {
  const theme = painter.theme;
  const { points: p, repeated: r } = m.state;
  if (!m.shown.has('curve')) return;
  const extra = m.copies - 1;
  if (extra > 0) {
    painter.polylineFlat(m.onceCurve, {
      color: theme.curveFaint,
      width: theme.sizes.curve,
      dash: [8, 6],
    });
  }
  drawPolygon(painter, p);
  painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
  // The ring grows with the copies: the pull of the repeated point, seen.
  painter.ring(p[r], theme.sizes.handle * (1.6 + 0.5 * extra), {
    color: theme.accent,
    width: theme.sizes.line,
  });
  if (!info.thumbnail && extra > 0) {
    painter.label(`×${m.copies}`, p[r], {
      dx: -theme.sizes.handle * 2,
      dy: theme.sizes.label,
      align: 'right',
      color: theme.accent,
      halo: true,
      bold: true,
    });
  }
  drawMarked(painter, m.point, 'P(t)', info);
}
