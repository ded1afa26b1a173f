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

/** The end tangents are drawn at this fraction of their true length. */
export const ARROW_SCALE = 0.35;

export interface ClosedModel extends ExperimentBase {
  x: 'closed';
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

export function deriveClosed(state: PropertiesState): ClosedModel {
  const p0 = state.p[0];
  const controls = [...state.p, p0];
  const hodograph = bezierDerivative(controls);
  const start = hodograph[0];
  const end = hodograph[hodograph.length - 1];
  const measurable = norm(start) !== 0 && norm(end) !== 0;
  const corner = measurable ? Math.abs((signedAngle(start, end) * 180) / Math.PI) : null;
  return {
    x: 'closed',
    controls,
    extra: [],
    n: controls.length - 1,
    curve: sampleCurve(controls),
    point: bezierPoint(controls, state.t),
    leaving: [p0, add(p0, scale(start, ARROW_SCALE))],
    arriving: [subtract(p0, scale(end, ARROW_SCALE)), p0],
    corner,
    smooth: corner !== null && corner < 0.5,
  };
}
