/**
 * The raster lesson's exercises: where a curve strays furthest from the one
 * segment drawn for it, the next pixel a line rasteriser lights, the flatness
 * that adaptive flattening tests, and a curve shaped to flatten into exactly
 * two segments.
 */
import type { ExerciseSpec } from '../../kit/exercise';
import { farthestPoint } from './farthestPointExercise';
import { flatness } from './flatnessExercise';
import { nextPixel } from './nextPixelExercise';
import type { RasterState } from './state';
import { twoSegments } from './twoSegmentsExercise';

/** The lesson's exercises, in the order the practice card lists them. */
export const exercises: readonly ExerciseSpec<RasterState>[] = [
  farthestPoint,
  nextPixel,
  flatness,
  twoSegments,
];
