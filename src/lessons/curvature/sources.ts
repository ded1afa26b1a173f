import {
  type Continuity,
  type Point,
  bezierChainSegments,
  bezierCurvature,
  bezierJointContinuity,
  catmullRomSegments,
  catmullRomTangents,
  cubicSplineC2,
  cubicSplineSegments,
  onOneSpot,
  uniformBSplineSegments,
} from '../../math';
import type { CurveSource } from '../../kit/lessonLinks';

/** The curve in words (panel, notes). */
export const SOURCE_NAMES: Record<CurveSource, string> = {
  bezier: 'One Bézier curve (control points P0 … Pn)',
  chain: 'Cubic Bézier pieces (joints at every third point)',
  natural: 'Natural cubic spline through the points (C²)',
  hermite: 'Hermite spline through the points with gradients Di (C¹)',
  'catmull-rom': 'Catmull-Rom spline through the points (C¹)',
  'b-spline': 'Uniform cubic B-spline (C²)',
};

/** Does the curve pass through its points (so the dashed control polygon is not drawn)? */
export const THROUGH_POINTS: Record<CurveSource, boolean> = {
  bezier: false,
  chain: false,
  natural: true,
  hermite: true,
  'catmull-rom': true,
  'b-spline': false,
};

/** Where piece i − 1 meets piece i: at the global parameter p̄ = i (`s`), with κ just before and just after. */
export interface Join {
  s: number;
  point: Point;
  continuity: Continuity;
  before: number | null;
  after: number | null;
}

/** The plane curve as polynomial Bézier pieces, on the global parameter p̄ ∈ [0, pieces]. */
export interface PiecewiseCurve {
  segments: Point[][];
  joins: Join[];
  /** What was done with input the source cannot take (null when all was fine). */
  notice: string | null;
  /** What the curve drawn is, in words for a caption: "The natural cubic spline through the 5 points". */
  name: string;
}

const curvatureOrNull = (segment: readonly Point[], t: number) => {
  try {
    return bezierCurvature(segment, t);
  } catch {
    return null;
  }
};

const same = (a: Point, b: Point) => a[0] === b[0] && a[1] === b[1];

/**
 * The source's pieces from its points (and the Hermite gradients d). Input the
 * source cannot take falls back to something sensible and says so: too few
 * points for a B-spline or a chain give the Bézier curve of the points;
 * repeated points of a spline through points are taken once.
 */
export function piecewiseCurve(
  source: CurveSource,
  p: readonly Point[],
  d: readonly Point[],
): PiecewiseCurve {
  const { segments, notice, name } = build(source, p, d);
  const joins: Join[] = [];
  for (let i = 1; i < segments.length; i++) {
    const [left, right] = [segments[i - 1], segments[i]];
    joins.push({
      s: i,
      point: right[0],
      continuity: bezierJointContinuity(left, right),
      before: curvatureOrNull(left, 1),
      after: curvatureOrNull(right, 0),
    });
  }
  return { segments, joins, notice, name };
}

type Built = { segments: Point[][]; notice: string | null; name: string };

/** One Bézier curve of `count` control points, named by its degree. */
export function bezierName(count: number): string {
  const degree = count - 1;
  if (degree === 1) return 'The Bézier curve of degree 1, a straight segment,';
  if (degree === 2) return 'The quadratic Bézier curve';
  if (degree === 3) return 'The cubic Bézier curve';
  return `The Bézier curve of degree ${degree}`;
}

const pieceCount = (segments: readonly Point[][]) =>
  segments.length === 1 ? '1 piece' : `${segments.length} pieces`;

function build(source: CurveSource, p: readonly Point[], d: readonly Point[]): Built {
  const whole = (notice: string | null, name = bezierName(p.length)) => ({
    segments: [p.map((q) => q.slice())],
    notice,
    name,
  });
  if (onOneSpot(p))
    return whole(
      'All the points are on one spot: the curve is that point. Its velocity is 0 everywhere, so T, N, κ and the osculating circle are undefined along all of it.',
      'A curve that is one point',
    );
  switch (source) {
    case 'bezier':
      return whole(null);
    case 'b-spline': {
      if (p.length < 4)
        return whole(
          `A uniform cubic B-spline needs at least 4 control points; with ${p.length} the Bézier curve of the points is shown.`,
        );
      const segments = uniformBSplineSegments(p);
      return {
        segments,
        notice: null,
        name: `The uniform cubic B-spline of the ${p.length} control points (${pieceCount(segments)})`,
      };
    }
    case 'chain': {
      const pieces = Math.floor((p.length - 1) / 3);
      if (pieces === 0)
        return whole(
          `Cubic Bézier pieces need 3k + 1 points (4, 7, 10, …); with ${p.length} the Bézier curve of the points is shown.`,
        );
      const used = 3 * pieces + 1;
      return {
        segments: bezierChainSegments(p.slice(0, used), 3),
        name:
          pieces === 1 ? bezierName(4) : `The ${pieces} cubic Bézier pieces, joined end to end,`,
        notice:
          used === p.length
            ? null
            : `Cubic Bézier pieces need 3k + 1 points (4, 7, 10, …): the last ${p.length - used} of ${p.length} are left out.`,
      };
    }
    default:
      return through(source, p, d);
  }
}

const THROUGH_NAMES = {
  natural: 'natural cubic spline',
  hermite: 'Hermite spline',
  'catmull-rom': 'Catmull-Rom spline',
} as const;

/** Splines through the points: a repeated point would make a piece of length 0, so it is taken once. */

function through(
  source: 'natural' | 'hermite' | 'catmull-rom',
  p: readonly Point[],
  d: readonly Point[],
): Built {
  const gradients = source === 'hermite' ? hermiteGradients(p, d) : [];
  const keep = p.map((q, i) => i === 0 || !same(q, p[i - 1]));
  const points = p.filter((_, i) => keep[i]);
  const repeated = p.length - points.length;
  const notice = repeated
    ? `${repeated === 1 ? 'A point repeats' : `${repeated} points repeat`} the one before: a piece of length 0 has no direction, so each repeated point is taken once.`
    : null;
  if (points.length < 2)
    return {
      segments: [p.map((q) => q.slice())],
      notice: 'All the points coincide: there is no curve through them, only a point.',
      name: 'A curve that is one point',
    };
  const segments =
    source === 'natural'
      ? cubicSplineC2(points)
      : source === 'catmull-rom'
        ? catmullRomSegments(points, 0)
        : cubicSplineSegments(
            points,
            gradients.filter((_, i) => keep[i]),
          );
  const name = `The ${THROUGH_NAMES[source]} through the ${points.length} points (${pieceCount(segments)})`;
  return { segments, notice, name };
}

/** The Hermite gradients: the given ones, and Catmull-Rom's where none is given. */
export function hermiteGradients(p: readonly Point[], d: readonly Point[]): Point[] {
  if (d.length === p.length) return d.map((v) => v.slice());
  const fill = catmullRomTangents(p);
  return p.map((_, i) => (d[i] ?? fill[i]).slice());
}
