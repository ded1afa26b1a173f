import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';

const NAMES = ['½P′(0)', '½P′(1)', '½P′(t)'];
/** The end tangents come with their step, the tangent at t with P(t). */
const REVEALED_BY = ['tangents', 'tangents', 'point'] as const;

export function drawEnds(painter: Painter, m: ModelOf<'ends'>, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  if (shown.has('polygon')) drawPolygon(painter, m.controls);
  if (shown.has('curve')) painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
  m.tangents.forEach(({ from, tip, speed }, j) => {
    if (!shown.has(REVEALED_BY[j])) return;
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
  if (shown.has('ends')) {
    drawMarked(painter, m.controls[0], 'P(0) = P_0', info, painter.color(0));
    drawMarked(painter, m.controls[m.n], `P(1) = P_{${m.n}}`, info, painter.color(1));
  }
  if (shown.has('point')) drawMarked(painter, m.point, 'P(t)', info, painter.color(2));
}
