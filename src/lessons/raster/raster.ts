import { type Point, nearestOnSegment, rasterizeLine, segmentCoverage } from '../../math';

// From segments to pixels. Pixel (i, j) of a raster with `zoom` pixels per
// unit covers [i, i + 1] × [j, j + 1] / zoom; its centre is at pixel
// coordinates (i, j), which is what rasterizeLine and segmentCoverage use.

/** A pixel and what it holds: lit (1) or covered by a fraction of its area. */
export interface Pixel {
  i: number;
  j: number;
  value: number;
}

/** The raster: `width` × `height` pixels of size 1 / zoom, from pixel (left, bottom). */
export interface RasterSize {
  zoom: number;
  left: number;
  bottom: number;
  width: number;
  height: number;
}

/** A point in pixel coordinates (pixel centres at whole numbers). */
export const toPixel = (p: Point, zoom: number): [number, number] => [
  p[0] * zoom - 0.5,
  p[1] * zoom - 0.5,
];

const inside = (size: RasterSize, i: number, j: number) =>
  i >= size.left && j >= size.bottom && i < size.left + size.width && j < size.bottom + size.height;

/** The pixels a line rasteriser lights for a polyline, each once, on the raster only. */
export function rasterizePolyline(points: readonly Point[], size: RasterSize): Map<string, Pixel> {
  const lit = new Map<string, Pixel>();
  for (let k = 0; k + 1 < points.length; k++) {
    const [u0, v0] = toPixel(points[k], size.zoom);
    const [u1, v1] = toPixel(points[k + 1], size.zoom);
    for (const [i, j] of rasterizeLine(u0, v0, u1, v1)) {
      if (inside(size, i, j)) lit.set(`${i},${j}`, { i, j, value: 1 });
    }
  }
  return lit;
}

/**
 * Anti-aliased: each pixel's coverage by the polyline drawn one pixel wide,
 * the larger of its segments' coverages where two segments meet.
 */
export function coveragePolyline(points: readonly Point[], size: RasterSize): Map<string, Pixel> {
  const covered = new Map<string, Pixel>();
  for (let k = 0; k + 1 < points.length; k++) {
    for (const pixel of segmentPixels(points[k], points[k + 1], size)) {
      const key = `${pixel.i},${pixel.j}`;
      const before = covered.get(key);
      if (!before || before.value < pixel.value) covered.set(key, pixel);
    }
  }
  return covered;
}

/** The pixels one segment (1 pixel wide) covers, with their coverage, on the raster only. */
export function segmentPixels(a: Point, b: Point, size: RasterSize): Pixel[] {
  const [u0, v0] = toPixel(a, size.zoom);
  const [u1, v1] = toPixel(b, size.zoom);
  const pixels: Pixel[] = [];
  for (let i = Math.floor(Math.min(u0, u1)) - 1; i <= Math.ceil(Math.max(u0, u1)) + 1; i++) {
    for (let j = Math.floor(Math.min(v0, v1)) - 1; j <= Math.ceil(Math.max(v0, v1)) + 1; j++) {
      if (!inside(size, i, j)) continue;
      const value = segmentCoverage(u0, v0, u1, v1, 1, i, j);
      if (value > 0) pixels.push({ i, j, value });
    }
  }
  return pixels;
}

/** One segment rasterised step by step: what each step along the major axis decides. */
export interface LineSteps {
  /** The segment's ends in pixel coordinates. */
  from: [number, number];
  to: [number, number];
  /** The pixels, one per unit step along the major axis. */
  pixels: [number, number][];
  /** Which coordinate steps by one pixel each time. */
  major: 'x' | 'y';
  /** At each step, where the ideal line through the end pixels' centres crosses (minor coordinate). */
  ideal: number[];
}

export function lineSteps(a: Point, b: Point, zoom: number): LineSteps {
  const from = toPixel(a, zoom);
  const to = toPixel(b, zoom);
  const pixels = rasterizeLine(from[0], from[1], to[0], to[1]);
  const first = pixels[0];
  const last = pixels[pixels.length - 1];
  const major = Math.abs(last[0] - first[0]) >= Math.abs(last[1] - first[1]) ? 'x' : 'y';
  const [m, n] = major === 'x' ? [0, 1] : [1, 0];
  const run = last[m] - first[m];
  const ideal = pixels.map((pixel) =>
    run === 0 ? first[n] : first[n] + ((pixel[m] - first[m]) * (last[n] - first[n])) / run,
  );
  return { from, to, pixels, major, ideal };
}

/**
 * The lit pixels whose centres lie more than `limit` pixels from the curve,
 * given as a polyline far finer than a pixel: a pixel any rasteriser of the
 * curve itself might light is within ½ pixel across of it, so these are
 * pixels the curve would never light.
 */
export function farPixels(
  lit: Map<string, Pixel>,
  curve: readonly Point[],
  zoom: number,
  limit = 1,
): Pixel[] {
  const path = curve.map((p) => toPixel(p, zoom));
  const far: Pixel[] = [];
  for (const pixel of lit.values()) {
    const centre = [pixel.i, pixel.j];
    let nearest = Infinity;
    for (let k = 0; k + 1 < path.length && nearest > limit; k++) {
      const q = nearestOnSegment(centre, path[k], path[k + 1]);
      nearest = Math.min(nearest, Math.hypot(q[0] - centre[0], q[1] - centre[1]));
    }
    if (nearest > limit) far.push(pixel);
  }
  return far;
}
