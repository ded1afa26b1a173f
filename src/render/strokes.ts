/**
 * Straight strokes on screen: world points projected into one buffer reused
 * by every projection, cut to the clip rectangle, stroked, and their ink
 * recorded (a curve's marked as the figure's subject).
 */
import { clipPolyline } from './clip';
import type { P, Painter, StrokeStyle } from './painter';
import type { Projection } from './projection';

/** World points as screen pixels, interleaved x, y, in one buffer that grows as needed. */
export class ScreenPoints {
  private scratch = new Float64Array(256);

  /** Projects world points into the buffer as interleaved screen x, y: read it before the next projection. */
  project(view: Projection, points: readonly P[]): Float64Array {
    const n = points.length;
    if (this.scratch.length < 2 * n) this.scratch = new Float64Array(4 * n);
    const xy = this.scratch;
    for (let i = 0; i < n; i++) {
      const [x, y] = view.toScreen(points[i]);
      xy[2 * i] = x;
      xy[2 * i + 1] = y;
    }
    return xy.length === 2 * n ? xy : xy.subarray(0, 2 * n);
  }

  /** The same for interleaved 2D world coordinates [x0, y0, x1, y1, …]: big samples. */
  projectFlat(view: Projection, coords: ArrayLike<number>): Float64Array {
    const n = coords.length >> 1;
    if (this.scratch.length < 2 * n) this.scratch = new Float64Array(4 * n);
    const xy = this.scratch;
    const point = [0, 0];
    for (let i = 0; i < n; i++) {
      point[0] = coords[2 * i];
      point[1] = coords[2 * i + 1];
      const [x, y] = view.toScreen(point);
      xy[2 * i] = x;
      xy[2 * i + 1] = y;
    }
    return xy.subarray(0, 2 * n);
  }
}

/** A polyline through screen points, interleaved x, y, cut to the clip rectangle, and its ink. */
export function strokeScreen(painter: Painter, xy: ArrayLike<number>, style: StrokeStyle): void {
  if (painter.hidden(style)) return;
  const c = painter.ctx;
  c.save();
  painter.applyStroke(style, painter.sizes.curve, painter.theme.curve);
  c.beginPath();
  if (clipPolyline(xy, painter.clip, c) > 0) c.stroke();
  c.restore();
  const from = painter.ink.segments;
  if (style.role !== 'grid') painter.ink.polyline(xy, (style.width ?? painter.sizes.curve) / 2);
  if (style.role === 'curve') painter.ink.subject(from);
}

/**
 * Separate straight segments in one style, stroked as one path: a sampled
 * surface's hundreds of depth-sorted pieces cost one stroke, not hundreds.
 */
export function drawSegments(
  painter: Painter,
  pairs: readonly (readonly [P, P])[],
  style: StrokeStyle = {},
): void {
  if (!pairs.length || painter.hidden(style)) return;
  const c = painter.ctx;
  c.save();
  painter.applyStroke(style, painter.sizes.curve, painter.theme.curve);
  c.beginPath();
  let drawn = 0;
  const half = (style.width ?? painter.sizes.curve) / 2;
  for (const [a, b] of pairs) {
    const xy = painter.project([a, b]);
    drawn += clipPolyline(xy, painter.clip, c);
    if (style.role !== 'grid') painter.ink.segment(xy[0], xy[1], xy[2], xy[3], half);
  }
  if (drawn > 0) c.stroke();
  c.restore();
}
