import { memoOn } from '../../../kit/memoOn';
import {
  type Point,
  bezierPoint,
  convexHull,
  convexHullContains,
  sampleBezier,
} from '../../../math';
import type { ExperimentBase } from '../curve';
import type { PropertiesState } from '../state';

/** The curve is checked (and drawn) at this many segments: 401 samples. */
const SAMPLES = 400;

export interface HullModel extends ExperimentBase {
  kind: 'hull';
  curve: Float64Array;
  point: Point;
  /** Corners of the convex hull of the control points, anticlockwise: 1 if they coincide, 2 if collinear. */
  hull: Point[];
  /** How many of the `total` curve samples lie in the hull. */
  inside: number;
  total: number;
}

export const deriveHull = memoOn<PropertiesState, 'points' | 't', HullModel>(
  ['points', 't'],
  ({ points: controls, t }) => {
    const hull = convexHull(controls);
    const curve = sampleBezier(controls, SAMPLES);
    // Rounding may put a sample a hair outside an edge: allow a tolerance relative to the size.
    const tolerance = 1e-9 * Math.max(1, ...controls.flat().map(Math.abs));
    let inside = 0;
    for (let k = 0; k < curve.length; k += 2) {
      if (convexHullContains(hull, [curve[k], curve[k + 1]], tolerance)) inside++;
    }
    return {
      kind: 'hull',
      controls,
      extra: [],
      curve,
      point: bezierPoint(controls, t),
      hull,
      inside,
      total: SAMPLES + 1,
    };
  },
);
