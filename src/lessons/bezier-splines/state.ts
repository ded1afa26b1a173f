import { choice, stepField, linkKey, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';
import { catmullRomTangents, cubicSplineC2 } from '../../math';

/** The parts of the lesson, one scene each, in teaching order. */
export type Part =
  'why' | 'quadratic' | 'system' | 'grid' | 'inspector' | 'catmull' | 'worked' | 'degree';
export const PARTS: readonly Part[] = [
  'why',
  'quadratic',
  'system',
  'grid',
  'inspector',
  'catmull',
  'worked',
  'degree',
];

/**
 * Everything the lesson shows; all of it goes in the link. Each field keeps
 * its short link key (`p`, `b`, `q`, `inf`, `spi`, `semi`, `tg`).
 */
export interface BezierSplinesState {
  part: Part;
  /** Step of the current part's construction (0 = only the given points). */
  step: number;
  /** The points p0 … pn the spline passes through (parts 1, 2, 3, 6, 7 and 8). */
  points: Point[];
  /** The chosen first inner control point b0 of the C¹ quadratic spline. */
  firstControl: Point[];
  /** The hand-built piecewise cubic: 3k + 1 control points, joints at every third. */
  handBuilt: Point[];
  /** The three datasets of the practical's figure. */
  infinity: Point[];
  spiral: Point[];
  semicircle: Point[];
  /** Hand-set tangents T_i at p_i for the Hermite spline (part 6). */
  tangents: Point[];
}

export const MAX_POINTS = 12;

const round = (p: Point): Point => p.map((v) => Math.round(v * 100) / 100);

/** Six points with a bend and a rise: the C¹ quadratic spline swings visibly through them. */
export const LECTURE_POINTS: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2.5],
  [4, 0.5],
  [6, 1],
  [7, 3],
];

/** The practical's four points A, D, G, J. */
export const FOUR_POINTS: Point[] = [
  [0, 0],
  [1, 2.5],
  [4, 2.5],
  [5, 0],
];

/** A hairpin: two points close together between far ones (uniform Catmull-Rom loops there). */
export const HAIRPIN: Point[] = [
  [0, 0],
  [3, 1],
  [3, 1.2],
  [0, 2.5],
];

/** Figure eight (lemniscate of Gerono), 9 points, the first repeated at the end. */
export const INFINITY: Point[] = Array.from({ length: 9 }, (_, k) => {
  const theta = (k * Math.PI) / 4;
  return round([3 * Math.cos(theta), 1.5 * Math.sin(2 * theta)]);
});

/** An Archimedean spiral r = 0.4 + 0.3θ, 10 points. */
export const SPIRAL: Point[] = Array.from({ length: 10 }, (_, k) => {
  const theta = (k * 3 * Math.PI) / 9;
  const r = 0.4 + 0.3 * theta;
  return round([r * Math.cos(theta), r * Math.sin(theta)]);
});

/** A half circle of radius 3, 7 points. */
export const SEMI: Point[] = Array.from({ length: 7 }, (_, k) => {
  const theta = Math.PI - (k * Math.PI) / 6;
  return round([3 * Math.cos(theta), 3 * Math.sin(theta)]);
});

/** Three pieces built by hand: a C² joint, then a G¹ joint (length ratio ½). */
export const HAND_BUILT: Point[] = [
  [0, 0],
  [1, 2],
  [2, 2.5],
  [3, 2],
  [4, 1.5],
  [5, 0],
  [6, 1],
  [6.5, 1.5],
  [8, 3],
  [9, 2],
];

export const midpoint = (a: Point, b: Point): Point => [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];

/** Hand-set tangents to start from: the Catmull-Rom ones, turned and stretched, so they visibly differ. */
export const handTangents = (p: readonly Point[]): Point[] =>
  catmullRomTangents(p).map(([x, y], i) =>
    i === 0 || i === p.length - 1 ? [1.5, 1.5] : round([1.6 * x - 0.6 * y, 0.6 * x + 1.6 * y]),
  );

// In schema order: the link writes its fields in this order.
export const schema: Schema<BezierSplinesState> = {
  part: choice({ default: 'why', values: PARTS }),
  step: stepField(),
  points: linkKey(points({ default: LECTURE_POINTS, min: 2, max: MAX_POINTS }), 'p'),
  firstControl: linkKey(
    points({ default: [midpoint(LECTURE_POINTS[0], LECTURE_POINTS[1])], min: 1, max: 1 }),
    'b',
  ),
  handBuilt: linkKey(points({ default: HAND_BUILT, min: 4, max: 3 * 6 + 1 }), 'q'),
  infinity: linkKey(points({ default: INFINITY, min: 2, max: 16 }), 'inf'),
  spiral: linkKey(points({ default: SPIRAL, min: 2, max: 16 }), 'spi'),
  semicircle: linkKey(points({ default: SEMI, min: 2, max: 16 }), 'semi'),
  tangents: linkKey(
    points({ default: handTangents(LECTURE_POINTS), min: 2, max: MAX_POINTS }),
    'tg',
  ),
};

/** The hand-built spline needs 3k + 1 points and one tangent per point. */
export function normalize(state: BezierSplinesState): {
  state: BezierSplinesState;
  issues: string[];
} {
  const issues: string[] = [];
  let next = state;
  const extra = (state.handBuilt.length - 1) % 3;
  if (extra !== 0) {
    issues.push('q: a piecewise cubic has 3k + 1 control points; the last ones were dropped');
    next = { ...next, handBuilt: state.handBuilt.slice(0, state.handBuilt.length - extra) };
  }
  if (next.tangents.length !== next.points.length) {
    const fallback = handTangents(next.points);
    next = { ...next, tangents: next.points.map((_, i) => next.tangents[i] ?? fallback[i]) };
  }
  return { state: next, issues };
}

/** The C² spline through the joints of the hand-built spline, as its control points. */
export const c2ControlPoints = (joints: readonly Point[]): Point[] => {
  const segments = cubicSplineC2(joints);
  return [joints[0], ...segments.flatMap((s) => s.slice(1))];
};
