import { checkNumber } from './validate';

// Anti-aliasing by area coverage: a line drawn with width w is the rectangle
// of points within w/2 of the segment (butt ends); the grey of a pixel is the
// fraction of its unit square the rectangle covers. Both are convex, so the
// overlap is the square clipped by the rectangle's four sides
// (Sutherland & Hodgman 1974) and its area is exact (the shoelace formula).

/**
 * The area of the pixel square [i − ½, i + ½] × [j − ½, j + ½] (pixel centres
 * at integers, as rasterizeLine's) covered by the segment from (x0, y0) to
 * (x1, y1) drawn `width` pixels wide: a number in [0, 1]. A segment of zero
 * length covers nothing.
 */
export function segmentCoverage(
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  width: number,
  i: number,
  j: number,
): number {
  const caller = 'segmentCoverage';
  for (const [name, value] of [
    ['x0', x0],
    ['y0', y0],
    ['x1', x1],
    ['y1', y1],
    ['width', width],
    ['i', i],
    ['j', j],
  ] as const)
    checkNumber(caller, name, value);
  const length = Math.hypot(x1 - x0, y1 - y0);
  if (!(length > 0) || !(width > 0)) return 0;
  const ux = (x1 - x0) / length;
  const uy = (y1 - y0) / length;
  let polygon: number[][] = [
    [i - 0.5, j - 0.5],
    [i + 0.5, j - 0.5],
    [i + 0.5, j + 0.5],
    [i - 0.5, j + 0.5],
  ];
  // Keep the points with a·(p − origin) ≤ limit for each side of the rectangle.
  const half = width / 2;
  const sides: [number, number, number][] = [
    [-ux, -uy, -(ux * x0 + uy * y0)],
    [ux, uy, ux * x1 + uy * y1],
    [-uy, ux, -uy * x0 + ux * y0 + half],
    [uy, -ux, uy * x0 - ux * y0 + half],
  ];
  for (const [ax, ay, limit] of sides) {
    polygon = clipToHalfPlane(polygon, ax, ay, limit);
    if (polygon.length < 3) return 0;
  }
  return Math.min(1, Math.max(0, polygonArea(polygon)));
}

/** The part of a convex polygon where ax·x + ay·y ≤ limit. */
function clipToHalfPlane(polygon: number[][], ax: number, ay: number, limit: number): number[][] {
  const result: number[][] = [];
  for (let k = 0; k < polygon.length; k++) {
    const p = polygon[k];
    const q = polygon[(k + 1) % polygon.length];
    const fp = ax * p[0] + ay * p[1] - limit;
    const fq = ax * q[0] + ay * q[1] - limit;
    if (fp <= 0) result.push(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
      const s = fp / (fp - fq);
      result.push([p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])]);
    }
  }
  return result;
}

/** The area of a simple polygon (shoelace formula), positive either way round. */
function polygonArea(polygon: readonly number[][]): number {
  let twice = 0;
  for (let k = 0; k < polygon.length; k++) {
    const [x0, y0] = polygon[k];
    const [x1, y1] = polygon[(k + 1) % polygon.length];
    twice += x0 * y1 - x1 * y0;
  }
  return Math.abs(twice) / 2;
}
