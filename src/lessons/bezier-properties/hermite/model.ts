import { memoOn } from '../../../kit/memoOn';
import {
  type Point,
  add,
  bezierPoint,
  bezierToHermite,
  bezierToPowerBasis,
  hermitePoint,
  sampleBezier,
  sampledDeviation,
  scale,
} from '../../../math';
import type { ExperimentBase } from '../curve';
import type { PropertiesState } from '../state';

/** Both forms are drawn and compared at this many segments (201 samples). */
export const SAMPLES = 200;

export interface HermiteModel extends ExperimentBase {
  kind: 'hermite';
  /** The Bézier form and the Hermite form, sampled at the same t. */
  curve: Float64Array;
  hermiteCurve: Float64Array;
  /** Largest distance between them: rounding only. */
  deviation: number;
  point: Point;
  /** Power form a0 + a1μ + a2μ² + a3μ³ (equation 11 of the notes). */
  power: Point[];
  /** Hermite data: end points x0, x1 and end tangents x0′, x1′, and the tips of the tangents drawn at half length. */
  x0: Point;
  d0: Point;
  x1: Point;
  d1: Point;
  tips: [Point, Point];
  /** P(t) from the Hermite form. */
  hermiteAtT: Point;
}

export const deriveHermite = memoOn<PropertiesState, 'points' | 't', HermiteModel>(
  ['points', 't'],
  ({ points: controls, t }) => {
    const [x0, d0, x1, d1] = bezierToHermite(controls);
    const hermiteCurve = new Float64Array(2 * (SAMPLES + 1));
    for (let k = 0; k <= SAMPLES; k++)
      hermiteCurve.set(hermitePoint(x0, d0, x1, d1, k / SAMPLES), 2 * k);
    const curve = sampleBezier(controls, SAMPLES);
    // At half their length, as the end-tangents scene draws P′: at full length
    // the view had to reach three times the first leg out and the curve itself
    // came out 185 × 71 px on the projector (#19).
    const tips: [Point, Point] = [add(x0, scale(d0, 0.5)), add(x1, scale(d1, 0.5))];
    return {
      kind: 'hermite',
      controls,
      extra: tips,
      curve,
      hermiteCurve,
      deviation: sampledDeviation(curve, hermiteCurve).distance,
      point: bezierPoint(controls, t),
      power: bezierToPowerBasis(controls),
      x0,
      d0,
      x1,
      d1,
      tips,
      hermiteAtT: hermitePoint(x0, d0, x1, d1, t),
    };
  },
);
