import type { Point, Scene } from '../../app/lesson';
import { clampedUniformKnots, nurbsCircle } from '../../math';
import { CIRCLE } from './model';
import { type BSplineState, DEFAULT_LINE, LECTURE_POINTS, type Part } from './state';

const copy = (list: readonly Point[]): Point[] => list.map((point) => [...point]);

const CLOSED: Point[] = [
  [0, 0],
  [4, -1.5],
  [8, 0.5],
  [9, 4.5],
  [5, 6.5],
  [0.5, 5],
];

/** Ten points (seven segments), so that moving x4 leaves three of them as they were. */
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

const n = LECTURE_POINTS.length;
const ones = LECTURE_POINTS.map(() => 1);

function scene(id: Part, label: string, fields: Partial<BSplineState> = {}): Scene<BSplineState> {
  return {
    id,
    label,
    apply: (s) => {
      const p = fields.p ?? copy(LECTURE_POINTS);
      const d = fields.d ?? 3;
      return {
        ...s,
        x: id,
        p,
        q: fields.q ?? copy(p),
        t: fields.t ?? 0.35,
        k: 0,
        d,
        u: fields.u ?? clampedUniformKnots(p.length, d),
        w: fields.w ?? p.map(() => 1),
        l: copy(DEFAULT_LINE),
      };
    },
  };
}

const circle = nurbsCircle(CIRCLE.centre, CIRCLE.radius);
const circleFields: Partial<BSplineState> = {
  p: circle.points,
  w: circle.weights,
  u: circle.knots,
  d: circle.degree,
  t: 0.1,
};

/** The lesson's script, in the lecture's order. */
export const SCENES: Scene<BSplineState>[] = [
  scene('uniform', 'Uniform cubic B-spline'),
  scene('closed', 'Closed B-spline', { p: CLOSED, t: 0.1 }),
  scene('local', 'Local control', { p: MOVED, q: copy(LONG), t: 0.45 }),
  scene('knots', 'Knots and Cox–de Boor', {
    u: Array.from({ length: n + 4 }, (_, j) => j),
    t: 0.4,
  }),
  scene('clamped', 'Clamped ends', { u: clampedUniformKnots(n, 3), t: 0.05 }),
  scene('repeated', 'Repeated knots', { u: [0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2], t: 0.3 }),
  scene('convert', 'B-spline ↔ Bézier', { t: 0.4 }),
  scene('properties', 'Properties'),
  scene('nurbs', 'NURBS weights', {
    w: ones.map((w, i) => (i === 2 ? 4 : i === 5 ? 0.25 : w)),
    t: 0.3,
  }),
  scene('circle', 'The exact circle', circleFields),
  scene('projective', 'Projective map', circleFields),
];
