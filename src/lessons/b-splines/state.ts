import { choice, int, knots, number, points, weights } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';
import { clampedUniformKnots } from '../../math';

/**
 * The parts of the lesson, one per scene (`x=knots` in the link). The first
 * five are the lecture's uniform cubic B-spline; the others a general knot
 * vector of degree p, with weights from `nurbs` on.
 */
export type Part =
  | 'uniform'
  | 'closed'
  | 'local'
  | 'convert'
  | 'properties'
  | 'knots'
  | 'clamped'
  | 'repeated'
  | 'nurbs'
  | 'circle'
  | 'projective';

export const PARTS: readonly Part[] = [
  'uniform',
  'closed',
  'local',
  'convert',
  'properties',
  'knots',
  'clamped',
  'repeated',
  'nurbs',
  'circle',
  'projective',
];

/** Everything the lesson shows, and all of it goes in the link. */
export interface BSplineState {
  x: Part;
  /** Control points x0 … xm. */
  p: Point[];
  /** The control points before the last change, for local control ("before" curve). */
  q: Point[];
  /** Where the cursor is along the whole curve, 0 … 1 (u = u_p + t·(u_{n} − u_p)). */
  t: number;
  /** The step of the scene. */
  k: number;
  /** Degree p of the general B-spline (knot parts). */
  d: number;
  /** The knot vector u_0 … u_{m+p+1} (knot parts). */
  u: number[];
  /** One weight per control point (NURBS parts). */
  w: number[];
  /** Two points of the line that tests variation diminishing. */
  l: Point[];
}

export const MAX_POINTS = 12;
export const MAX_DEGREE = 5;

/** The lecture's open curve: m + 1 = 7 points, m − 2 = 4 segments. */
export const LECTURE_POINTS: Point[] = [
  [0, 0],
  [1, 3],
  [3, 4],
  [4.5, 1],
  [6.5, 0],
  [8, 3],
  [10, 3.5],
];

export const DEFAULT_LINE: Point[] = [
  [-0.5, 2.2],
  [10.5, 1.6],
];

const partUses = {
  uniform: new Set<Part>(['uniform', 'closed', 'local', 'convert', 'properties']),
  weights: new Set<Part>(['nurbs', 'circle', 'projective']),
};

/** The lecture's uniform cubic (matrix form): no knot vector or weights of its own. */
export const isUniformPart = (x: Part) => partUses.uniform.has(x);
/** Parts whose weights are not all 1 in general. */
export const isRationalPart = (x: Part) => partUses.weights.has(x);

export const schema: Schema<BSplineState> = {
  x: choice({ default: 'uniform', values: PARTS }),
  p: points({ default: LECTURE_POINTS, min: 3, max: MAX_POINTS }),
  q: points({ default: [], min: 0, max: MAX_POINTS }),
  t: number({ default: 0.35, min: 0, max: 1 }),
  k: int({ default: 0, min: 0, max: 20 }),
  d: int({ default: 3, min: 1, max: MAX_DEGREE }),
  u: knots({ default: [], min: 0, max: MAX_POINTS + MAX_DEGREE + 1, low: -1e3, high: 1e3 }),
  w: weights({ default: [], min: 0, max: MAX_POINTS, high: 100 }),
  l: points({ default: DEFAULT_LINE, min: 2, max: 2 }),
};

const copy = (list: readonly Point[]): Point[] => list.map((point) => [...point]);

/** Knots that fit n points of degree p and leave a non-empty domain [u_p, u_n]. */
export function knotsFit(u: readonly number[], n: number, p: number): boolean {
  return u.length === n + p + 1 && u[p] < u[n];
}

/** Both ends clamped: p + 1 equal knots at each end. */
export function isClamped(u: readonly number[], p: number): boolean {
  const last = u.length - 1;
  for (let j = 1; j <= p; j++) {
    if (u[j] !== u[0] || u[last - j] !== u[last]) return false;
  }
  return true;
}

/**
 * The knot vector after a point is added or removed: clamped uniform if it was
 * clamped, else uniform 0, 1, 2, … (what a lecturer would start from again).
 */
export function refitKnots(u: readonly number[], n: number, p: number): number[] {
  if (u.length > p && isClamped(u, p)) return clampedUniformKnots(n, p);
  return Array.from({ length: n + p + 1 }, (_, j) => j);
}

/** Cross-field rules: points enough for the part, knots and weights that fit the points. */
export function normalize(state: BSplineState): { state: BSplineState; issues: string[] } {
  const issues: string[] = [];
  let next = state;
  const n = next.p.length;
  if (n < 4 && next.x !== 'closed') {
    issues.push(
      `a cubic B-spline needs at least 4 control points, not ${n}; the lecture's are shown`,
    );
    next = { ...next, p: copy(LECTURE_POINTS) };
  }
  const count = next.p.length;
  if (next.d > count - 1) {
    issues.push(
      `degree ${next.d} needs ${next.d + 1} control points; the degree is now ${count - 1}`,
    );
    next = { ...next, d: count - 1 };
  }
  if (!knotsFit(next.u, count, next.d)) {
    if (next.u.length > 0) {
      issues.push(
        `u: ${next.u.length} knots do not fit ${count} points of degree ${next.d} (${count + next.d + 1} are needed, with u_${next.d} < u_${count}); clamped uniform knots are used`,
      );
    }
    next = { ...next, u: clampedUniformKnots(count, next.d) };
  }
  if (next.w.length !== count) {
    if (next.w.length > 0) {
      issues.push(`w: ${next.w.length} weights for ${count} points; missing weights are 1`);
    }
    next = { ...next, w: next.p.map((_, i) => next.w[i] ?? 1) };
  }
  if (next.q.length !== count) next = { ...next, q: copy(next.p) };
  return { state: next, issues };
}
