import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked } from '../painting';

export function drawSplit(painter: Painter, m: ModelOf<'split'>, info: DrawInfo): void {
  const theme = painter.theme;
  const k = m.state.k;
  painter.polyline(m.controls, {
    color: theme.polygon,
    width: theme.sizes.thin,
    dash: [6, 5],
    alpha: 0.6,
  });
  painter.polylineFlat(m.curve, { color: theme.curve, width: theme.sizes.curve });
  m.levels[k].forEach((piece, j) => {
    const color = painter.color(j % 2);
    painter.polyline(piece, { color, width: theme.sizes.line * 1.2, alpha: 0.9 });
    for (const point of piece) painter.dot(point, color, theme.sizes.point * (k > 2 ? 0.6 : 0.9));
  });
  if (k >= 1) drawMarked(painter, m.point, 'P(t)', info);
}
