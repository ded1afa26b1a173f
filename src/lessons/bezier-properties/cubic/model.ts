import { memoOn } from '../../../kit/memoOn';
import {
  type Point,
  bezierCurvature,
  bezierPoint,
  cubicInflections,
  cubicSelfIntersection,
  sampleBezier,
} from '../../../math';
import type { ExperimentBase } from '../curve';
import type { PropertiesState } from '../state';

const SAMPLES = 240;

/** A stretch of the curve where the curvature keeps one sign. */
export interface SignRun {
  /** +1 turning left, −1 turning right, 0 straight, NaN where the speed is zero (a cusp). */
  sign: number;
  samples: Float64Array;
}

export interface CubicModel extends ExperimentBase {
  kind: 'cubic';
  point: Point;
  /** The curve cut where its curvature changes sign, to colour each turn. */
  runs: SignRun[];
  inflections: { t: number; point: Point }[];
  /** The two parameters where the curve crosses itself, and the crossing. */
  loop: { t: [number, number]; point: Point } | null;
  /** κ(t); null where the speed is zero. */
  curvature: number | null;
  /** All four control points on one line: curvature zero everywhere. */
  straight: boolean;
  /** The speed is zero somewhere (between a loop and an inflection). */
  cusp: boolean;
}

/** κ, or NaN where the speed is zero and the curvature is undefined. */
function curvatureAt(p: readonly Point[], t: number): number {
  try {
    return bezierCurvature(p, t);
  } catch {
    return Number.NaN;
  }
}

/** The samples cut into runs of one curvature sign (a run ends on the sample where the next begins). */
function signRuns(curve: Float64Array, signs: readonly number[]): SignRun[] {
  const runs: SignRun[] = [];
  let start = 0;
  for (let k = 1; k <= SAMPLES; k++) {
    if (k === SAMPLES || signs[k] !== signs[start]) {
      runs.push({ sign: signs[start], samples: curve.slice(2 * start, 2 * k + 2) });
      start = k;
    }
  }
  return runs;
}

export const deriveCubic = memoOn<PropertiesState, 'points' | 't', CubicModel>(
  ['points', 't'],
  ({ points: controls, t }) => {
    const signs = Array.from({ length: SAMPLES + 1 }, (_, k) =>
      Math.sign(curvatureAt(controls, k / SAMPLES)),
    );
    const crossing = cubicSelfIntersection(controls);
    const curvature = curvatureAt(controls, t);
    return {
      kind: 'cubic',
      controls,
      extra: [],
      point: bezierPoint(controls, t),
      runs: signRuns(sampleBezier(controls, SAMPLES), signs),
      inflections: cubicInflections(controls).map((t) => ({ t, point: bezierPoint(controls, t) })),
      loop: crossing ? { t: crossing, point: bezierPoint(controls, crossing[0]) } : null,
      curvature: Number.isNaN(curvature) ? null : curvature,
      straight: signs.every((s) => s === 0),
      cusp: signs.some((s) => Number.isNaN(s)),
    };
  },
);
