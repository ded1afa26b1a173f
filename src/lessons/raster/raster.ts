import {
  type PixelBox,
  type Point,
  flattenBezier,
  nearestOnSegment,
  rasterizeLine,
  rasterizeLineInBox,
  segmentCoverage,
  splitBezier,
} from '../../math';
import { RASTER_HEIGHT, RASTER_WIDTH } from './state';

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

/** The whole raster at `zoom`: 32z × 24z pixels from pixel (0, 0). */
export const rasterSize = (zoom: number): RasterSize => ({
  zoom,
  left: 0,
  bottom: 0,
  width: Math.ceil(RASTER_WIDTH * zoom),
  height: Math.ceil(RASTER_HEIGHT * zoom),
});

/** The rectangle a raster covers, in units of the control points. */
export const windowOf = (size: RasterSize): Box => ({
  minX: size.left / size.zoom,
  minY: size.bottom / size.zoom,
  maxX: (size.left + size.width) / size.zoom,
  maxY: (size.bottom + size.height) / size.zoom,
});

/** A point in pixel coordinates (pixel centres at whole numbers). */
export const toPixel = (p: Point, zoom: number): [number, number] => [
  p[0] * zoom - 0.5,
  p[1] * zoom - 0.5,
];

/** The raster's pixels as a box of pixel centres. */
const boxOf = (size: RasterSize): PixelBox => ({
  left: size.left,
  bottom: size.bottom,
  right: size.left + size.width - 1,
  top: size.bottom + size.height - 1,
});

/**
 * The pixels a line rasteriser lights for a polyline, each once, on the raster
 * only: the work is the raster's, however far the segments reach beyond it.
 */
