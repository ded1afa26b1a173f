import type { DrawInfo } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import { drawCursor, drawMarks, drawPolygon, drawSegments, hint, ringHovered } from './drawParts';
import type { ConvertModel, LocalModel, PropertiesModel, UniformModel } from './model';
import { segmentLabel } from './notation';

/** The uniform cubic, open or closed: points, polygon, one segment, all, joints. */
export function drawUniform(painter: Painter, m: UniformModel, info: DrawInfo): void {
  const { shown } = m;
  const closed = m.state.part === 'closed';
  if (shown.has('polygon')) drawPolygon(painter, m.state.points, closed);
  if (shown.is('segment')) {
    drawSegments(painter, m, info, m.segment);
    const color = painter.color(m.segment);
    for (const j of m.segments[m.segment].points) {
      painter.ring(m.state.points[j], painter.theme.sizes.handle * 2.2, {
        color,
        width: painter.theme.sizes.line * 1.5,
      });
    }
    drawCursor(painter, m, `${segmentLabel(m.segment)}(t)`, info);
  }
  if (shown.has('segments')) {
    drawSegments(painter, m, info);
    if (!info.thumbnail) {
      m.segments.forEach((segment, i) => {
        const middle = segment.samples.length / 2 - ((segment.samples.length / 2) % 2);
        painter.label(segmentLabel(i), [segment.samples[middle], segment.samples[middle + 1]], {
          dx: 0,
          dy: -16,
          color: painter.color(i),
          halo: true,
          bold: true,
        });
      });
    }
  }
  if (shown.has('joints')) {
    const joints = m.beziers.map((bezier) => bezier[0]);
    if (!closed) joints.push(m.end);
    drawMarks(painter, joints, painter.theme.ink, null, info);
    drawCursor(painter, m, 'P(s)', info);
  }
  ringHovered(painter, m, info);
}

/** Local control: the B-spline against one Bézier curve of the same points, before and after. */
export function drawLocal(painter: Painter, m: LocalModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown, localControl: local } = m;
  const { points, before } = m.state;
  if (shown.has('curves')) drawPolygon(painter, points);
  if (shown.has('moved')) {
    painter.polylineFlat(local.bezierBefore, {
      color: theme.muted,
      width: theme.sizes.line,
      dash: [3, 5],
      alpha: 0.7,
    });
    local.before.forEach((samples) =>
      painter.polylineFlat(samples, { color: theme.curveFaint, width: theme.sizes.curve * 0.8 }),
    );
    m.segments.forEach((segment, i) => {
      if (local.changed[i]) {
        painter.polylineFlat(segment.samples, {
          color: theme.accent,
          width: theme.sizes.curve * 4,
          alpha: 0.3,
        });
      }
    });
    for (const j of local.moved) {
      painter.ring(before[j], theme.sizes.handle, {
        color: theme.accent,
        width: theme.sizes.line,
        dash: [3, 3],
      });
      painter.arrow(before[j], points[j], { color: theme.accent, width: theme.sizes.line });
    }
  }
  if (shown.has('curves')) {
    painter.polylineFlat(local.bezier, { color: theme.muted, width: theme.sizes.line * 1.4 });
    drawSegments(painter, m, info);
    if (!info.thumbnail) {
      const end = local.bezier.length - 2;
      painter.label('Bézier', [local.bezier[end >> 1], local.bezier[(end >> 1) + 1]], {
        dy: 22,
        color: theme.muted,
        halo: true,
      });
    }
  }
  if (shown.is('moved') && local.moved.length === 0)
    hint(painter, info, 'Drag a control point: only its four segments change');
  if (shown.has('basis')) drawCursor(painter, m, 'P(s)', info);
  ringHovered(painter, m, info);
}

/** B-spline ↔ Bézier, segment by segment. */
export function drawConvert(painter: Painter, m: ConvertModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown } = m;
  if (shown.has('curve')) {
    drawPolygon(painter, m.state.points);
    drawSegments(painter, m, info);
  }
  if (shown.has('beziers')) {
    m.beziers.forEach((bezier, i) => {
      if (i !== m.segment) drawMarks(painter, bezier, painter.color(i), null, info);
    });
  }
  if (shown.has('bezier')) {
    const bezier = m.beziers[m.segment];
    const color = painter.color(m.segment);
    painter.polyline(bezier, { color, width: theme.sizes.line * 1.3 });
    drawMarks(painter, bezier, color, ['B_0', 'B_1', 'B_2', 'B_3'], info);
  }
  if (shown.has('back')) {
    m.back.forEach((point) =>
      painter.ring(point, theme.sizes.handle * 2.4, {
        color: painter.color(m.segment),
        width: theme.sizes.line * 1.5,
      }),
    );
  }
  ringHovered(painter, m, info);
}

/** Convex hulls, the variation-diminishing line, the affine image. */
export function drawProperties(painter: Painter, m: PropertiesModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { shown, properties: props } = m;
  if (shown.has('hulls')) {
    props.hulls.forEach((hull, i) =>
      painter.polygon(hull, painter.color(i), 0.12, {
        color: painter.color(i),
        width: theme.sizes.thin,
      }),
    );
  }
  if (shown.has('curve')) {
    drawPolygon(painter, m.state.points);
    drawSegments(painter, m, info);
  }
  if (shown.has('line')) {
    const [a, b] = m.state.line;
    const far = 1e3;
    const dx = b[0] - a[0];
    const dy = b[1] - a[1];
    const length = Math.hypot(dx, dy) || 1;
    painter.segment(
      [a[0] - (far * dx) / length, a[1] - (far * dy) / length],
      [b[0] + (far * dx) / length, b[1] + (far * dy) / length],
      { color: theme.ink, width: theme.sizes.line },
    );
    drawMarks(painter, props.crossings.polygonPoints, theme.polygon, null, info);
    drawMarks(painter, props.crossings.curvePoints, theme.accent, null, info);
  }
  if (shown.has('affine')) {
    drawPolygon(painter, props.image);
    painter.cubicSegments(props.imageSegments, { color: theme.curve, width: theme.sizes.curve });
    drawMarks(
      painter,
      props.image,
      theme.polygon,
      props.image.map((_, i) => `AP_{${i}}`),
      info,
    );
    props.imageSamples.forEach((point) =>
      painter.ring(point, theme.sizes.point * 1.3, {
        color: theme.accent,
        width: theme.sizes.thin,
      }),
    );
  }
  ringHovered(painter, m, info);
}
