import type { Point } from '../../math';
import type { Revealed } from '../../kit/script';
import {
  type Curve,
  type Flattening,
  type SteppedSegment,
  boundOf,
  coverageOf,
  curveOf,
  flatteningOf,
  gapsOf,
  sameGapOf,
  steppedOf,
  uniformOf,
  zoomViewOf,
} from './geometry';
import type { Polyline, SameGap } from './polyline';
import { type Pixel, lineSteps } from './raster';
import { type Reveal, piecesShown, pixelsShown } from './reveals';
import type { RasterState } from './state';
import { type ZoomView, zoomAt } from './zoomView';

export { SAME_ERROR_MAX, type Polyline } from './polyline';

/** Everything the figures and the panel show, computed once per state. */
export interface RasterModel extends Curve, Flattening, SteppedSegment, SameGap {
  state: RasterState;
  /** What the steps so far reveal (names in reveals.ts). */
  shown: Revealed<Reveal>;
  /** n uniform segments (the slider). */
  uniform: Polyline;
  /** Uniform sampling planned by the flatness bound: boundCount segments, with the gap they leave. */
  bound: Polyline;
  /** The adaptive polyline anti-aliased (coverage scene). */
  coverage: Map<string, Pixel> | null;
  /** The stepped segment's pixels with their coverage (coverage scene, magnified). */
  segmentCoverage: Pixel[] | null;
  zoom: ZoomView | null;
  /** The gap between the curve and the uniform polyline over t, as (t, gap) pairs (plot scene). */
  gaps: Float64Array | null;
  /** Pieces of the flattening visited so far (subdivide scene). */
  piecesShown: number;
  /** Pixels of the stepped segment lit so far (pixel scene). */
  pixelsShown: number;
}

/** The model of a state, with what its step reveals; the heavy parts are kept across steps. */
export function derive(state: RasterState, shown: Revealed<Reveal>): RasterModel {
  const flattening = flatteningOf(state);
  const stepped = steppedOf(state);
  const { view } = state;
  return {
    state,
    shown,
    ...curveOf(state),
    ...flattening,
    ...stepped,
    uniform: uniformOf(state),
    bound: boundOf(state),
    ...(view === 'compare' ? sameGapOf(state) : { sameError: null, sameErrorBeyond: false }),
    ...(view === 'coverage' ? coverageOf(state) : { coverage: null, segmentCoverage: null }),
    // The zoom scene's zoom is its step: ×½ at the first press, doubling at each.
    zoom: view === 'zoom' ? zoomViewOf({ ...state, factor: zoomAt(shown.count('zoom')) }) : null,
    gaps: view === 'plot' ? gapsOf(state) : null,
    piecesShown: piecesShown(flattening.tree.length, shown),
    pixelsShown: pixelsShown(stepped.line.pixels.length, shown),
  };
}

/**
 * The segment worth stepping through pixel by pixel: the one with the most
 * steps where the ideal line falls between two pixels (a level run or an
 * exact diagonal decides nothing), the longer of two that tie.
 */
export function instructiveSegment(points: readonly Point[], zoom: number): number {
  let best = 0;
  let score = -1;
  for (let k = 0; k + 1 < points.length; k++) {
    const { ideal } = lineSteps(points[k], points[k + 1], zoom);
    const decisions = ideal.filter((v) => Math.abs(v - Math.round(v)) > 1e-9).length;
    const value = decisions * 1e6 + ideal.length;
    if (value > score) {
      score = value;
      best = k;
    }
  }
  return best;
}
