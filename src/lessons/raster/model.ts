import {
  type ChordDeviation,
  type FlatteningNode,
  type Point,
  bezierPoint,
  chordDeviation,
  nearestOnSegment,
  onOneSpot,
  flattenBezier,
  flatteningTree,
  sampleBezier,
  uniformCountWithin,
  uniformParameters,
} from '../../math';
import {
  type LineSteps,
  type Pixel,
  type RasterSize,
  coveragePolyline,
  curveNear,
  farPixels,
  lineSteps,
  rasterizePolyline,
  segmentPixels,
} from './raster';
import { RASTER_HEIGHT, RASTER_WIDTH, type RasterState, segmentsOf } from './state';

/** A polyline drawn for the curve: its vertices P(tk) and how far the curve strays from it. */
export interface Polyline {
  parameters: number[];
  points: Point[];
  /** In units of the control points (pixels at zoom 1). */
  deviation: ChordDeviation;
}

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

export interface RasterModel {
  state: RasterState;
  /** All control points on one spot: the curve is that point (the figure says so). */
  oneSpot: boolean;
  degree: number;
  curve: Float64Array;
  /** n uniform segments (the slider). */
  uniform: Polyline;
  /** The tolerance in units of the control points: tol pixels of size 1 / zoom. */
  tolerance: number;
  /** Every piece the adaptive flattening looked at, in visiting order. */
  tree: FlatteningNode[];
  /** flattenBezier's polyline at the tolerance, with its leaves' parameters. */
  adaptive: Polyline;
  /** Uniform segments the flatness bound asks for: ⌈√(n(n−1)·max‖Δ²P‖ / (8τ))⌉. */
  boundCount: number;
  /**
   * Fewest uniform segments with at most the adaptive polyline's deviation
   * (compare scene; null elsewhere, or when that is more than SAME_ERROR_MAX).
   */
  sameError: Polyline | null;
  /** In the compare scene: uniform sampling would need more than SAME_ERROR_MAX segments (not drawn). */
  sameErrorBeyond: boolean;
  /** The raster of the pixel scenes. */
  size: RasterSize;
  /** The adaptive polyline's pixels (line rasteriser). */
  pixels: Map<string, Pixel>;
  /** The segment stepped pixel by pixel (index into the adaptive polyline's segments). */
  segment: number;
  line: LineSteps;
  /** The adaptive polyline anti-aliased (coverage scene). */
  coverage: Map<string, Pixel> | null;
  /** The stepped segment's pixels with their coverage (coverage scene, magnified). */
  segmentCoverage: Pixel[] | null;
  zoom: ZoomView | null;
  /** The gap between the curve and the uniform polyline over t, as (t, gap) pairs (plot scene). */
  gaps: Float64Array | null;
}

/** Uniform segments the compare scene searches up to; past it the lesson says "more than". */
export const SAME_ERROR_MAX = 512;

/** Samples per piece of the gap function. */
const GAP_SAMPLES = 24;

/** (t, distance from P(t) to the chord of its piece) over every piece. */
function gapFunction(points: readonly Point[], line: Polyline): Float64Array {
  const pieces = line.parameters.length - 1;
  const gaps = new Float64Array(2 * (pieces * GAP_SAMPLES + 1));
  let at = 0;
  for (let k = 0; k < pieces; k++) {
    const [t0, t1] = [line.parameters[k], line.parameters[k + 1]];
    for (let s = k === 0 ? 0 : 1; s <= GAP_SAMPLES; s++) {
      const t = t0 + ((t1 - t0) * s) / GAP_SAMPLES;
      const p = bezierPoint(points, t);
      const q = nearestOnSegment(p, line.points[k], line.points[k + 1]);
      gaps[at++] = t;
      gaps[at++] = Math.hypot(p[0] - q[0], p[1] - q[1]);
    }
  }
  return gaps;
}

/** The zoom scene's zoom at step k: ×½, ×1, ×2, ×4, ×8. */
export const zoomAtStep = (k: number) => 2 ** (Math.min(4, Math.max(0, k)) - 1);

