import { choice, int, stepField, knots, linkKey, number, points, weights } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';
import { clampedUniformKnots } from '../../math';

/**
 * The parts of the lesson, one per scene (`x=knots` in the link). Five are the
 * uniform cubic B-spline in the slides' matrix form; the others a general knot
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
  | 'projective'
  | 'meanings'
  | 'continuity';

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
  'meanings',
  'continuity',
];

/**
 * Everything the lesson shows, and all of it goes in the link, each field
 * under its one-letter key (`x p q t k d u w l`, in this order).
 */
export interface BSplineState {
  /** Which scene the state is in (`x`). */
  part: Part;
  /** Control points P0 … Pm (`p`). */
  points: Point[];
  /** The control points before the last change, for local control's "before" curve (`q`). */
  before: Point[];
  /**
   * Where the cursor is along the whole curve, 0 … 1: s = (m − 2)·t in the uniform
   * cubic, u = u_p + t·(u_{m+1} − u_p) on a knot vector (`t`).
   */
  t: number;
  /** The step of the scene (`k`). */
  step: number;
  /** Degree p of the general B-spline, in the knot scenes (`d`). */
  degree: number;
  /** The knot vector u_0 … u_{m+p+1} (m + p + 2 knots), in the knot scenes (`u`). */
  knots: number[];
  /** One weight per control point, in the NURBS scenes (`w`). */
  weights: number[];
  /** Two points of the line that tests variation diminishing (`l`). */
  line: Point[];
}

export const MAX_POINTS = 12;
export const MAX_DEGREE = 5;

/**
 * Seven control points that rise, fall and rise again (m + 1 = 7, so m − 2 = 4
 * segments): the open curve most scenes start from. The notes give no numbers.
 */
export const SEVEN_POINTS: Point[] = [
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

/**
 * The scene families: the scenes of one family share their steps and their
 * model (the open and the closed uniform cubic; the three knot scenes).
 */
export type Family =
  | 'uniform'
  | 'local'
  | 'convert'
  | 'properties'
  | 'knots'
  | 'nurbs'
  | 'circle'
  | 'projective'
  | 'meanings'
  | 'continuity';

export const FAMILY: Readonly<Record<Part, Family>> = {
  uniform: 'uniform',
  closed: 'uniform',
  local: 'local',
  convert: 'convert',
  properties: 'properties',
  knots: 'knots',
  clamped: 'knots',
  repeated: 'knots',
  nurbs: 'nurbs',
  circle: 'circle',
  projective: 'projective',
  meanings: 'meanings',
  continuity: 'continuity',
};

const partUses = {
  uniform: new Set<Part>(['uniform', 'closed', 'local', 'convert', 'properties']),
  weights: new Set<Part>(['nurbs', 'circle', 'projective']),
};

/** The uniform cubic in the slides' matrix form: no knot vector or weights of its own. */
export const isUniformPart = (part: Part) => partUses.uniform.has(part);
/** Parts whose weights are not all 1 in general. */
export const isRationalPart = (part: Part) => partUses.weights.has(part);

/** Most knots a link may give: m + p + 2 for the most points (m + 1) and the highest degree. */
export const MAX_KNOTS = MAX_POINTS + MAX_DEGREE + 1;

// The link's keys come in this order, the order they always had.
export const schema: Schema<BSplineState> = {
  part: linkKey(choice({ default: 'uniform', values: PARTS }), 'x'),
  points: linkKey(points({ default: SEVEN_POINTS, min: 3, max: MAX_POINTS }), 'p'),
  before: linkKey(points({ default: [], min: 0, max: MAX_POINTS }), 'q'),
  t: number({ default: 0.35, min: 0, max: 1 }),
  step: linkKey(stepField(), 'k'),
  degree: linkKey(int({ default: 3, min: 1, max: MAX_DEGREE }), 'd'),
  knots: linkKey(knots({ default: [], min: 0, max: MAX_KNOTS, low: -1e3, high: 1e3 }), 'u'),
  weights: linkKey(weights({ default: [], min: 0, max: MAX_POINTS, high: 100 }), 'w'),
  line: linkKey(points({ default: DEFAULT_LINE, min: 2, max: 2 }), 'l'),
};

const copy = (list: readonly Point[]): Point[] => list.map((point) => [...point]);

/** Knots that fit n = m + 1 points of degree p and leave a non-empty domain [u_p, u_{m+1}]. */
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

/**
 * The continuity scene stacks three knots inside a cubic's domain: that takes
 * m + p + 2 ≥ 4 + 3 + 4 knots, so m + 1 ≥ 7 points.
 */
export const CONTINUITY_POINTS = 7;

/** Cross-field rules: points enough for the part, knots and weights that fit the points. */
export function normalize(state: BSplineState): { state: BSplineState; issues: string[] } {
  const issues: string[] = [];
  let next = state;
  const n = next.points.length;
  if (n < 4 && next.part !== 'closed') {
    issues.push(
      `a cubic B-spline needs at least 4 control points, not ${n}; the seven default points are shown`,
    );
    next = { ...next, points: copy(SEVEN_POINTS) };
  } else if (n < CONTINUITY_POINTS && next.part === 'continuity') {
    issues.push(
      `a triple knot inside a cubic’s curve needs at least ${CONTINUITY_POINTS} control points, not ${n}; the seven default points are shown`,
    );
    next = { ...next, points: copy(SEVEN_POINTS) };
  }
  const count = next.points.length;
  if (next.degree > count - 1) {
    issues.push(
      `degree ${next.degree} needs ${next.degree + 1} control points; the degree is now ${count - 1}`,
    );
    next = { ...next, degree: count - 1 };
  }
  if (!knotsFit(next.knots, count, next.degree)) {
    if (next.knots.length > 0) {
      issues.push(
        `u: ${next.knots.length} knots do not fit ${count} points of degree ${next.degree} (${count + next.degree + 1} are needed, with u_${next.degree} < u_${count}); clamped uniform knots are used`,
      );
    }
    next = { ...next, knots: clampedUniformKnots(count, next.degree) };
  }
  if (next.weights.length !== count) {
    if (next.weights.length > 0) {
      issues.push(`w: ${next.weights.length} weights for ${count} points; missing weights are 1`);
    }
    next = { ...next, weights: next.points.map((_, i) => next.weights[i] ?? 1) };
  }
  if (next.before.length !== count) next = { ...next, before: copy(next.points) };
  return { state: next, issues };
}
