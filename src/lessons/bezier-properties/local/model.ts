import { memoOn } from '../../../kit/memoOn';
import { type Point, bernstein, bezierDeviation, bezierPoint, distance } from '../../../math';
import { type ExperimentBase, sampleCurve } from '../curve';
import type { PropertiesState } from '../state';

export interface LocalModel extends ExperimentBase {
  kind: 'local';
  /** Degree N. */
  n: number;
  /** The "before" control points and curve (dashed), and the current curve. */
  before: Point[];
  beforeCurve: Float64Array;
  curve: Float64Array;
  /** Where the curve moved most: the parameter, the distance, the curve point before and after there. */
  largest: { at: number; distance: number; from: Point; to: Point };
  /** Indices of the control points that differ from "before". */
  moved: number[];
  /**
   * When exactly one point Pi moved: P_after(t) − P_before(t) = W(N, i, t)·ΔPi,
   * largest where W(N, i, ·) peaks, at t = i/N; the curve moved at most
   * `percent` of the point's shift.
   */
  single: { index: number; shift: number; peak: number; percent: number } | null;
}

export const deriveLocal = memoOn<PropertiesState, 'points' | 'before', LocalModel>(
  ['points', 'before'],
  ({ points: p, before: q }) => {
    const n = p.length - 1;
    const { at, distance: largest } = bezierDeviation(q, p);
    const moved = p.flatMap((point, i) => (distance(point, q[i]) > 0 ? [i] : []));
    let single: LocalModel['single'] = null;
    if (moved.length === 1) {
      const index = moved[0];
      const shift = distance(p[index], q[index]);
      single = {
        index,
        shift,
        peak: bernstein(n, index, index / n),
        percent: (100 * largest) / shift,
      };
    }
    return {
      kind: 'local',
      controls: p,
      extra: q,
      n,
      before: q,
      beforeCurve: sampleCurve(q),
      curve: sampleCurve(p),
      largest: { at, distance: largest, from: bezierPoint(q, at), to: bezierPoint(p, at) },
      moved,
      single,
    };
  },
);
