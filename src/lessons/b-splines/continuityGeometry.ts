import { memoOn } from '../../kit/memoOn';
import { type Point, uniformKnots } from '../../math';
import { type KnotCurve, buildKnotCurve } from './knotGeometry';
import type { BSplineState } from './state';

/** The curves the continuity scene steps through, each named after its step. */
export type ContinuityCase = 'linear' | 'quadratic' | 'cubic' | 'double' | 'triple';
export const CONTINUITY_CASES: readonly ContinuityCase[] = [
  'linear',
  'quadratic',
  'cubic',
  'double',
  'triple',
];

/** Two sides of a derivative count as equal within this, relative to their size (≥ 1). */
export const AGREE = 1e-9;

/** A knot inside the curve, seen from the piece before it and the piece after it. */
export interface JoinCheck {
  u: number;
  multiplicity: number;
  /** P(u), P′(u), … P⁽ᵖ⁾(u) of the piece that ends at u: left[r] is the r-th derivative. */
  left: Point[];
  /** The same of the piece that starts at u. */
  right: Point[];
  /** right[r] equals left[r] (within AGREE). */
  agree: boolean[];
  /** Derivatives 0 … smooth agree, smooth + 1 does not: C^smooth there (−1: the curve breaks; Infinity: one polynomial). */
  smooth: number;
  /** What the degree and the multiplicity promise: p − multiplicity. */
  promised: number;
  /** Indices into the curve's segments of the piece before and the piece after. */
  before: number;
  after: number;
  at: Point;
  /** The control point the curve passes through there (multiplicity ≥ p), else null. */
  through: number | null;
}

/**
 * The derivatives 0 … p at `join` of the curve's polynomial piece on [from, to]
 * (`join` is one of its ends): the polynomial through p + 1 points of the piece
 * computed by `at` strictly inside it (so from that piece alone, never its
 * neighbour), in Newton's form, expanded in powers of (u − join). A piece of
 * degree p is that polynomial, so this is exact up to rounding.
 */
export function pieceDerivatives(
  at: (u: number) => Point,
  from: number,
  to: number,
  join: number,
  degree: number,
): Point[] {
  const width = to - from;
  // x = (u − join)/width: the nodes lie within (−1, 1), so no power of x grows.
  const xs = Array.from(
    { length: degree + 1 },
    (_, k) => (from + (width * (k + 1)) / (degree + 2) - join) / width,
  );
  const values = xs.map((x) => at(join + x * width));
  const derivatives = Array.from({ length: degree + 1 }, () =>
    new Array<number>(values[0].length).fill(0),
  );
  values[0].forEach((_, d) => {
    // Divided differences in place: c[k] = f[x0 … xk].
    const c = values.map((v) => v[d]);
    for (let level = 1; level <= degree; level++)
      for (let k = degree; k >= level; k--) c[k] = (c[k] - c[k - 1]) / (xs[k] - xs[k - level]);
    // c0 + c1(x − x0) + c2(x − x0)(x − x1) + … as Σ aᵢxⁱ, by Horner from the top.
    let power = [c[degree]];
    for (let k = degree - 1; k >= 0; k--) {
      const next = new Array<number>(power.length + 1).fill(0);
      power.forEach((a, i) => {
        next[i + 1] += a;
        next[i] -= a * xs[k];
      });
      next[0] += c[k];
      power = next;
    }
    // dʳ/duʳ of Σ aᵢxⁱ at x = 0 is r!·aᵣ/widthʳ.
    let factorial = 1;
    for (let r = 0; r <= degree; r++) {
      factorial *= Math.max(r, 1);
      derivatives[r][d] = (factorial * power[r]) / width ** r;
    }
  });
  return derivatives;
}

/** Two vectors equal within AGREE, relative to the larger (as the maths' bezierJointContinuity counts). */
export function same(a: readonly number[], b: readonly number[]): boolean {
  let difference = 0;
  let size = 1;
  a.forEach((value, d) => {
    difference = Math.max(difference, Math.abs(value - b[d]));
    size = Math.max(size, Math.abs(value), Math.abs(b[d]));
  });
  return difference <= AGREE * size;
}

/** Every knot inside the curve, its two sides' derivatives compared. */
export function joinChecks({ curve, at }: KnotCurve): JoinCheck[] {
  const { segments, degree } = curve;
  return curve.joins.map((join) => {
    const before = segments.findIndex((s) => s.to === join.u);
    const after = segments.findIndex((s) => s.from === join.u);
    const left = pieceDerivatives(at, segments[before].from, join.u, join.u, degree);
    const right = pieceDerivatives(at, join.u, segments[after].to, join.u, degree);
    const agree = left.map((l, r) => same(l, right[r]));
    const first = agree.indexOf(false);
    return {
      u: join.u,
      multiplicity: join.multiplicity,
      left,
      right,
      agree,
      smooth: first < 0 ? Infinity : first - 1,
      promised: join.continuity,
      before,
      after,
      at: join.at,
      through: join.through,
    };
  });
}

/**
 * The knot the scene watches: inside every case's curve, with a knot on each
 * side to stack onto it (u = 5 for seven points). Needs m + 1 ≥ 7 points.
 */
export const watchedKnot = (n: number) => Math.floor((n + 3) / 2);

/** Each case's degree and knots: uniform knots 0, 1, …, then one or two knots moved onto the watched one. */
export function caseKnots(n: number, name: ContinuityCase): { degree: number; knots: number[] } {
  if (name === 'linear') return { degree: 1, knots: uniformKnots(n, 1) };
  if (name === 'quadratic') return { degree: 2, knots: uniformKnots(n, 2) };
  const knots = uniformKnots(n, 3);
  const c = watchedKnot(n);
  // On uniform knots u(j) = j: a double knot moves u(c+1) onto u(c), a triple u(c−1) too.
  if (name !== 'cubic') knots[c + 1] = c;
  if (name === 'triple') knots[c - 1] = c;
  return { degree: 3, knots };
}

export interface ContinuityCurve {
  curve: KnotCurve;
  checks: JoinCheck[];
  /** The check at the watched knot. */
  watched: JoinCheck;
}

/** All five cases for the state's points, made once per set of points: a step costs nothing. */
export const continuityCurves = memoOn<
  BSplineState,
  'points',
  Record<ContinuityCase, ContinuityCurve>
>(['points'], ({ points }) => {
  const n = points.length;
  const weights = points.map(() => 1);
  const entries = CONTINUITY_CASES.map((name) => {
    const curve = buildKnotCurve({ part: 'continuity', points, weights, ...caseKnots(n, name) });
    const checks = joinChecks(curve);
    const watched = checks.find((check) => check.u === watchedKnot(n))!;
    return [name, { curve, checks, watched }] as const;
  });
  return Object.fromEntries(entries) as Record<ContinuityCase, ContinuityCurve>;
});
