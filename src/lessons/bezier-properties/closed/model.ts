import { memoOn } from '../../../kit/memoOn';
import { boundsOf, diagonal } from '../../../render/projection';
import {
  type Point,
  bezierDerivative,
  bezierPoint,
  norm,
  scale,
  add,
  subtract,
  signedAngle,
} from '../../../math';
import { type ExperimentBase, sampleCurve } from '../curve';
import type { PropertiesState } from '../state';

/**
 * The end tangents are drawn at this fraction of their true length, but never
 * longer than ARROW_REACH times the size of the control polygon: N(P1 − P0)
 * of a degree-5 curve is five legs long and would leave the figure, or make
 * "fit view" frame the arrows instead of the curve.
 */
export const ARROW_SCALE = 0.35;
export const ARROW_REACH = 0.3;

export interface ClosedModel extends ExperimentBase {
  kind: 'closed';
  /** Degree N (the polygon P0 … PN−1, P0). */
  n: number;
  curve: Float64Array;
  point: Point;
  /** The arrows at P0: the leaving tangent from it, the arriving one into it. */
  leaving: [Point, Point];
  arriving: [Point, Point];
  /** The angle between arriving and leaving tangent (degrees, ≥ 0); null if one of them is zero. */
  corner: number | null;
  /** Within half a degree: smooth at P0. */
  smooth: boolean;
}

export const deriveClosed = memoOn<PropertiesState, 'points' | 't', ClosedModel>(
  ['points', 't'],
  ({ points, t }) => {
    const p0 = points[0];
    const controls = [...points, p0];
    const hodograph = bezierDerivative(controls);
    const start = hodograph[0];
    const end = hodograph[hodograph.length - 1];
    const measurable = norm(start) !== 0 && norm(end) !== 0;
    const size = diagonal(boundsOf(points));
    const arrow = (v: Point) =>
      scale(v, norm(v) === 0 ? 0 : Math.min(ARROW_SCALE, (ARROW_REACH * size) / norm(v)));
    const leaving: [Point, Point] = [p0, add(p0, arrow(start))];
    const arriving: [Point, Point] = [subtract(p0, arrow(end)), p0];
    const corner = measurable ? Math.abs((signedAngle(start, end) * 180) / Math.PI) : null;
    return {
      kind: 'closed',
      controls,
      // The arrows are in the view, and short enough not to set its size.
      extra: [leaving[1], arriving[0]],
      n: controls.length - 1,
      curve: sampleCurve(controls),
      point: bezierPoint(controls, t),
      leaving,
      arriving,
      corner,
      smooth: corner !== null && corner < 0.5,
    };
  },
);
