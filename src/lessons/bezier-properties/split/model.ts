import { type Point, bezierPoint, controlPolygonGap, subdivisionLevels } from '../../../math';
import { type ExperimentBase, sampleCurve } from '../curve';
import { type PropertiesState, amount } from '../state';

export interface SplitModel extends ExperimentBase {
  x: 'split';
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

export function deriveSplit(state: PropertiesState): SplitModel {
  const controls = state.p;
  const splits = amount(state);
  const levels = subdivisionLevels(controls, state.t, splits);
  return {
    x: 'split',
    controls,
    extra: [],
    curve: sampleCurve(controls),
    point: bezierPoint(controls, state.t),
    levels,
    gaps: levels.map((pieces) => Math.max(...pieces.map(controlPolygonGap))),
    first: splits > 0 ? [levels[1][0], levels[1][1]] : null,
    atEnd: splits > 0 && (state.t === 0 || state.t === 1),
  };
}
