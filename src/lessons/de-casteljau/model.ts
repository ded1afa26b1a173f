import { bernstein, deCasteljau, sampleBezier, splitBezier, type Point } from '../../math';
import { degenerateNote } from './degenerate';
import type { Revealed } from '../../kit/script';
import type { Reveal } from './script';
import { memoOn } from '../../kit/memoOn';
import type { DeCasteljauState } from './state';

/** Everything the figure and the panel show, computed once per state. */
export interface DeCasteljauModel {
  state: DeCasteljauState;
  /** Degree n of the curve. */
  n: number;
  /** What the steps so far reveal: the polygon, how many levels, the traced curve. */
  shown: Revealed<Reveal>;
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

/** The construction at t: it reads only the points and t, so a step costs no new work. */
const geometry = memoOn<DeCasteljauState, 'p' | 't', Omit<DeCasteljauModel, 'state' | 'shown'>>(
  ['p', 't'],
  ({ p, t }) => {
    const n = p.length - 1;
    const samples = Math.max(64, 24 * n);
    const levels = deCasteljau(p, t);
    const [left, right] = splitBezier(p, t);
    const weights = p.map((_, i) => bernstein(n, i, t));
    const bernsteinPoint = [0, 1].map((d) => weights.reduce((sum, w, i) => sum + w * p[i][d], 0));
    return {
      n,
      levels,
      curve: sampleBezier(p, samples),
      left,
      right,
      leftCurve: sampleBezier(left, samples),
      rightCurve: sampleBezier(right, samples),
      bernsteinPoint,
      note: degenerateNote(p),
    };
  },
);

export function derive(state: DeCasteljauState, shown: Revealed<Reveal>): DeCasteljauModel {
  return { ...geometry(state), state, shown };
}
