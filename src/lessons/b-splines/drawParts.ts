import type { DrawInfo } from '../../app/lesson';
import type { Point } from '../../math';
import type { Painter, StrokeStyle } from '../../render/painter';
import { haloIds, segmentIds } from './ids';
import type { BSplineModel } from './model';
import { controlPoints } from './points';

/** A hint in the figure (not in the gallery's thumbnail). */
export const hint = (painter: Painter, info: DrawInfo, text: string) => {
  if (!info.thumbnail) painter.note(text);
};

/** The control point hovered: its handle, or (with `halos`) its weight's halo; else null. */
export function hoveredPoint(hover: string | null, halos = true): number | null {
  const handle = hover === null ? null : controlPoints.ref(hover);
  if (handle) return handle.index;
  return halos ? haloIds.index(hover) : null;
}

/** Which segments to draw strongly: the hovered one, or those a hovered point moves. */
export function emphasis(m: BSplineModel, info: DrawInfo): (i: number) => 'strong' | 'weak' | '' {
  const segment = segmentIds.index(info.hover);
  // A point, or its weight's halo: the segments it acts on.
  const point = hoveredPoint(info.hover);
  if (segment !== null) return (i) => (i === segment ? 'strong' : 'weak');
  if (point !== null) return (i) => (m.segments[i]?.points.includes(point) ? 'strong' : 'weak');
  return () => '';
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
      best = segmentIds.id(i);
    }
  });
  return best;
}

/** The curve's segments, each in its own colour (the lesson's main result). */
export function drawSegments(
  painter: Painter,
  m: BSplineModel,
  info: DrawInfo,
  only: number | null = null,
): void {
  const theme = painter.theme;
  const level = emphasis(m, info);
  m.segments.forEach((segment, i) => {
    if (only !== null && i !== only) return;
    const look = level(i);
    const style: StrokeStyle = {
      color: painter.color(i),
      width: theme.sizes.curve * (look === 'strong' ? 1.7 : 1),
      alpha: look === 'weak' ? 0.35 : 1,
      role: 'curve',
    };
    if (segment.bezier) painter.cubicSegments([segment.bezier], style);
    else painter.polylineFlat(segment.samples, style);
  });
}

/** Rings around the control points of the hovered segment. */
export function ringHovered(painter: Painter, m: BSplineModel, info: DrawInfo): void {
  const i = segmentIds.index(info.hover);
  const segment = i === null ? undefined : m.segments[i];
  if (i === null || !segment) return;
  for (const j of segment.points) {
    painter.ring(m.state.points[j], painter.theme.sizes.handle * 2.2, {
      color: painter.color(i),
      width: painter.theme.sizes.line * 1.5,
    });
  }
}

export function drawPolygon(painter: Painter, points: readonly Point[], closed = false): void {
  const theme = painter.theme;
  painter.polyline(points, { color: theme.polygon, width: theme.sizes.line, dash: [6, 5] }, closed);
}

/**
 * The point at the cursor, labelled beside it, all round it, and on a leader
 * if it must go farther, nearer it than any control point: shifted a label's
 * width at a time, its name stood 109 px off by the polygon (Repeated knots).
 */
export function drawCursor(painter: Painter, m: BSplineModel, text: string, info: DrawInfo): void {
  const theme = painter.theme;
  const radius = theme.sizes.point * 1.6;
  painter.movingPoint(m.point, 1.6);
  if (info.thumbnail) return;
  const rivals = m.state.points.map((p) => painter.view.toScreen(p) as [number, number]);
  painter.label(text, m.point, { around: radius, color: theme.ink, halo: true, rivals });
}

/** Small labelled marks (Bézier points, crossings, joints). */
export function drawMarks(
  painter: Painter,
  points: readonly Point[],
  color: string,
  labels: readonly string[] | null,
  info: DrawInfo,
): void {
  const theme = painter.theme;
  const radius = theme.sizes.point * 1.1;
  // Named marks are rivals of the handles' names, and of each other's: each
  // name goes on the side of its own mark, nearer it than any other mark or
  // handle (the placer adds the handles and the figure's other named points).
  const rivals = labels && !info.thumbnail ? points.map((p) => painter.namedPoint(p)) : [];
  points.forEach((point, k) => {
    painter.dot(point, color, radius);
    const text = labels?.[k];
    if (text && !info.thumbnail) {
      painter.label(text, point, {
        around: radius + theme.sizes.line,
        color,
        halo: true,
        size: theme.sizes.label * 0.85,
        rivals,
      });
    }
  });
}

/** Distance from `at` to a sampled path (interleaved x, y). */
export function distanceToPath(samples: Float64Array, at: readonly number[]): number {
  let best = Infinity;
  for (let k = 0; k + 3 < samples.length; k += 2) {
    const ax = samples[k];
    const ay = samples[k + 1];
    const dx = samples[k + 2] - ax;
    const dy = samples[k + 3] - ay;
    const length = dx * dx + dy * dy;
    const f =
      length > 0 ? Math.max(0, Math.min(1, ((at[0] - ax) * dx + (at[1] - ay) * dy) / length)) : 0;
    best = Math.min(best, Math.hypot(at[0] - ax - f * dx, at[1] - ay - f * dy));
  }
  return best;
}
