import { memoOn } from '../../kit/memoOn';
import {
  bezierToUniformBSpline,
  convexHull,
  coxDeBoorTable,
  projectiveMap,
  sampleBezier,
  uniformBSplineBasis,
  uniformBSplinePoint,
  uniformBSplineSegments,
  type Point,
} from '../../math';
import { basisRows } from './basisSamples';
import { crossings } from './crossings';
import type { Curve, Cursor, LocalControl, Properties } from './model';
import { SAMPLES } from './sampling';
import type { BSplineState } from './state';

/** The affine map of the properties scene: a rotation with shear, moved to the right. */
export const AFFINE: number[][] = [
  [0.9, 0.5, 13],
  [-0.3, 1, 1],
  [0, 0, 1],
];

/** The uniform cubic's curve, with each segment as its Bézier curve. */
export type UniformCurve = Curve & { beziers: Point[][] };

type CurveFields = Pick<BSplineState, 'part' | 'points'>;

/**
 * The uniform cubic in the slides' matrix form: segment i (Q_{i+3}) blends P_i … P_{i+3} with the 1/6
 * matrix. It reads only the points and whether the curve is closed.
 */
export const uniformCurve = memoOn<CurveFields, keyof CurveFields, UniformCurve>(
  ['part', 'points'],
  ({ part, points }) => {
    const n = points.length;
    const owner = Array.from({ length: part === 'closed' ? n + 3 : n }, (_, i) => i % n);
    const control = owner.map((i) => points[i]);
    const count = control.length - 3;
    const beziers = uniformBSplineSegments(control);
    const segments = beziers.map((bezier, i) => ({
      from: i,
      to: i + 1,
      points: [0, 1, 2, 3].map((k) => owner[i + k]),
      samples: sampleBezier(bezier, SAMPLES),
      bezier,
    }));
    // s ∈ [0, m − 2] is u on the knots −3, −2, …: segment i is [i, i + 1] (the continuation
    // notes' t, whose segment changes where it is a whole number).
    const knots = Array.from({ length: control.length + 4 }, (_, j) => j - 3);
    return {
      control,
      owner,
      degree: 3,
      knots,
      weights: control.map(() => 1),
      domain: [0, count],
      segments,
      rows: basisRows(knots, 3),
      start: beziers[0][0],
      end: beziers[count - 1][3],
      joins: [],
      beziers,
    };
  },
);

/** The cursor at t: s = t·(number of segments), its segment, and the four weights there. */
export function uniformCursor(curve: UniformCurve, t: number): Cursor {
  const count = curve.segments.length;
  const u = t * count;
  const segment = Math.min(Math.floor(u), count - 1);
  const local = u - segment;
  const basis = curve.control.map(() => 0);
  uniformBSplineBasis(local).forEach((b, k) => (basis[segment + k] = b));
  return {
    u,
    segment,
    local,
    point: uniformBSplinePoint(curve.control, u),
    table: coxDeBoorTable(curve.knots, 3, u),
    basis,
  };
}

/** The segment's Bézier points converted back: its four B-spline points. */
export const convertBack = (curve: UniformCurve, segment: number): Point[] =>
  bezierToUniformBSpline(curve.beziers[segment]);

type LocalFields = Pick<BSplineState, 'part' | 'points' | 'before'>;

/** Local control: the points now against the points before, as B-spline and as one Bézier curve. */
export const localControl = memoOn<LocalFields, keyof LocalFields, LocalControl>(
  ['part', 'points', 'before'],
  (state) => {
    const { points, before: q } = state;
    const moved = points.flatMap((point, i) =>
      point[0] !== q[i][0] || point[1] !== q[i][1] ? [i] : [],
    );
    const before = uniformBSplineSegments(q).map((bezier) => sampleBezier(bezier, SAMPLES));
    const samples = Math.max(96, 16 * points.length);
    return {
      bezier: sampleBezier(points, samples),
      bezierBefore: sampleBezier(q, samples),
      before,
      changed: uniformCurve(state).segments.map((segment) =>
        segment.points.some((i) => moved.includes(i)),
      ),
      moved,
    };
  },
);

type PropertyFields = Pick<BSplineState, 'part' | 'points' | 'line'>;

/** Convex hulls, crossings with the line, and the affine image of the curve. */
export const properties = memoOn<PropertyFields, keyof PropertyFields, Properties>(
  ['part', 'points', 'line'],
  (state) => {
    const { segments, domain } = uniformCurve(state);
    const hulls = segments.map((segment) => convexHull(segment.points.map((i) => state.points[i])));
    const image = projectiveMap(AFFINE, state.points);
    const imageSegments = uniformBSplineSegments(image);
    const imageSamples: Point[] = [];
    let deviation = 0;
    segments.forEach((_, i) => {
      for (let j = 0; j <= 8; j++) {
        const s = Math.min(i + j / 8, domain[1]);
        const mapped = projectiveMap(AFFINE, [uniformBSplinePoint(state.points, s)])[0];
        const direct = uniformBSplinePoint(image, s);
        deviation = Math.max(deviation, Math.hypot(mapped[0] - direct[0], mapped[1] - direct[1]));
        if (j < 8 || i === segments.length - 1) imageSamples.push(mapped);
      }
    });
    return {
      hulls,
      crossings: crossings(state.line, state.points, segments),
      image,
      imageSegments,
      imageSamples,
      deviation,
    };
  },
);
