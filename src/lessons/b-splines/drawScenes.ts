import type { DrawInfo } from '../../app/lesson';
import type { Painter } from '../../render/painter';
import {
  distanceToPath,
  drawCursor,
  drawMarks,
  drawPolygon,
  drawSegments,
  ringHovered,
} from './drawParts';
import { haloRadius } from './halo';
import { CIRCLE, type BSplineModel } from './model';
import { segmentName, superscript } from './steps';

const hint = (painter: Painter, info: DrawInfo, text: string) => {
  if (!info.thumbnail) painter.note(text);
};

/** The lecture's uniform cubic, open or closed: points, polygon, one segment, all, joints. */
export function drawUniform(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  const k = m.state.k;
  const closed = m.state.x === 'closed';
  if (k >= 1) drawPolygon(painter, m.state.p, closed);
  if (k === 2) {
    drawSegments(painter, m, info, m.segment);
    const color = painter.color(m.segment);
    for (const j of m.segments[m.segment].points) {
      painter.ring(m.state.p[j], painter.theme.sizes.handle * 2.2, {
        color,
        width: painter.theme.sizes.line * 1.5,
      });
    }
    drawCursor(painter, m.point, `${segmentName(m.segment).replace(/(\d+)/, '_{$1}')}(t)`, info);
  }
  if (k >= 3) {
    drawSegments(painter, m, info);
    if (!info.thumbnail) {
      m.segments.forEach((segment, i) => {
        const middle = segment.samples.length / 2 - ((segment.samples.length / 2) % 2);
        painter.label(
          segmentName(i).replace(/(\d+)/, '_{$1}'),
          [segment.samples[middle], segment.samples[middle + 1]],
          {
            dx: 0,
            dy: -16,
            color: painter.color(i),
            halo: true,
            bold: true,
          },
        );
      });
    }
  }
  if (k >= 4) {
    const joints = m.segments.map((s) => s.bezier![0]);
    if (!closed) joints.push(m.end);
    drawMarks(painter, joints, painter.theme.ink, null, info);
    drawCursor(painter, m.point, 'P(t)', info);
  }
  ringHovered(painter, m, info);
}

/** Local control: the B-spline against one Bézier curve of the same points, before and after. */
export function drawLocal(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  const theme = painter.theme;
  const local = m.localControl!;
  const k = m.state.k;
  if (k >= 1) drawPolygon(painter, m.state.p);
  if (k >= 2) {
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
      painter.ring(m.state.q[j], theme.sizes.handle, {
        color: theme.accent,
        width: theme.sizes.line,
        dash: [3, 3],
      });
      painter.arrow(m.state.q[j], m.state.p[j], { color: theme.accent, width: theme.sizes.line });
    }
  }
  if (k >= 1) {
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
  if (k === 2 && local.moved.length === 0)
    hint(painter, info, 'Drag a control point: only its four segments change');
  if (k >= 3) drawCursor(painter, m.point, 'P(s)', info);
  ringHovered(painter, m, info);
}

/** B-spline ↔ Bézier, segment by segment. */
export function drawConvert(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  const theme = painter.theme;
  const k = m.state.k;
  if (k >= 1) {
    drawPolygon(painter, m.state.p);
    drawSegments(painter, m, info);
  }
  if (k >= 3) {
    m.segments.forEach((segment, i) => {
      if (i !== m.segment) drawMarks(painter, segment.bezier!, painter.color(i), null, info);
    });
  }
  if (k >= 2) {
    const bez = m.segments[m.segment].bezier!;
    const color = painter.color(m.segment);
    painter.polyline(bez, { color, width: theme.sizes.line * 1.3 });
    drawMarks(painter, bez, color, ['B_0', 'B_1', 'B_2', 'B_3'], info);
  }
  if (k >= 4) {
    m.convert!.bspline.forEach((point) =>
      painter.ring(point, theme.sizes.handle * 2.4, {
        color: painter.color(m.segment),
        width: theme.sizes.line * 1.5,
      }),
    );
  }
  ringHovered(painter, m, info);
}

