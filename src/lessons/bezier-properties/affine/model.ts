import { memoOn } from '../../../kit/memoOn';
import {
  type Point,
  bezierPoint,
  homogeneousWeight,
  projectiveMap,
  sampleBezier,
  sampleRationalBezier,
  sampledDeviation,
} from '../../../math';
import { type ExperimentBase, sampleCurve, samplesFor } from '../curve';
import type { PropertiesState } from '../state';
import { LINEAR, mapMatrix } from './maps';

/** Both images of the curve under the map. */
export interface MapImages {
  ok: true;
  /** The mapped control points and the curve they make. */
  mappedControls: Point[];
  curveOfMapped: Float64Array;
  /** The map of the curve itself (its samples mapped). */
  mappedCurve: Float64Array;
  /** Largest distance between the two images at equal t, and where. */
  distance: number;
  at: number;
  /** At t: the curve of the mapped points (dot), and the map of P(t) (ring). */
  onMapped: Point;
  imageOfPoint: Point;
  /** Where each image is named: its middle sample. */
  middles: { mappedCurve: Point; curveOfMapped: Point };
  /** The w the map gives each control point: all 1 for an affine map. */
  weights: number[];
  /** The smallest and largest of them. */
  weightRange: [number, number];
  affine: boolean;
  /** Largest distance from the map of the curve to the rational Bézier curve of the mapped points, weighted by w; null when affine. */
  rationalDistance: number | null;
}

export interface AffineModel extends ExperimentBase {
  kind: 'affine';
  curve: Float64Array;
  point: Point;
  /** The map about the origin (as printed) and as applied (about the centre, shifted). */
  linear: number[][];
  matrix: number[][];
  /** The images, or why there are none (a control point on or beyond the vanishing line). */
  images: MapImages | { ok: false; why: string };
}

const middleOf = (samples: Float64Array): Point => {
  const middle = 2 * Math.floor(samples.length / 4);
  return [samples[middle], samples[middle + 1]];
};

function mapImages(
  matrix: number[][],
  p: Point[],
  curve: Float64Array,
  point: Point,
  t: number,
): MapImages {
  const count = samplesFor(p.length - 1);
  const curvePoints: Point[] = [];
  for (let k = 0; k < curve.length; k += 2) curvePoints.push([curve[k], curve[k + 1]]);
  const mappedControls = projectiveMap(matrix, p);
  const mappedCurve = Float64Array.from(projectiveMap(matrix, curvePoints).flat());
  const curveOfMapped = sampleBezier(mappedControls, count);
  const { at, distance } = sampledDeviation(mappedCurve, curveOfMapped);
  const weights = p.map((q) => homogeneousWeight(matrix, q));
  const affine = weights.every((w) => w === 1);
  return {
    ok: true,
    mappedControls,
    curveOfMapped,
    mappedCurve,
    distance,
    at: at / count,
    onMapped: bezierPoint(mappedControls, t),
    imageOfPoint: projectiveMap(matrix, [point])[0],
    middles: { mappedCurve: middleOf(mappedCurve), curveOfMapped: middleOf(curveOfMapped) },
    weights,
    weightRange: [Math.min(...weights), Math.max(...weights)],
    affine,
    // Giving each mapped point its w as a weight repairs the perspective map.
    rationalDistance: affine
      ? null
      : sampledDeviation(mappedCurve, sampleRationalBezier(mappedControls, weights, count))
          .distance,
  };
}

export const deriveAffine = memoOn<PropertiesState, 'points' | 't' | 'map', AffineModel>(
  ['points', 't', 'map'],
  ({ points: controls, t, map }) => {
    const matrix = mapMatrix(map);
    const curve = sampleCurve(controls);
    const point = bezierPoint(controls, t);
    let images: AffineModel['images'];
    try {
      images = mapImages(matrix, controls, curve, point, t);
    } catch (error) {
      images = { ok: false, why: error instanceof Error ? error.message : String(error) };
    }
    return {
      kind: 'affine',
      controls,
      extra: images.ok ? images.mappedControls : [],
      curve,
      point,
      linear: LINEAR[map],
      matrix,
      images,
    };
  },
);
