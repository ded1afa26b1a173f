import { bernstein, deCasteljau, sampleBezier, splitBezier, type Point } from '../../math';
import { degenerateNote } from './degenerate';
import { type DeCasteljauState, degree, stage } from './state';

/** Everything the figure and the panel show, computed once per state. */
export interface DeCasteljauModel {
  state: DeCasteljauState;
  /** Degree n of the curve. */
  n: number;
  /** What the current step shows: the polygon, how many levels, the traced curve. */
  shown: ReturnType<typeof stage>;
  /** Every level of the construction at t: levels[r][i] = P_{r,i}. */
  levels: Point[][];
  /** The whole curve, sampled (interleaved x, y). */
  curve: Float64Array;
  /** Subdivision at t: the control polygons of the two halves, and their curves. */
  left: Point[];
  right: Point[];
  leftCurve: Float64Array;
  rightCurve: Float64Array;
  /** P(t) again from the Bernstein form, Σ W(n, i, t) P_i, as a check. */
  bernsteinPoint: Point;
  /** What degenerate control points do to the construction, in words; null if nothing. */
  note: string | null;
}

export function derive(state: DeCasteljauState): DeCasteljauModel {
  const n = degree(state);
  const samples = Math.max(64, 24 * n);
  const levels = deCasteljau(state.p, state.t);
  const [left, right] = splitBezier(state.p, state.t);
  const weights = state.p.map((_, i) => bernstein(n, i, state.t));
  const bernsteinPoint = [0, 1].map((d) =>
    weights.reduce((sum, w, i) => sum + w * state.p[i][d], 0),
  );
  return {
    state,
    n,
    shown: stage(state),
    levels,
    curve: sampleBezier(state.p, samples),
    left,
    right,
    leftCurve: sampleBezier(left, samples),
    rightCurve: sampleBezier(right, samples),
    bernsteinPoint,
    note: degenerateNote(state.p),
  };
}
