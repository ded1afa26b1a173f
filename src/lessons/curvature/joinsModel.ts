import { type Point, bezierCurvature, bezierDerivative, bezierTangent } from '../../math';
import { type CurvatureSlope, curvatureSlope } from './curvatureSlope';
import { type PlaneCurve, deriveCurve } from './planeModel';
import { piecewiseCurve } from './sources';

// G², G³ and C^(n−1): at each join of a natural cubic spline κ has one value
// from both sides (G²) but its slope dκ/ds does not (not G³); at a join of the
// Catmull-Rom spline of the same points (C¹ only) κ itself jumps (not G²).

/** A value just before a join (the end of piece i − 1) and just after it (the start of piece i). */
export interface Sides<T> {
  before: T;
  after: T;
}

/** What the scene says of one join: at the global p̄ = s, with each side's value. */
export interface SplineJoin {
  s: number;
  point: Point;
  /** P′ and P″ (in each piece's own parameter). */
  first: Sides<Point>;
  second: Sides<Point>;
  /** κ, and its slope dκ/ds (and dκ/dp̄, for the plot); null where undefined (P′ = 0). */
  kappa: Sides<number> | null;
  slope: Sides<CurvatureSlope> | null;
}

export interface JoinsModel {
  /** The natural spline's joins (the plane model holds its curve and its κ). */
  natural: SplineJoin[];
  /** The Catmull-Rom spline of the same points: drawn dashed, its κ plotted, its joins. */
  catmull: PlaneCurve;
  catmullJoins: SplineJoin[];
}

const secondDerivative = (piece: readonly Point[], p: number) =>
  bezierTangent(bezierDerivative(piece), p);

const kappaOrNull = (piece: readonly Point[], p: number) => {
  try {
    return bezierCurvature(piece, p);
  } catch {
    return null;
  }
};

/** Both sides of every join of a chain of cubic pieces. */
export function splineJoins(segments: readonly Point[][]): SplineJoin[] {
  const joins: SplineJoin[] = [];
  for (let i = 1; i < segments.length; i++) {
    const [left, right] = [segments[i - 1], segments[i]];
    const [kBefore, kAfter] = [kappaOrNull(left, 1), kappaOrNull(right, 0)];
    const [sBefore, sAfter] = [curvatureSlope(left, 1), curvatureSlope(right, 0)];
    joins.push({
      s: i,
      point: right[0],
      first: { before: bezierTangent(left, 1), after: bezierTangent(right, 0) },
      second: { before: secondDerivative(left, 1), after: secondDerivative(right, 0) },
      kappa: kBefore === null || kAfter === null ? null : { before: kBefore, after: kAfter },
      slope: sBefore && sAfter ? { before: sBefore, after: sAfter } : null,
    });
  }
  return joins;
}

/** Two numbers that agree up to rounding (relative to their size), or to the finite difference's error. */
export function same(a: number, b: number, tolerance = 1e-9): boolean {
  return Math.abs(a - b) <= tolerance * Math.max(1, Math.abs(a), Math.abs(b));
}

/** The finite differences of dκ/ds agree to about 10⁻⁸: slopes closer than this are one slope. */
export const SLOPE_TOLERANCE = 1e-6;

/** The joins of the natural spline (its pieces from the plane model) and the Catmull-Rom spline of the same points. */
export function deriveJoins(points: readonly Point[], natural: readonly Point[][]): JoinsModel {
  const catmull = deriveCurve(piecewiseCurve('catmull-rom', points, []));
  return {
    natural: splineJoins(natural),
    catmull,
    catmullJoins: splineJoins(catmull.pieces.segments),
  };
}
