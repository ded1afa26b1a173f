import type { DrawInfo } from '../../../app/lesson';
import { add } from '../../../math';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawMarked, drawPolygon } from '../painting';

/**
 * The curve, its legs as vectors (on the polygon and again from O), the
 * derivative's control points n(P_{i+1} − P_i) from O, its polygon and curve,
 * P′(t) on it, and the same vector at P(t) along the construction's last edge.
 */
export function drawHodograph(painter: Painter, m: ModelOf<'hodograph'>, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown, controls, origin, n } = m;
  if (!shown.has('curve')) return;
  drawPolygon(painter, controls);
  painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
  const legs = painter.color(0);
  const scaled = painter.color(2);
  const label = (text: string, at: readonly number[], color: string) => {
    if (!info.thumbnail) painter.label(text, at, { dx: 6, dy: -6, color, halo: true, bold: true });
  };
  if (shown.has('differences')) {
    const faint = shown.has('times');
    const style = {
      color: legs,
      width: theme.sizes.line * (faint ? 1 : 1.4),
      alpha: faint ? 0.5 : 1,
    };
    controls.slice(1).forEach((q, i) => painter.arrow(controls[i], q, style));
    m.placedDifferences.forEach((tip, i) => {
      painter.arrow(origin, tip, style);
      if (shown.is('differences')) label(`P_{${i + 1}} − P_{${i}}`, tip, legs);
    });
    painter.dot(origin, theme.ink, theme.sizes.point);
    label('O', origin, theme.ink);
  }
  if (shown.has('times')) {
    const style = { color: scaled, width: theme.sizes.line * 1.4 };
    m.placed.forEach((tip, i) => {
      painter.arrow(origin, tip, shown.has('hodograph') ? { ...style, alpha: 0.5 } : style);
      label(`${n}(P_{${i + 1}} − P_{${i}})`, tip, scaled);
    });
  }
  if (shown.has('hodograph')) {
    drawPolygon(painter, m.placed, { color: scaled });
    painter.polylineFlat(m.placedCurve, { color: scaled, width: theme.sizes.curve });
  }
  if (shown.has('derivative')) {
    const tip = add(origin, m.derivative);
    painter.arrow(origin, tip, { color: theme.accent, width: theme.sizes.line * 1.6 });
    drawMarked(painter, tip, 'P′(t)', info);
  }
  if (shown.has('tangent')) {
    const edge = painter.color(3);
    painter.segment(m.edge[0], m.edge[1], { color: edge, width: theme.sizes.line * 2 });
    m.edge.forEach((end) => painter.dot(end, edge, theme.sizes.point * 0.8));
    painter.arrow(m.point, add(m.point, m.derivative), {
      color: theme.accent,
      width: theme.sizes.line * 1.6,
    });
    drawMarked(painter, m.point, 'P(t)', info);
  }
}
