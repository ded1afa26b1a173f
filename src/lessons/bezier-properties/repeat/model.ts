import { type Point, bernsteinBasis, bezierPoint } from '../../../math';
import { type ExperimentBase, sampleCurve } from '../curve';
import { type PropertiesState, amount } from '../state';

export interface RepeatModel extends ExperimentBase {
  x: 'repeat';
  /** Degree of the curve with the copies. */
  n: number;
  /** How many times P_r is listed (k + 1). */
  copies: number;
  /** The curve with the copies, and the curve with P_r once (dashed). */
  curve: Float64Array;
  onceCurve: Float64Array;
  point: Point;
  /** The weight of P_r at t: the sum over its copies, and with it listed once. */
  weight: number;
  weightOnce: number;
}

/** The user's points with P_r listed k + 1 times. */
export const repeatPoint = (state: PropertiesState): Point[] =>
  state.p.flatMap((point, i) =>
    i === state.r ? Array.from({ length: amount(state) + 1 }, () => point) : [point],
  );

export function deriveRepeat(state: PropertiesState): RepeatModel {
  const controls = repeatPoint(state);
  const n = controls.length - 1;
  const copies = amount(state) + 1;
  // The copies of P_r sit at indices r … r + copies − 1 of the repeated list.
  const weight = bernsteinBasis(n, state.t)
    .slice(state.r, state.r + copies)
    .reduce((a, b) => a + b, 0);
  return {
    x: 'repeat',
    controls,
    extra: [],
    n,
    copies,
    curve: sampleCurve(controls),
    onceCurve: sampleCurve(state.p),
    point: bezierPoint(controls, state.t),
    weight,
    weightOnce: bernsteinBasis(state.p.length - 1, state.t)[state.r],
  };
}
