import { memoOn } from '../../kit/memoOn';
import { nurbsPoint, projectiveMap, projectiveMapWeighted, type Point } from '../../math';
import { haloUnit } from './halo';
import { KNOT_FIELDS, type KnotFields, knotCurve } from './knotGeometry';
import type { CircleCheck, Cursor, Projective, Rational } from './model';
import { flatten, sampleRange } from './sampling';

/**
 * The perspective map of the projective scene: (x, y) ↦ (x, y)/(0.08x + 0.06y + 1)
 * moved 9 to the right. Its vanishing line 0.08x + 0.06y + 1 = 0 is far to the lower left.
 */
export const PERSPECTIVE: number[][] = [
  [1 + 9 * 0.08, 9 * 0.06, 9],
  [0, 1, 0],
  [0.08, 0.06, 1],
];

/** The exact circle of the NURBS circle scene. */
export const CIRCLE = { centre: [0, 0] as Point, radius: 3 };

/** The same points and knots with every weight 1 (the plain B-spline), and the halo unit. */
const plainCurve = memoOn<KnotFields, keyof KnotFields, Omit<Rational, 'denominator'>>(
  KNOT_FIELDS,
  (state) => {
    const { points, degree, knots } = state;
    const plain = points.map(() => 1);
    return {
      plain: flatten(
        knotCurve(state).curve.segments.map((s) =>
          sampleRange((v) => nurbsPoint(points, plain, knots, degree, v), s.from, s.to),
        ),
      ),
      haloUnit: haloUnit(points),
    };
  },
);

/** The weights at work: the plain B-spline to compare, and Σ w_j N_j(u) at the cursor. */
export function rational(state: KnotFields, cursor: Cursor): Rational {
  const { weights } = knotCurve(state).curve;
  const denominator = cursor.basis.reduce((sum, b, i) => sum + weights[i] * b, 0);
  return { ...plainCurve(state), denominator };
}

/** The circle scene: how far the sampled curve is from the circle (and would be with weights 1). */
export const circleCheck = memoOn<KnotFields, keyof KnotFields, CircleCheck>(
  KNOT_FIELDS,
  (state) => {
    const { curve, at } = knotCurve(state);
    const { centre, radius } = CIRCLE;
    const off = (point: Point) =>
      Math.abs(Math.hypot(point[0] - centre[0], point[1] - centre[1]) - radius);
    const samples: Point[] = [];
    const [a, b] = curve.domain;
    for (let i = 0; i <= 200; i++) samples.push(at(a + ((b - a) * i) / 200));
    // The plain curve's samples are already there (every weight 1).
    const { plain } = plainCurve(state);
    let plainDeviation = 0;
    for (let k = 0; k < plain.length; k += 2) {
      plainDeviation = Math.max(plainDeviation, off([plain[k], plain[k + 1]]));
    }
    return {
      deviation: Math.max(...samples.map(off)),
      plainDeviation,
      samples: samples.filter((_, k) => k % 5 === 0),
    };
  },
);

/** The perspective map applied to the control points with their weights, and without. */
export const projective = memoOn<KnotFields, keyof KnotFields, Projective>(KNOT_FIELDS, (state) => {
  const { curve, at } = knotCurve(state);
  const { degree, knots } = state;
  let image: { points: Point[]; weights: number[] };
  try {
    image = projectiveMapWeighted(PERSPECTIVE, state.points, curve.weights);
  } catch {
    return {
      error: 'A control point lies beyond the vanishing line of the map: move it back up or right.',
      points: [],
      weights: [],
      curve: new Float64Array(0),
      mapped: [],
      plain: new Float64Array(0),
      deviation: 0,
      plainDeviation: 0,
    };
  }
  const mappedAt = (u: number) => nurbsPoint(image.points, image.weights, knots, degree, u);
  const plainAt = (u: number) => nurbsPoint(image.points, curve.weights, knots, degree, u);
  const mappedCurve = flatten(curve.segments.map((s) => sampleRange(mappedAt, s.from, s.to)));
  const plain = flatten(curve.segments.map((s) => sampleRange(plainAt, s.from, s.to)));
  const mapped: Point[] = [];
  let deviation = 0;
  let plainDeviation = 0;
  const [a, b] = curve.domain;
  for (let i = 0; i <= 64; i++) {
    const u = a + ((b - a) * i) / 64;
    const expected = projectiveMap(PERSPECTIVE, [at(u)])[0];
    const got = mappedAt(u);
    const wrong = plainAt(u);
    mapped.push(expected);
    deviation = Math.max(deviation, Math.hypot(got[0] - expected[0], got[1] - expected[1]));
    plainDeviation = Math.max(
      plainDeviation,
      Math.hypot(wrong[0] - expected[0], wrong[1] - expected[1]),
    );
  }
  return { error: null, ...image, curve: mappedCurve, mapped, plain, deviation, plainDeviation };
});
