import {
  bernstein,
  bezierPoint,
  deCasteljau,
  distance,
  sampleBezier,
  splitBezier,
  type Point,
} from '../../math';
import { degenerateNote } from './degenerate';
import type { Revealed } from '../../kit/script';
import { memoOn } from '../../kit/memoOn';
import { PLOT_STEPS, computedBy } from './pseudocode';
import type { DeCasteljauState } from './state';
import type { Reveal } from './walks';

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
  /** weights[r][j] = W(r, j, t), the blending functions of every level. */
  weights: number[][];
  /**
   * Every level expanded into the control points, apart from the
   * construction: blends[r][i] = Σ_j W(r, j, t) P_{i+j}, which is P_{r,i}.
   */
  blends: Point[][];
  /** How far the expansion's last point lies from the construction's (rounding only). */
  blendGap: number;
  /** The pseudocode's drawCurve: P(j/L) for j = 0 … L. */
  plotted: Point[];
  /** For each level r, how many of its points the steps so far have computed (from the left). */
  computed: number[];
  /** The points [r, i] the current step computes (none at the steps that compute nothing). */
  current: [number, number][];
  /** What degenerate control points do to the construction, in words; null if nothing. */
  note: string | null;
}

type Geometry = Omit<DeCasteljauModel, 'state' | 'shown' | 'computed' | 'current'>;

/** The construction at t: it reads only the points and t, so a step costs no new work. */
const geometry = memoOn<DeCasteljauState, 'p' | 't', Geometry>(['p', 't'], ({ p, t }) => {
  const n = p.length - 1;
  const samples = Math.max(64, 24 * n);
  const levels = deCasteljau(p, t);
  const [left, right] = splitBezier(p, t);
  const weights = levels.map((_, r) => Array.from({ length: r + 1 }, (_, j) => bernstein(r, j, t)));
  const blend = (r: number, i: number): Point =>
    [0, 1].map((d) => weights[r].reduce((sum, w, j) => sum + w * p[i + j][d], 0));
  const blends = levels.map((level, r) => level.map((_, i) => blend(r, i)));
  return {
    n,
    levels,
    curve: sampleBezier(p, samples),
    left,
    right,
    leftCurve: sampleBezier(left, samples),
    rightCurve: sampleBezier(right, samples),
    bernsteinPoint: blends[n][0],
    weights,
    blends,
    blendGap: distance(blends[n][0], levels[n][0]),
    plotted: Array.from({ length: PLOT_STEPS + 1 }, (_, j) => bezierPoint(p, j / PLOT_STEPS)),
    note: degenerateNote(p),
  };
});

/** Which points of which levels the steps so far have computed, and which the current step does. */
function progress(state: DeCasteljauState, shown: Revealed<Reveal>, n: number) {
  const all = (r: number) => n - r + 1;
  const levelsDone = (count: number) =>
    Array.from({ length: n + 1 }, (_, r) => (r <= count ? all(r) : 0));
  const wholeLevel = (r: number): [number, number][] =>
    r > 0 ? Array.from({ length: all(r) }, (_, i) => [r, i]) : [];
  if (state.mode === 'pseudocode') {
    const presses = shown.count('compute');
    const computed = Array.from({ length: n + 1 }, (_, r) =>
      r === 0 && shown.has('copy') ? all(0) : 0,
    );
    for (let k = 1; k <= presses; k++) for (const [r] of computedBy(n, k)) computed[r]++;
    return { computed, current: shown.is('compute') ? computedBy(n, shown.index) : [] };
  }
  if (state.mode === 'bernstein') {
    const count = shown.has('same') ? n : shown.count('blend');
    return { computed: levelsDone(count), current: shown.is('blend') ? wholeLevel(count) : [] };
  }
  const count = shown.count('level');
  return { computed: levelsDone(count), current: wholeLevel(count) };
}

export function derive(state: DeCasteljauState, shown: Revealed<Reveal>): DeCasteljauModel {
  const made = geometry(state);
  return { ...made, state, shown, ...progress(state, shown, made.n) };
}
