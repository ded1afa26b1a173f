import { choice, int, stepField, linkKey, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';

/** What the figures show: one per scene of the script (`x=pixels` in the link). */
export type View = 'plot' | 'compare' | 'subdivide' | 'pixels' | 'coverage' | 'zoom';

export const VIEWS: readonly View[] = [
  'plot',
  'compare',
  'subdivide',
  'pixels',
  'coverage',
  'zoom',
];

/** Everything the raster lesson shows, and all of it goes in the link (its key beside each). */
export interface RasterState {
  /** The scene the figures show (`x`). */
  view: View;
  /** Control points, in pixels of the coarse raster (zoom 1: 32 × 24 pixels) (`p`). */
  points: Point[];
  /** Segments of uniform sampling (the slider n; rounded to a whole number) (`n`). */
  uniformSegments: number;
  /** Tolerance τ of adaptive flattening, in pixels (`tol`). */
  tolerance: number;
  /** Zoom: raster pixels per unit of the control points (1: 32 × 24 pixels) (`z`). */
  zoom: number;
  /** The segment of the polyline rasterised pixel by pixel (0 is the first) (`seg`). */
  steppedSegment: number;
  /** The step of the current scene. */
  step: number;
}

export const MAX_POINTS = 10;
export const MAX_SEGMENTS = 64;
/** The raster at zoom 1, in pixels. */
export const RASTER_WIDTH = 32;
export const RASTER_HEIGHT = 24;
export const ZOOM_MIN = 0.25;
export const ZOOM_MAX = 16;

/**
 * A long straight run that ends in a hairpin (degree 6): uniform sampling
 * spends as many segments on the straight as on the bend, adaptive flattening
 * spends them where the curve bends.
 */
export const HAIRPIN: Point[] = [
  [2, 3],
  [9, 3],
  [16, 3],
  [23, 3],
  [30, 3],
  [31, 21],
  [18, 21],
];

// The link's keys and their order are the lesson's first ones: every link opens the same picture.
export const schema: Schema<RasterState> = {
  view: linkKey(choice({ default: 'plot', values: VIEWS }), 'x'),
  points: linkKey(points({ default: HAIRPIN, min: 2, max: MAX_POINTS }), 'p'),
  uniformSegments: linkKey(number({ default: 6, min: 1, max: MAX_SEGMENTS }), 'n'),
  tolerance: linkKey(number({ default: 0.5, min: 0.05, max: 4 }), 'tol'),
  zoom: linkKey(number({ default: 1, min: ZOOM_MIN, max: ZOOM_MAX }), 'z'),
  steppedSegment: linkKey(int({ default: 0, min: 0, max: 4096 }), 'seg'),
  step: stepField(),
};

/** The number of uniform segments the slider's value stands for. */
export const segmentsOf = (state: Pick<RasterState, 'uniformSegments'>) =>
  Math.min(MAX_SEGMENTS, Math.max(1, Math.round(state.uniformSegments)));
