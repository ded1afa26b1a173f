import type { Point } from '../../math';
import type { Dataset } from './model';

// The lesson's three datasets as plain text files, for a student's own
// computeSplineC1 and computeSplineC2: one point a line, x then y.

/** Each dataset's file name, after the practical's names: infinity, spiral, semi. */
export const DATASET_FILES: Record<Dataset, string> = {
  infinity: 'infinity.txt',
  spiral: 'spiral.txt',
  semicircle: 'semi.txt',
};

/** "x y" per line, every number in full (what the lesson draws, to the last digit), a final newline. */
export const datasetText = (points: readonly Point[]) =>
  points.map(([x, y]) => `${x} ${y}\n`).join('');
