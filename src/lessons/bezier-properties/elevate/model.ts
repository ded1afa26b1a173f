import { type Point, bezierDeviation, controlPolygonGap, elevateDegree } from '../../../math';
import { type ExperimentBase, sampleCurve } from '../curve';
import { type PropertiesState, amount } from '../state';

/** The original and the elevated curve are compared at this many segments (1001 samples). */
export const DEVIATION_SAMPLES = 1000;

export interface ElevateModel extends ExperimentBase {
  x: 'elevate';
  /** The polygons after 0, 1, …, k elevations; the last is `controls`. */
  polygons: Point[][];
  /** Degree before and after. */
  originalDegree: number;
  n: number;
  curve: Float64Array;
  /** Largest distance between the original curve and the elevated one (rounding only). */
  deviation: number;
  /** How far each polygon is from the curve: max |Qi − P(i/N)|. */
  gaps: number[];
  /** The last elevation, from degree m: its Q1 = P0/(m+1) + m·P1/(m+1). */
  lastStep: { from: number; q1: Point } | null;
}

export function deriveElevate(state: PropertiesState): ElevateModel {
  const polygons: Point[][] = [state.p];
  for (let j = 0; j < amount(state); j++) polygons.push(elevateDegree(polygons[j]));
  const controls = polygons[polygons.length - 1];
  return {
    x: 'elevate',
    controls,
    extra: [],
    polygons,
    originalDegree: state.p.length - 1,
    n: controls.length - 1,
    curve: sampleCurve(controls),
    deviation: bezierDeviation(state.p, controls, DEVIATION_SAMPLES).distance,
    gaps: polygons.map(controlPolygonGap),
    lastStep: amount(state) > 0 ? { from: controls.length - 2, q1: controls[1] } : null,
  };
}