export function rasterizePolyline(points: readonly Point[], size: RasterSize): Map<string, Pixel> {
  const lit = new Map<string, Pixel>();
  const box = boxOf(size);
  for (let k = 0; k + 1 < points.length; k++) {
    const [u0, v0] = toPixel(points[k], size.zoom);
    const [u1, v1] = toPixel(points[k + 1], size.zoom);
    for (const [i, j] of rasterizeLineInBox(u0, v0, u1, v1, box))
      lit.set(`${i},${j}`, { i, j, value: 1 });
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
  const box = boxOf(size);
  // The segment's bounding box (and a pixel round it), cut to the raster.
  const [i0, i1] = [Math.floor(Math.min(u0, u1)) - 1, Math.ceil(Math.max(u0, u1)) + 1];
  const [j0, j1] = [Math.floor(Math.min(v0, v1)) - 1, Math.ceil(Math.max(v0, v1)) + 1];
  for (let i = Math.max(i0, box.left); i <= Math.min(i1, box.right); i++) {
    for (let j = Math.max(j0, box.bottom); j <= Math.min(j1, box.top); j++) {
      const value = segmentCoverage(u0, v0, u1, v1, 1, i, j);
      if (value > 0) pixels.push({ i, j, value });
    }
  }
  return pixels;
}

/** Pixels of one segment listed step by step at most (a longer one shows its first ones). */
export const LINE_LIMIT = 512;

/** One segment rasterised step by step: what each step along the major axis decides. */
export interface LineSteps {
  /** The segment's ends in pixel coordinates. */
  from: [number, number];
  to: [number, number];
  /** The end pixels: the ends rounded. */
  first: [number, number];
  last: [number, number];
  /** How many pixels the whole segment lights: one per step along the major axis. */
  count: number;
  /** Its first pixels, one per unit step along the major axis (all of them, up to LINE_LIMIT). */
  pixels: [number, number][];
  /** Which coordinate steps by one pixel each time. */
  major: 'x' | 'y';
  /** At each step, where the ideal line through the end pixels' centres crosses (minor coordinate). */
  ideal: number[];
}

export function lineSteps(a: Point, b: Point, zoom: number, limit = LINE_LIMIT): LineSteps {
  const from = toPixel(a, zoom);
  const to = toPixel(b, zoom);
  const round = (p: [number, number]): [number, number] => [
    Math.round(p[0]) + 0,
    Math.round(p[1]) + 0,
  ];
  const first = round(from);
  const last = round(to);
  const major = Math.abs(last[0] - first[0]) >= Math.abs(last[1] - first[1]) ? 'x' : 'y';
  const [m, n] = major === 'x' ? [0, 1] : [1, 0];
  const run = last[m] - first[m];
  const count = Math.abs(run) + 1;
  let pixels: [number, number][];
  if (count <= limit) pixels = rasterizeLine(from[0], from[1], to[0], to[1]);
  else {
    // The first `limit` steps from the start, towards the end.
    const reach = first[m] + Math.sign(run) * (limit - 1);
    const [low, high] = [Math.min(first[m], reach), Math.max(first[m], reach)];
    const box =
      major === 'x'
        ? { left: low, right: high, bottom: -Infinity, top: Infinity }
        : { left: -Infinity, right: Infinity, bottom: low, top: high };
    pixels = rasterizeLineInBox(from[0], from[1], to[0], to[1], box);
  }
  const ideal = pixels.map((pixel) =>
    run === 0 ? first[n] : first[n] + ((pixel[m] - first[m]) * (last[n] - first[n])) / run,
  );
  return { from, to, first, last, count, pixels, major, ideal };
}

/** A rectangle in units of the control points. */
export interface Box {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

/**
 * The curve near a box, as polylines within `tolerance` of it: a piece whose
 * control polygon's bounding box misses the box widened by `margin` is
 * dropped (the piece lies in its control polygon's hull), the others are
 * halved (de Casteljau) until no larger than the box, then flattened. The
 * work follows what the box shows, not how far the curve reaches beyond it.
 */
export function curveNear(
  points: readonly Point[],
  box: Box,
  margin: number,
  tolerance: number,
): Point[][] {
  const paths: Point[][] = [];
  const size = Math.max(box.maxX - box.minX, box.maxY - box.minY) + 2 * margin;
  const visit = (piece: readonly Point[], depth: number) => {
    const xs = piece.map((p) => p[0]);
    const ys = piece.map((p) => p[1]);
    const [minX, maxX, minY, maxY] = [
      Math.min(...xs),
      Math.max(...xs),
      Math.min(...ys),
      Math.max(...ys),
    ];
    if (minX > box.maxX + margin || maxX < box.minX - margin) return;
    if (minY > box.maxY + margin || maxY < box.minY - margin) return;
    if (depth >= 40 || Math.max(maxX - minX, maxY - minY) <= size) {
      paths.push(flattenBezier(piece, tolerance));
      return;
    }
    const [left, right] = splitBezier(piece, 0.5);
    visit(left, depth + 1);
    visit(right, depth + 1);
  };
  visit(points, 0);
  return paths;
}

/**
 * The lit pixels whose centres lie more than `limit` pixels from the curve,
 * given as polylines far finer than a pixel (the curve near the raster): a
 * pixel any rasteriser of the curve itself might light is within ½ pixel
 * across of it, so these are pixels the curve would never light.
 */
export function farPixels(
  lit: Map<string, Pixel>,
  curve: readonly (readonly Point[])[],
  zoom: number,
  limit = 1,
): Pixel[] {
  const paths = curve.map((path) => path.map((p) => toPixel(p, zoom)));
  const far: Pixel[] = [];
  for (const pixel of lit.values()) {
    const centre = [pixel.i, pixel.j];
    let nearest = Infinity;
    for (const path of paths) {
      for (let k = 0; k + 1 < path.length && nearest > limit; k++) {
        const q = nearestOnSegment(centre, path[k], path[k + 1]);
        nearest = Math.min(nearest, Math.hypot(q[0] - centre[0], q[1] - centre[1]));
      }
    }
    if (nearest > limit) far.push(pixel);
  }
  return far;
}
