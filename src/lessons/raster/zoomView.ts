import { type Point, flattenBezier } from '../../math';
import type { Polyline } from './polyline';
import {
  type Pixel,
  type RasterSize,
  curveNear,
  farPixels,
  rasterSize,
  rasterizePolyline,
  windowOf,
} from './raster';
import { RASTER_HEIGHT, RASTER_WIDTH } from './state';

/**
 * The zoom scene at one zoom: a screen of 32 × 24 pixels looking at the
 * curve magnified, centred where the uniform polyline strays most.
 */
export interface ZoomView {
  /** The window: 32 × 24 pixels of size 1 / zoom. */
  size: RasterSize;
  /** The whole raster the curve would fill at this zoom. */
  full: RasterSize;
  uniformPixels: Map<string, Pixel>;
  /** Adaptive flattening's vertices to the tolerance at this zoom. */
  adaptive: Point[];
  /** Lit pixels more than a pixel from the curve: pixels the curve itself would never light. */
  uniformFar: Pixel[];
  adaptiveFar: Pixel[];
}

/** The zoom scene's presses: ×½, ×1, ×2, ×4, ×8. */
export const ZOOM_PRESSES = 5;

/** The zoom at the zoom scene's press 1 … 5: ×½, ×1, ×2, ×4, ×8. */
export const zoomAt = (press: number) => 2 ** (Math.min(ZOOM_PRESSES, Math.max(1, press)) - 2);

/** A zoom as the captions write it: ×½, ×1, ×2, … */
export const zoomWords = (zoom: number) => (zoom === 0.5 ? '½' : String(zoom));

/** The curve `points` at `zoom`, tolerance `tolerance` pixels, against its uniform polyline. */
export function zoomView(
  points: readonly Point[],
  uniform: Polyline,
  tolerance: number,
  zoom: number,
): ZoomView {
  const { point, foot } = uniform.deviation;
  const size: RasterSize = {
    zoom,
    left: Math.round(((point[0] + foot[0]) / 2) * zoom - RASTER_WIDTH / 2),
    bottom: Math.round(((point[1] + foot[1]) / 2) * zoom - RASTER_HEIGHT / 2),
    width: RASTER_WIDTH,
    height: RASTER_HEIGHT,
  };
  const adaptive = flattenBezier(points, tolerance / zoom);
  // The curve within 1/50 of a pixel, where it passes the window (and 2 pixels round it).
  const curve = curveNear(points, windowOf(size), 2 / zoom, 0.02 / zoom);
  const uniformPixels = rasterizePolyline(uniform.points, size);
  return {
    size,
    full: rasterSize(zoom),
    uniformPixels,
    adaptive,
    uniformFar: farPixels(uniformPixels, curve, zoom),
    adaptiveFar: farPixels(rasterizePolyline(adaptive, size), curve, zoom),
  };
}
