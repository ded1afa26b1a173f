import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';
import { STAGES } from '../state';

const NAMES = ["½P'(0)", "½P'(1)", "½P'(t)"];
const AT = STAGES.ends;

export function drawEnds(painter: Painter, m: ModelOf<'ends'>, info: DrawInfo): void {
  const theme = painter.theme;
  const k = m.state.k;
  if (k >= AT.polygon) drawPolygon(painter, m.controls);
  if (k >= AT.curve) painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
  m.tangents.forEach(({ from, tip, speed }, j) => {
    if (k < (j < 2 ? AT.tangents : AT.point)) return;
    const color = painter.color(j);
    painter.arrow(from, tip, { color, width: theme.sizes.line * 1.4 });
    if (!info.thumbnail && speed > 0) {
      painter.label(NAMES[j], tip, {
        dx: 6,
        dy: -theme.sizes.label * 0.6,
        color,
        halo: true,
        bold: true,
      });
    }
  });
  if (k >= AT.ends) {
    drawMarked(painter, m.controls[0], 'P(0) = P_0', info, painter.color(0));
    drawMarked(painter, m.controls[m.n], `P(1) = P_{${m.n}}`, info, painter.color(1));
  }
  if (k >= AT.point) drawMarked(painter, m.point, 'P(t)', info, painter.color(2));
}
