import { memoOn } from '../../../kit/memoOn';
import {
  type Point,
  add,
  bezierDerivative,
  bezierPoint,
  norm,
  scale,
  subtract,
} from '../../../math';
import { type ExperimentBase, sampleCurve } from '../curve';
import type { PropertiesState } from '../state';

/**
 * Tangent arrows are drawn at half their true length: at full length (three
 * legs of a cubic's polygon) they shrink the curve to a corner of the figure,
 * while half still reaches past P1, showing the speed is N times the leg.
 */
export const ARROW_SCALE = 0.5;

/** A tangent vector at a point of the curve, and the tip of its (half-length) arrow. */
export interface Tangent {
  from: Point;
  vector: Point;
  tip: Point;
  /** |vector|. */
  speed: number;
}

export interface EndsModel extends ExperimentBase {
  kind: 'ends';
  /** Degree N. */
  n: number;
  curve: Float64Array;
  /** P(t). */
  point: Point;
  /** P′(0) at P0, P′(1) at PN and P′(t) at P(t): the hodograph's end points and its value at t. */
  tangents: [Tangent, Tangent, Tangent];
  /** P1 sits on P0: the curve starts with zero speed. */
  stillAtStart: boolean;
  /** PN−1 sits on PN: the curve arrives with zero speed. */
  stillAtEnd: boolean;
}

const tangent = (from: Point, vector: Point): Tangent => ({
  from,
  vector,
  tip: add(from, scale(vector, ARROW_SCALE)),
  speed: norm(vector),
});

export const deriveEnds = memoOn<PropertiesState, 'points' | 't', EndsModel>(
  ['points', 't'],
  ({ points: controls, t }) => {
    const n = controls.length - 1;
    const hodograph = bezierDerivative(controls);
    const point = bezierPoint(controls, t);
    const tangents: EndsModel['tangents'] = [
      tangent(controls[0], hodograph[0]),
      tangent(controls[n], hodograph[hodograph.length - 1]),
      tangent(point, bezierPoint(hodograph, t)),
    ];
    return {
      kind: 'ends',
      controls,
      extra: tangents.map((arrow) => arrow.tip),
      n,
      curve: sampleCurve(controls),
      point,
      tangents,
      stillAtStart: norm(subtract(controls[1], controls[0])) === 0,
      stillAtEnd: norm(subtract(controls[n], controls[n - 1])) === 0,
    };
  },
);
