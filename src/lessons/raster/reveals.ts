import type { Revealed } from '../../kit/script';
import { flatteningOf, steppedOf } from './geometry';
import type { RasterState } from './state';

/**
 * What the steps reveal, by name, scene by scene: the figures, the panel and
 * the captions ask for these.
 */
export type Reveal =
  // Plot the curve: the given points, P(k/n), the segments, the curve, the largest gap.
  | 'points'
  | 'samples'
  | 'polyline'
  | 'curve'
  | 'gap'
  // Uniform or adaptive: the curve twice, uniform, adaptive, uniform with the same gap, the bound.
  | 'twice'
  | 'uniform'
  | 'adaptive'
  | 'sameGap'
  | 'bound'
  // Flatten by subdivision: the question, the pieces visited (in chunks), done.
  | 'question'
  | 'pieces'
  | 'done'
  // Segments to pixels: the raster, the segment's end pixels, its pixels (in chunks), every segment.
  | 'raster'
  | 'ends'
  | 'pixels'
  | 'everySegment'
  // Anti-aliasing: the strip, each pixel's share, the whole curve in shades.
  | 'strip'
  | 'shares'
  | 'shades'
  // Zoom in, zoom out: one press per zoom.
  | 'zoom';

/** Pixel steps of one segment are shown in at most this many clicks. */
export const LINE_CHUNKS = 12;
/** The pieces of the flattening are shown in at most this many clicks (with the last, "done"). */
export const TREE_CHUNKS = 20;

/** Presses that visit pieces of the flattening before "done" (which shows the rest). */
export const piecePresses = (state: RasterState) =>
  Math.min(TREE_CHUNKS, flatteningOf(state).tree.length) - 1;

/** Presses that light the stepped segment's pixels, a chunk at a time. */
export const pixelPresses = (state: RasterState) =>
  Math.min(LINE_CHUNKS, steppedOf(state).line.pixels.length);

/** Pieces of the flattening (of `pieces`) visited by press `press` of `presses`: spread evenly. */
export const piecesAt = (pieces: number, press: number, presses: number) =>
  Math.ceil((pieces * press) / presses);

/** How many pieces of the flattening (of `pieces`) are visited so far. */
export function piecesShown(pieces: number, shown: Revealed<Reveal>): number {
  if (shown.has('done')) return pieces;
  // The presses up to "done" (the last step) spread the visits evenly.
  return shown.has('pieces') ? piecesAt(pieces, shown.count('pieces'), shown.lastStep) : 0;
}

/** Pixels (of `total`) of the stepped segment lit by its `press`-th chunk. */
export const pixelsAt = (total: number, press: number) =>
  Math.min(total, Math.ceil((total * press) / Math.min(LINE_CHUNKS, total)));

/** How many pixels (of `total`) of the stepped segment are lit so far. */
export const pixelsShown = (total: number, shown: Revealed<Reveal>) =>
  shown.has('everySegment') ? total : pixelsAt(total, shown.count('pixels'));
