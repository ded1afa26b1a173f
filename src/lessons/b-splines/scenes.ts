import type { ScriptedScene } from '../../kit/lesson';
import { clampedUniformKnots, nurbsCircle, type Point, uniformKnots } from '../../math';
import type { BSplineModel } from './model';
import { CIRCLE } from './nurbsGeometry';
import { type Reveal, partScript } from './scripts';
import { type BSplineState, DEFAULT_LINE, SEVEN_POINTS, type Part } from './state';

const copy = (list: readonly Point[]): Point[] => list.map((point) => [...point]);

/** Six points around a loop: closed, they give six segments. */
const CLOSED: Point[] = [
  [0, 0],
  [4, -1.5],
  [8, 0.5],
  [9, 4.5],
  [5, 6.5],
  [0.5, 5],
];

/** Ten points (seven segments), so that moving P4 leaves three of them as they were. */
const LONG: Point[] = [
  [0, 0],
  [1, 3],
  [3, 4],
  [4.5, 1],
  [6.5, 0],
  [8, 3],
  [10, 3.5],
  [11.5, 0.5],
  [13.5, 0],
  [15, 3],
];
const MOVED: Point[] = LONG.map((point, i) => (i === 4 ? [6.5, 3.5] : [...point]));

const n = SEVEN_POINTS.length;
const ones = SEVEN_POINTS.map(() => 1);

type Scene = ScriptedScene<BSplineState, BSplineModel, Reveal>;

/** A scene of one part, with the fields it sets (the rest: the seven points, cubic, clamped). */
function scene(part: Part, label: string, fields: Partial<BSplineState> = {}): Scene {
  const setup = (s: BSplineState): BSplineState => {
    const points = fields.points ?? copy(SEVEN_POINTS);
    const degree = fields.degree ?? 3;
    return {
      ...s,
      part,
      points,
      before: fields.before ?? copy(points),
      t: fields.t ?? 0.35,
      step: 0,
      degree,
      knots: fields.knots ?? clampedUniformKnots(points.length, degree),
      weights: fields.weights ?? points.map(() => 1),
      line: copy(DEFAULT_LINE),
    };
  };
  return { id: part, label, setup, script: partScript(part) };
}

const circle = nurbsCircle(CIRCLE.centre, CIRCLE.radius);
const circleFields: Partial<BSplineState> = {
  points: circle.points,
  weights: circle.weights,
  knots: circle.knots,
  degree: circle.degree,
  t: 0.1,
};

/** The lesson's scenes, in teaching order. */
export const SCENES: Scene[] = [
  scene('uniform', 'Uniform cubic B-spline'),
  scene('closed', 'Closed B-spline', { points: CLOSED, t: 0.1 }),
  scene('local', 'Local control', { points: MOVED, before: copy(LONG), t: 0.45 }),
  scene('knots', 'Knots and Cox–de Boor', {
    knots: Array.from({ length: n + 4 }, (_, j) => j),
    t: 0.4,
  }),
  scene('clamped', 'Clamped ends', { knots: clampedUniformKnots(n, 3), t: 0.05 }),
  scene('repeated', 'Repeated knots', { knots: [0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2], t: 0.3 }),
  scene('convert', 'B-spline ↔ Bézier', { t: 0.4 }),
  scene('properties', 'Properties'),
  scene('nurbs', 'NURBS weights', {
    weights: ones.map((w, i) => (i === 2 ? 4 : i === 5 ? 0.25 : w)),
    t: 0.3,
  }),
  scene('circle', 'The exact circle', circleFields),
  scene('projective', 'Projective map', circleFields),
  scene('meanings', 'Two meanings of “knots”', { t: 0.4 }),
  // The steps set the degree and the knots; the state's are the cubic's, uniform.
  scene('continuity', 'Degree p ⇒ Cᵖ⁻¹', { knots: uniformKnots(n, 3), t: 0.4 }),
];
