import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';

/** The end tangents at half length, named as the step's formula names them. */
const NAMES = ['½x_0′', '½x_1′'];

export function drawHermite(painter: Painter, m: ModelOf<'hermite'>, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  if (!shown.has('curve')) return;
  // Neither form wears the accent, the colour of P(t).
  const hermite = painter.color(2);
  drawPolygon(painter, m.controls);
  painter.polylineFlat(m.curve, {
    color: painter.color(0),
    width: theme.sizes.curve * 2.2,
    role: 'curve',
  });
  if (shown.has('hermite')) {
    painter.polylineFlat(m.hermiteCurve, {
      color: hermite,
      width: theme.sizes.curve * 0.8,
      dash: [10, 6],
      role: 'curve',
    });
  }
  if (shown.has('tangents')) {
    painter.arrow(m.x0, m.tips[0], { color: hermite, width: theme.sizes.line * 1.3 });
    painter.arrow(m.x1, m.tips[1], { color: hermite, width: theme.sizes.line * 1.3 });
    if (!info.thumbnail) {
      m.tips.forEach((tip, j) =>
        painter.label(NAMES[j], tip, {
          dx: 6,
          dy: -theme.sizes.label * 0.6,
          color: hermite,
          halo: true,
          bold: true,
        }),
      );
    }
  }
  if (shown.has('point')) drawMarked(painter, m.point, 'P(t)', info);
}