/** Convex hulls, the variation-diminishing line, the affine image. */
export function drawProperties(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  const theme = painter.theme;
  const props = m.properties!;
  const k = m.state.k;
  if (k >= 2) {
    props.hulls.forEach((hull, i) =>
      painter.polygon(hull, painter.color(i), 0.12, {
        color: painter.color(i),
        width: theme.sizes.thin,
      }),
    );
  }
  if (k >= 1) {
    drawPolygon(painter, m.state.p);
    drawSegments(painter, m, info);
  }
  if (k >= 3) {
    const [a, b] = m.state.l;
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
  if (k >= 4) {
    drawPolygon(painter, props.image);
    painter.cubicSegments(props.imageSegments, { color: theme.curve, width: theme.sizes.curve });
    drawMarks(
      painter,
      props.image,
      theme.polygon,
      props.image.map((_, i) => `Ax_{${i}}`),
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

/** The general B-spline on its knots: the curve, its joins and their continuity. */
export function drawKnots(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  const theme = painter.theme;
  const k = m.state.k;
  const p = m.degree;
  if (k >= 1) drawPolygon(painter, m.state.p);
  if (k >= 2 && k <= p + 2 && k - 2 === p) {
    m.basis.forEach((b, i) => {
      if (b > 0)
        painter.ring(m.state.p[i], theme.sizes.handle * 2.2, {
          color: painter.color(i),
          width: theme.sizes.line * 1.5,
        });
    });
  }
  if (k >= p + 3) {
    drawSegments(painter, m, info);
    for (const join of m.joins) {
      const text = join.continuity < 0 ? 'jump' : `C${superscript(join.continuity)}`;
      painter.dot(join.at, theme.ink, theme.sizes.point);
      if (!info.thumbnail)
        painter.label(text, join.at, {
          dx: 10,
          dy: 22,
          color: theme.ink,
          halo: true,
          box: join.continuity <= 0,
        });
    }
    drawCursor(painter, m.point, 'C(u)', info);
  }
  ringHovered(painter, m, info);
}

/** NURBS: weights as halos, the plain B-spline for comparison, the circle, the perspective map. */
export function drawRational(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  const theme = painter.theme;
  const { x, k } = m.state;
  const closed = x === 'circle';
  if (k >= 1) drawPolygon(painter, m.state.p, false);
  if (x === 'nurbs') {
    if (k === 1)
      painter.polylineFlat(m.rational!.plain, {
        color: theme.curve,
        width: theme.sizes.curve,
        role: 'curve',
      });
    if (k >= 2) {
      painter.polylineFlat(m.rational!.plain, {
        color: theme.muted,
        width: theme.sizes.line,
        dash: [5, 5],
      });
      drawSegments(painter, m, info);
      weightHalos(painter, m, info);
    }
    if (k >= 3) drawCursor(painter, m.point, 'C(u)', info);
  }
  if (closed) {
    if (k >= 1) weightHalos(painter, m, info);
    if (k >= 2) drawSegments(painter, m, info);
    if (k >= 3) {
      painter.circle(CIRCLE.centre, CIRCLE.radius, {
        color: theme.ink,
        width: theme.sizes.thin,
        dash: [2, 4],
      });
      m.circle!.samples.forEach((point) => painter.dot(point, theme.ink, theme.sizes.point * 0.8));
    }
    if (k >= 4)
      painter.polylineFlat(m.rational!.plain, {
        color: theme.muted,
        width: theme.sizes.line * 1.3,
        dash: [6, 4],
      });
  }
  if (x === 'projective') drawProjective(painter, m, info);
}

function drawProjective(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  const theme = painter.theme;
  const k = m.state.k;
  const pr = m.projective!;
  if (k >= 1) drawSegments(painter, m, info);
  if (pr.error) {
    if (k >= 2) hint(painter, info, pr.error);
    return;
  }
  if (k >= 2) {
    drawPolygon(painter, pr.points);
    painter.polylineFlat(pr.curve, { color: theme.curve, width: theme.sizes.curve, role: 'curve' });
    pr.mapped
      .filter((_, k) => k % 2 === 0)
      .forEach((point) =>
        painter.ring(point, theme.sizes.point * 1.2, {
          color: theme.accent,
          width: theme.sizes.thin,
        }),
      );
    drawMarks(
      painter,
      pr.points,
      theme.polygon,
      info.thumbnail ? null : pr.weights.map((w, i) => `w'_{${i}} = ${w.toFixed(2)}`),
      info,
    );
  }
  if (k >= 3) {
    painter.polylineFlat(pr.plain, {
      color: painter.color(3),
      width: theme.sizes.line * 1.8,
      dash: [8, 5],
    });
    if (!info.thumbnail) {
      const at = (pr.plain.length >> 2) & ~1;
      painter.label('old weights', [pr.plain[at], pr.plain[at + 1]], {
        dx: 12,
        dy: -12,
        color: painter.color(3),
        halo: true,
      });
    }
  }
}

/**
 * A halo around each control point, its radius growing with the weight (drag
 * the ring to change it), and the weight written. The hovered or dragged ring is drawn bold.
 */
function weightHalos(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  const theme = painter.theme;
  const pixels = 1 / painter.view.worldLength(1);
  m.weights.forEach((w, i) => {
    const point = m.state.p[i];
    const strong = info.hover === `w${i}`;
    painter.ring(
      point,
      haloRadius(w, m.rational!.haloUnit) * pixels,
      { color: theme.accent, width: strong ? theme.sizes.line * 1.5 : theme.sizes.thin },
      theme.accent,
      strong ? 0.2 : 0.12,
    );
    if (!info.thumbnail) {
      painter.label(`w_{${i}} = ${Number(w.toFixed(3))}`, point, {
        dx: 12,
        dy: 22,
        color: theme.ink,
        halo: true,
        size: theme.sizes.label * 0.85,
      });
    }
  });
}

/** The segment under the pointer, if any. */
export function segmentAt(
  m: BSplineModel,
  at: readonly number[],
  tolerance: number,
): string | null {
  let best: string | null = null;
  let distance = tolerance;
  m.segments.forEach((segment, i) => {
    const d = distanceToPath(segment.samples, at);
    if (d <= distance) {
      distance = d;
      best = `seg${i}`;
    }
  });
  return best;
}
