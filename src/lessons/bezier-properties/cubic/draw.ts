import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';

export function drawCubic(painter: Painter, m: ModelOf<'cubic'>, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  if (shown.has('polygon')) drawPolygon(painter, m.controls);
  // One colour turning left, another turning right (neither is the accent of the marks).
  for (const { sign, samples } of shown.has('curve') ? m.runs : []) {
    const turning = shown.has('turning');
    const color =
      turning && sign > 0 ? painter.color(0) : turning && sign < 0 ? painter.color(2) : theme.curve;
    painter.polylineFlat(samples, { color, role: 'curve' });
  }
  if (shown.has('marks')) drawMarks(painter, m, info);
  if (shown.has('point')) drawMarked(painter, m.point, 'P(t)', info, theme.ink);
}

/** The inflections and the crossing of a loop, with their parameters. */
function drawMarks(painter: Painter, m: ModelOf<'cubic'>, info: DrawInfo): void {
  const theme = painter.theme;
  m.inflections.forEach(({ t, point }, j) =>
    drawMarked(
      painter,
      point,
      `inflection${j === 0 ? '' : ' 2'}, t = ${t.toFixed(2)}`,
      info,
      theme.accent,
    ),
  );
  if (!m.loop) return;
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
