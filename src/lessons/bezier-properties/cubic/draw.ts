import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';

export function drawCubic(painter: Painter, m: ModelOf<'cubic'>, info: DrawInfo): void {
  const theme = painter.theme;
  drawPolygon(painter, m.controls);
  // One colour turning left, another turning right.
  for (const { sign, samples } of m.runs) {
    const color = sign > 0 ? painter.color(0) : sign < 0 ? painter.color(1) : theme.curve;
    painter.polylineFlat(samples, { color });
  }
  m.inflections.forEach(({ t, point }, j) =>
    drawMarked(
      painter,
      point,
      `inflection${j === 0 ? '' : ' 2'}, t = ${t.toFixed(2)}`,
      info,
      theme.accent,
    ),
  );
  if (m.loop) {
    const { t, point } = m.loop;
    painter.ring(point, theme.sizes.point * 2.2, {
      color: theme.accent,
      width: theme.sizes.line * 1.5,
    });
    if (!info.thumbnail) {
      painter.label(`crossing, t = ${t[0].toFixed(2)} and ${t[1].toFixed(2)}`, point, {
        dx: theme.sizes.point * 3,
        dy: -theme.sizes.label * 0.9,
        color: theme.accent,
        halo: true,
        bold: true,
      });
    }
  }
  drawMarked(painter, m.point, 'P(t)', info, theme.ink);
}
