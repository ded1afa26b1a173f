import { memoOn } from '../../../kit/memoOn';
import type { Revealed } from '../../../kit/script';
import { type Point, bezierDeviation, controlPolygonGap, elevateDegree } from '../../../math';
import { type ExperimentBase, byCount, sampleCurve } from '../curve';
import type { PropertiesState } from '../state';
import type { ElevateReveal } from './script';

/** The original and the elevated curve are compared at this many segments (1001 samples). */
export const DEVIATION_SAMPLES = 1000;

export interface ElevateModel extends ExperimentBase {
  kind: 'elevate';
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

/** One polygon of the sequence: the curve it draws, its distance from the original and from its curve. */
interface Elevation {
  polygon: Point[];
  curve: Float64Array;
  deviation: number;
  gap: number;
}

/** The polygons after 0, 1, 2, … elevations, each made once while the points stay. */
const elevations = memoOn<PropertiesState, 'points', (count: number) => Elevation>(
  ['points'],
  ({ points }) => {
    const elevation: (count: number) => Elevation = byCount((count) => {
      const polygon = count === 0 ? points : elevateDegree(elevation(count - 1).polygon);
      return {
        polygon,
        curve: sampleCurve(polygon),
        deviation: bezierDeviation(points, polygon, DEVIATION_SAMPLES).distance,
        gap: controlPolygonGap(polygon),
      };
    });
    return elevation;
  },
);

export function deriveElevate(
  state: PropertiesState,
  shown: Revealed<ElevateReveal>,
): ElevateModel {
  const elevation = elevations(state);
  const count = shown.count('elevation');
  const sequence = Array.from({ length: count + 1 }, (_, j) => elevation(j));
  const { polygon: controls, curve, deviation } = sequence[count];
  return {
    kind: 'elevate',
    controls,
    extra: [],
    polygons: sequence.map((step) => step.polygon),
    originalDegree: state.points.length - 1,
    n: controls.length - 1,
    curve,
    deviation,
    gaps: sequence.map((step) => step.gap),
    lastStep: count > 0 ? { from: controls.length - 2, q1: controls[1] } : null,
  };
}
