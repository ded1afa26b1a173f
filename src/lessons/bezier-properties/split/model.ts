import { memoOn } from '../../../kit/memoOn';
import type { Revealed } from '../../../kit/script';
import { type Point, bezierPoint, controlPolygonGap, subdivisionLevels } from '../../../math';
import { type ExperimentBase, byCount, sampleCurve } from '../curve';
import type { PropertiesState } from '../state';
import type { SplitReveal } from './script';

export interface SplitModel extends ExperimentBase {
  kind: 'split';
  curve: Float64Array;
  point: Point;
  /** levels[j]: the 2ʲ control polygons after j splits at t; the last level is drawn. */
  levels: Point[][][];
  /** The largest gap between a polygon and its piece of the curve, at each level. */
  gaps: number[];
  /** The first split: de Casteljau's left and right polygons; null before any split. */
  first: [Point[], Point[]] | null;
  /** Split at t = 0 or 1: one piece is a single point, the other the whole curve. */
  atEnd: boolean;
}

/** The curve split 0, 1, 2, … times at t, each made once while the points and t stay. */
const splits = memoOn<PropertiesState, 'points' | 't', (count: number) => SplitModel>(
  ['points', 't'],
  ({ points: controls, t }) => {
    const curve = sampleCurve(controls);
    const point = bezierPoint(controls, t);
    return byCount((count) => {
      const levels = subdivisionLevels(controls, t, count);
      return {
        kind: 'split',
        controls,
        extra: [],
        curve,
        point,
        levels,
        gaps: levels.map((pieces) => Math.max(...pieces.map(controlPolygonGap))),
        first: count > 0 ? [levels[1][0], levels[1][1]] : null,
        atEnd: count > 0 && (t === 0 || t === 1),
      };
    });
  },
);

export const deriveSplit = (state: PropertiesState, shown: Revealed<SplitReveal>) =>
  splits(state)(shown.count('split'));
