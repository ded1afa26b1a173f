/**
 * Keeping drawing bounded by the screen, not by the zoom: lines, curves and
 * polygons are cut to the visible rectangle (plus a margin) in screen pixels
 * before they reach the canvas, and a curve far larger than the screen is
 * subdivided until its visible pieces are screen-sized. A figure zoomed a
 * million times in costs what it costs at rest.
 */

/** The rectangle drawing is cut to, in screen pixels. */
export interface ClipRect {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

/** The part of a segment inside the rectangle as [t0, t1] along it, or null (Liang–Barsky). */
export function clipSegment(
  ax: number,
  ay: number,
  bx: number,
  by: number,
  r: ClipRect,
): [number, number] | null {
  let t0 = 0;
  let t1 = 1;
  const dx = bx - ax;
  const dy = by - ay;
  const edges: [number, number][] = [
    [-dx, ax - r.minX],
    [dx, r.maxX - ax],
    [-dy, ay - r.minY],
    [dy, r.maxY - ay],
  ];
  for (const [p, q] of edges) {
    if (p === 0) {
      if (q < 0) return null;
    } else {
      const t = q / p;
      if (p < 0) {
        if (t > t1) return null;
        if (t > t0) t0 = t;
      } else {
        if (t < t0) return null;
        if (t < t1) t1 = t;
      }
    }
  }
  return [t0, t1];
}

/** The path calls a clipped polyline makes. */
export interface PathSink {
  moveTo(x: number, y: number): void;
  lineTo(x: number, y: number): void;
  bezierCurveTo(c1x: number, c1y: number, c2x: number, c2y: number, x: number, y: number): void;
}

/**
 * Feeds a polyline (screen coordinates, interleaved x, y) to `sink`, cut to
 * `r`, with vertices closer than `tolerance` pixels to the last one dropped.
 * Returns the number of vertices emitted.
 */
export function clipPolyline(
  xy: ArrayLike<number>,
  r: ClipRect,
  sink: PathSink,
  tolerance = 0.35,
): number {
  let emitted = 0;
  let penX = 0;
  let penY = 0;
  // The pen is at (or within `tolerance` of) the start of the next segment.
  let connected = false;
  const n = xy.length >> 1;
  const t2 = tolerance * tolerance;
  for (let i = 1; i < n; i++) {
    const ax = xy[2 * i - 2];
    const ay = xy[2 * i - 1];
    const bx = xy[2 * i];
    const by = xy[2 * i + 1];
    if (!(
      Number.isFinite(ax) &&
      Number.isFinite(ay) &&
      Number.isFinite(bx) &&
      Number.isFinite(by)
    )) {
      connected = false;
      continue;
    }
    let sx = ax;
    let sy = ay;
    let ex = bx;
    let ey = by;
    let startCut = false;
    let endCut = false;
    // Both ends inside is the common case: no arithmetic beyond the test.
    const inside =
      ax >= r.minX &&
      ax <= r.maxX &&
      ay >= r.minY &&
      ay <= r.maxY &&
      bx >= r.minX &&
      bx <= r.maxX &&
      by >= r.minY &&
      by <= r.maxY;
    if (!inside) {
      const cut = clipSegment(ax, ay, bx, by, r);
      if (!cut) {
        connected = false;
        continue;
      }
      startCut = cut[0] > 0;
      endCut = cut[1] < 1;
      sx = ax + (bx - ax) * cut[0];
      sy = ay + (by - ay) * cut[0];
      ex = ax + (bx - ax) * cut[1];
      ey = ay + (by - ay) * cut[1];
    }
    if (!connected || startCut) {
      sink.moveTo(sx, sy);
      emitted++;
      penX = sx;
      penY = sy;
    }
    const dx = ex - penX;
    const dy = ey - penY;
    if (endCut || i === n - 1 || dx * dx + dy * dy >= t2) {
      sink.lineTo(ex, ey);
      emitted++;
      penX = ex;
      penY = ey;
    }
    connected = !endCut;
  }
  return emitted;
}

/** Deepest subdivision of one cubic: 2^-60 of a curve is far below a pixel at any zoom. */
const MAX_DEPTH = 60;

/**
 * Feeds a cubic Bézier (screen coordinates) to `sink`, cut to `r`: culled
 * when its control box misses the rectangle, drawn natively when it is
 * screen-sized, halved by de Casteljau while it is much larger than the
 * screen. `pen` is where the path is now; returns where it ends.
 */
export function clipCubic(
  q: readonly number[],
  r: ClipRect,
  sink: PathSink,
  pen: [number, number] | null,
  depth = 0,
): [number, number] | null {
  let minX = q[0];
  let maxX = q[0];
  let minY = q[1];
  let maxY = q[1];
  for (let i = 2; i < 8; i += 2) {
    if (q[i] < minX) minX = q[i];
    if (q[i] > maxX) maxX = q[i];
    if (q[i + 1] < minY) minY = q[i + 1];
    if (q[i + 1] > maxY) maxY = q[i + 1];
  }
  if (!(maxX >= r.minX && minX <= r.maxX && maxY >= r.minY && minY <= r.maxY)) return null;
  const span = Math.max(r.maxX - r.minX, r.maxY - r.minY);
  if ((maxX - minX <= 4 * span && maxY - minY <= 4 * span) || depth >= MAX_DEPTH) {
    if (!pen || pen[0] !== q[0] || pen[1] !== q[1]) sink.moveTo(q[0], q[1]);
    sink.bezierCurveTo(q[2], q[3], q[4], q[5], q[6], q[7]);
    return [q[6], q[7]];
  }
  const mid = (a: number, b: number) => (a + b) / 2;
  const l1x = mid(q[0], q[2]);
  const l1y = mid(q[1], q[3]);
  const m1x = mid(q[2], q[4]);
  const m1y = mid(q[3], q[5]);
  const r2x = mid(q[4], q[6]);
  const r2y = mid(q[5], q[7]);
  const l2x = mid(l1x, m1x);
  const l2y = mid(l1y, m1y);
  const r1x = mid(m1x, r2x);
  const r1y = mid(m1y, r2y);
  const cx = mid(l2x, r1x);
  const cy = mid(l2y, r1y);
  const left = clipCubic([q[0], q[1], l1x, l1y, l2x, l2y, cx, cy], r, sink, pen, depth + 1);
  const right = clipCubic([cx, cy, r1x, r1y, r2x, r2y, q[6], q[7]], r, sink, left, depth + 1);
  return right ?? left;
}

/** A polygon (screen coordinates) cut to the rectangle, for filling (Sutherland–Hodgman). */
export function clipPolygon(points: readonly (readonly number[])[], r: ClipRect): number[][] {
  let out: number[][] = points.map((p) => [p[0], p[1]]);
  const edges: [(p: number[]) => boolean, (a: number[], b: number[]) => number[]][] = [
    [(p) => p[0] >= r.minX, (a, b) => atX(a, b, r.minX)],
    [(p) => p[0] <= r.maxX, (a, b) => atX(a, b, r.maxX)],
    [(p) => p[1] >= r.minY, (a, b) => atY(a, b, r.minY)],
    [(p) => p[1] <= r.maxY, (a, b) => atY(a, b, r.maxY)],
  ];
  for (const [inside, cross] of edges) {
    const input = out;
    out = [];
    for (let i = 0; i < input.length; i++) {
      const a = input[(i + input.length - 1) % input.length];
      const b = input[i];
      if (inside(b)) {
        if (!inside(a)) out.push(cross(a, b));
        out.push(b);
      } else if (inside(a)) out.push(cross(a, b));
    }
    if (!out.length) break;
  }
  return out;
}

const atX = (a: number[], b: number[], x: number) => [
  x,
  a[1] + ((b[1] - a[1]) * (x - a[0])) / (b[0] - a[0]),
];
const atY = (a: number[], b: number[], y: number) => [
  a[0] + ((b[0] - a[0]) * (y - a[1])) / (b[1] - a[1]),
  y,
];

/** Does a circle (screen) reach into the rectangle? */
export function circleVisible(x: number, y: number, radius: number, r: ClipRect): boolean {
  const nx = Math.max(r.minX, Math.min(x, r.maxX));
  const ny = Math.max(r.minY, Math.min(y, r.maxY));
  return Math.hypot(x - nx, y - ny) <= radius;
}
