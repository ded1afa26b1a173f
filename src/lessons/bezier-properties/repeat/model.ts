import { memoOn } from '../../../kit/memoOn';
import type { Revealed } from '../../../kit/script';
import { type Point, bernsteinBasis, bezierPoint } from '../../../math';
import { type ExperimentBase, byCount, sampleCurve } from '../curve';
import type { PropertiesState } from '../state';
import type { RepeatReveal } from './script';

export interface RepeatModel extends ExperimentBase {
  kind: 'repeat';
  /** Degree of the curve with the copies. */
  n: number;
  /** How many times P_r is listed: once, and once more per copy the steps show. */
  copies: number;
  /** The curve with the copies, and the curve with P_r once (dashed). */
  curve: Float64Array;
  onceCurve: Float64Array;
  point: Point;
  /** The weight of P_r at t: the sum over its copies, and with it listed once. */
  weight: number;
  weightOnce: number;
}

/** The user's points with P_r listed `copies` times. */
export const repeatPoint = (points: readonly Point[], r: number, copies: number): Point[] =>
  points.flatMap((point, i) => (i === r ? Array.from({ length: copies }, () => point) : [point]));

/** The curve with P_r listed 1, 2, … times: made once for each count while the points, r and t stay. */
const curves = memoOn<
  PropertiesState,
  'points' | 'repeated' | 't',
  (copies: number) => RepeatModel
>(['points', 'repeated', 't'], ({ points, repeated: r, t }) => {
  const onceCurve = sampleCurve(points);
  const weightOnce = bernsteinBasis(points.length - 1, t)[r];
  return byCount((copies) => {
    const controls = repeatPoint(points, r, copies);
    const n = controls.length - 1;
    // The copies of P_r sit at indices r … r + copies − 1 of the repeated list.
    const weight = bernsteinBasis(n, t)
      .slice(r, r + copies)
      .reduce((a, b) => a + b, 0);
    return {
      kind: 'repeat',
      controls,
      extra: [],
      n,
      copies,
      curve: sampleCurve(controls),
      onceCurve,
      point: bezierPoint(controls, t),
      weight,
      weightOnce,
    };
  });
});

export const deriveRepeat = (state: PropertiesState, shown: Revealed<RepeatReveal>) =>
  curves(state)(shown.count('copy') + 1);