function polyline(points: readonly Point[], parameters: number[]): Polyline {
  return {
    parameters,
    points: parameters.map((t) => bezierPoint(points, t)),
    deviation: chordDeviation(points, parameters),
  };
}

/** The flattening's leaves as parameters t0 = 0 < t1 < … < tm = 1. */
const leafParameters = (tree: readonly FlatteningNode[]) => [
  0,
  ...tree.filter((node) => !node.split).map((node) => node.t1),
];

function adaptiveAt(points: readonly Point[], tolerance: number) {
  const tree = flatteningTree(points, tolerance);
  const adaptive = polyline(points, leafParameters(tree));
  // The drawn vertices are the leaves' end points: flattenBezier's polyline,
  // point for point, without flattening a second time.
  const leaves = tree.filter((node) => !node.split);
  adaptive.points = [
    tree[0].points[0],
    ...leaves.map((node) => node.points[node.points.length - 1]),
  ];
  return { tree, adaptive };
}

const rasterSize = (zoom: number): RasterSize => ({
  zoom,
  left: 0,
  bottom: 0,
  width: Math.ceil(RASTER_WIDTH * zoom),
  height: Math.ceil(RASTER_HEIGHT * zoom),
});

function zoomView(state: RasterState, uniform: Polyline): ZoomView {
  const zoom = zoomAtStep(state.step);
  const { point, foot } = uniform.deviation;
  const size: RasterSize = {
    zoom,
    left: Math.round(((point[0] + foot[0]) / 2) * zoom - RASTER_WIDTH / 2),
    bottom: Math.round(((point[1] + foot[1]) / 2) * zoom - RASTER_HEIGHT / 2),
    width: RASTER_WIDTH,
    height: RASTER_HEIGHT,
  };
  const adaptive = flattenBezier(state.p, state.tol / zoom);
  // The curve within 1/50 of a pixel, where it passes the window (and 2 pixels round it).
  const window = {
    minX: size.left / zoom,
    minY: size.bottom / zoom,
    maxX: (size.left + size.width) / zoom,
    maxY: (size.bottom + size.height) / zoom,
  };
  const curve = curveNear(state.p, window, 2 / zoom, 0.02 / zoom);
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

const cache = new WeakMap<RasterState, RasterModel>();

export function derive(state: RasterState): RasterModel {
  const cached = cache.get(state);
  if (cached) return cached;
  const degree = state.p.length - 1;
  const uniform = polyline(state.p, uniformParameters(segmentsOf(state)));
  const tolerance = state.tol / state.z;
  const { tree, adaptive } = adaptiveAt(state.p, tolerance);
  // The root's flatness is n(n−1)/8 · max‖Δ²P‖ of the whole curve.
  const boundCount = Math.max(1, Math.ceil(Math.sqrt(tree[0].flatness / tolerance)));
  let sameError: Polyline | null = null;
  let sameErrorBeyond = false;
  if (state.x === 'compare') {
    const count = uniformCountWithin(state.p, adaptive.deviation.distance, SAME_ERROR_MAX);
    if (count > SAME_ERROR_MAX) sameErrorBeyond = true;
    else sameError = polyline(state.p, uniformParameters(count));
  }
  const size = rasterSize(state.z);
  const segment = Math.min(state.seg, adaptive.points.length - 2);
  const model: RasterModel = {
    state,
    oneSpot: onOneSpot(state.p),
    degree,
    curve: sampleBezier(state.p, 400),
    uniform,
    tolerance,
    tree,
    adaptive,
    boundCount,
    sameError,
    sameErrorBeyond,
    size,
    pixels: rasterizePolyline(adaptive.points, size),
    segment,
    line: lineSteps(adaptive.points[segment], adaptive.points[segment + 1], state.z),
    coverage: state.x === 'coverage' ? coveragePolyline(adaptive.points, size) : null,
    segmentCoverage:
      state.x === 'coverage'
        ? segmentPixels(adaptive.points[segment], adaptive.points[segment + 1], size)
        : null,
    zoom: state.x === 'zoom' ? zoomView(state, uniform) : null,
    gaps: state.x === 'plot' ? gapFunction(state.p, uniform) : null,
  };
  cache.set(state, model);
  return model;
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
