import type { DrawInfo } from '../../../app/lesson';
import type { Painter } from '../../../render/painter';
import type { ModelOf } from '../model';
import { drawPolygon } from '../painting';

export function drawAffine(painter: Painter, m: ModelOf<'affine'>, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  if (!shown.has('curve')) return;
  drawPolygon(painter, m.controls);
  painter.polylineFlat(m.curve, { color: theme.curve, role: 'curve' });
  const images = m.images;
  if (!images.ok) {
    if (!info.thumbnail) painter.note(`No image: ${images.why}`);
    return;
  }
  // Neither image wears the accent, the colour of P(t).
  const mapped = painter.color(0);
  const map = painter.color(2);
  if (shown.has('mappedPoints')) {
    painter.polyline(images.mappedControls, {
      color: mapped,
      width: theme.sizes.line,
      dash: [6, 5],
    });
    for (const point of images.mappedControls) painter.dot(point, mapped, theme.sizes.point);
  }
  if (shown.has('curveOfMapped')) {
    painter.polylineFlat(images.curveOfMapped, {
      color: mapped,
      width: theme.sizes.curve * 1.6,
      role: 'curve',
    });
  }
  if (shown.has('mappedCurve')) {
    painter.polylineFlat(images.mappedCurve, {
      color: map,
      width: theme.sizes.curve * 0.8,
      dash: [10, 6],
      role: 'curve',
    });
  }
  if (shown.has('point')) {
    painter.movingPoint(m.point, 1.3);
    painter.dot(images.onMapped, mapped, theme.sizes.point * 1.4);
    painter.ring(images.imageOfPoint, theme.sizes.point * 1.8, {
      color: map,
      width: theme.sizes.line * 1.3,
    });
  }
  if (info.thumbnail) return;
  // Name each image at its middle: the map of the curve above, the curve of the mapped points below.
  const name = { align: 'center', halo: true, bold: true } as const;
  if (shown.has('mappedCurve')) {
    painter.label('map of the curve', images.middles.mappedCurve, {
      ...name,
      dy: -theme.sizes.label * 1.3,
      color: map,
    });
  }
  if (shown.has('curveOfMapped')) {
    painter.label('curve of the mapped points', images.middles.curveOfMapped, {
      ...name,
      dy: theme.sizes.label * 1.3,
      color: mapped,
    });
  }
}
