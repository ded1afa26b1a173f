/**
 * The lesson's heavy work, each part kept while the fields it reads are the
 * same (memoOn): a clicker press, which changes only the step, samples and
 * flattens nothing again, and lights no pixel again (except the zoom scene,
 * whose zoom is its step).
 */
import { type FlatteningNode, onOneSpot, sampleBezier, uniformParameters } from '../../math';
import { memoOn } from '../../kit/memoOn';
import {
  type Polyline,
  type SameGap,
  adaptiveAt,
  gapFunction,
  polyline,
  sameGap,
} from './polyline';
import {
  type LineSteps,
  type Pixel,
  type RasterSize,
  coveragePolyline,
  lineSteps,
  rasterSize,
  rasterizePolyline,
  segmentPixels,
} from './raster';
import { type RasterState, segmentsOf } from './state';
import { type ZoomView, zoomView } from './zoomView';

type CurveFields = Pick<RasterState, 'points'>;
type UniformFields = Pick<RasterState, 'points' | 'uniformSegments'>;
type FlatteningFields = Pick<RasterState, 'points' | 'tolerance' | 'zoom'>;
type SegmentFields = FlatteningFields & Pick<RasterState, 'steppedSegment'>;
type ZoomFields = UniformFields & Pick<RasterState, 'tolerance'> & { factor: number };

/** The curve itself: sampled, and whether it is one point. */
export const curveOf = memoOn<CurveFields, 'points', Curve>(['points'], ({ points }) => ({
  oneSpot: onOneSpot(points),
  degree: points.length - 1,
  curve: sampleBezier(points, 400),
}));

export interface Curve {
  /** All control points on one spot: the curve is that point (the figure says so). */
  oneSpot: boolean;
  degree: number;
  curve: Float64Array;
}

/** n uniform segments (the slider). */
export const uniformOf = memoOn<UniformFields, keyof UniformFields, Polyline>(
  ['points', 'uniformSegments'],
  (fields) => polyline(fields.points, uniformParameters(segmentsOf(fields))),
);

/** The gap between the curve and the uniform polyline over t, as (t, gap) pairs (plot scene). */
export const gapsOf = memoOn<UniformFields, keyof UniformFields, Float64Array>(
  ['points', 'uniformSegments'],
  (fields) => gapFunction(fields.points, uniformOf(fields)),
);

export interface Flattening {
  /** The tolerance in units of the control points: τ pixels of size 1 / zoom. */
  tolerance: number;
  /** Every piece the adaptive flattening looked at, in visiting order. */
  tree: FlatteningNode[];
  /** flattenBezier's polyline at the tolerance, with its leaves' parameters. */
  adaptive: Polyline;
  /** Uniform segments the flatness bound asks for: ⌈√(n(n−1)·max‖Δ²P‖ / (8τ))⌉. */
  boundCount: number;
  /** The raster of the pixel scenes. */
  size: RasterSize;
  /** The adaptive polyline's pixels (line rasteriser). */
  pixels: Map<string, Pixel>;
}

/** Adaptive flattening to τ pixels at the zoom, and the pixels its polyline lights. */
export const flatteningOf = memoOn<FlatteningFields, keyof FlatteningFields, Flattening>(
  ['points', 'tolerance', 'zoom'],
  ({ points, tolerance: pixels, zoom }) => {
    const tolerance = pixels / zoom;
    const { tree, adaptive } = adaptiveAt(points, tolerance);
    // The root's flatness is n(n−1)/8 · max‖Δ²P‖ of the whole curve.
    const boundCount = Math.max(1, Math.ceil(Math.sqrt(tree[0].flatness / tolerance)));
    const size = rasterSize(zoom);
    return {
      tolerance,
      tree,
      adaptive,
      boundCount,
      size,
      pixels: rasterizePolyline(adaptive.points, size),
    };
  },
);

/**
 * Uniform sampling planned without measuring (compare scene): the
 * ⌈√(n(n−1)·max‖Δ²P‖ / (8τ))⌉ segments of the flatness bound, the polyline
 * the figure draws and the caption counts.
 */
export const boundOf = memoOn<FlatteningFields, keyof FlatteningFields, Polyline>(
  ['points', 'tolerance', 'zoom'],
  (fields) => polyline(fields.points, uniformParameters(flatteningOf(fields).boundCount)),
);

/** Uniform sampling with the adaptive polyline's gap (compare scene). */
export const sameGapOf = memoOn<FlatteningFields, keyof FlatteningFields, SameGap>(
  ['points', 'tolerance', 'zoom'],
  (fields) => sameGap(fields.points, flatteningOf(fields).adaptive.deviation.distance),
);

export interface SteppedSegment {
  /** The segment stepped pixel by pixel (index into the adaptive polyline's segments). */
  segment: number;
  line: LineSteps;
}

/** The segment of the adaptive polyline stepped pixel by pixel (the link's one, if it exists). */
export const steppedOf = memoOn<SegmentFields, keyof SegmentFields, SteppedSegment>(
  ['points', 'tolerance', 'zoom', 'steppedSegment'],
  (fields) => {
    const { adaptive } = flatteningOf(fields);
    const segment = Math.min(fields.steppedSegment, adaptive.points.length - 2);
    const line = lineSteps(adaptive.points[segment], adaptive.points[segment + 1], fields.zoom);
    return { segment, line };
  },
);

export interface Coverage {
  /** The adaptive polyline anti-aliased. */
  coverage: Map<string, Pixel>;
  /** The stepped segment's pixels with their coverage (magnified). */
  segmentCoverage: Pixel[];
}

/** The coverage scene's shades: the whole polyline's, and the stepped segment's. */
export const coverageOf = memoOn<SegmentFields, keyof SegmentFields, Coverage>(
  ['points', 'tolerance', 'zoom', 'steppedSegment'],
  (fields) => {
    const { adaptive, size } = flatteningOf(fields);
    const { segment } = steppedOf(fields);
    return {
      coverage: coveragePolyline(adaptive.points, size),
      segmentCoverage: segmentPixels(adaptive.points[segment], adaptive.points[segment + 1], size),
    };
  },
);

/** The zoom scene at zoom `factor` (its step): the window, its pixels, the pixels wrong. */
export const zoomViewOf = memoOn<ZoomFields, keyof ZoomFields, ZoomView>(
  ['points', 'uniformSegments', 'tolerance', 'factor'],
  (fields) => zoomView(fields.points, uniformOf(fields), fields.tolerance, fields.factor),
);
