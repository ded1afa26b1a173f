import { memoOn } from '../../kit/memoOn';
import { coxDeBoorTable, nurbsPoint, type Point } from '../../math';
import { basisRows } from './basisSamples';
import type { Curve, Cursor, KnotJoin, Segment } from './model';
import { sampleRange } from './sampling';
import { type BSplineState, isRationalPart } from './state';

/** The fields a curve on a knot vector reads. */
export type KnotFields = Pick<BSplineState, 'part' | 'points' | 'degree' | 'knots' | 'weights'>;
export const KNOT_FIELDS: readonly (keyof KnotFields)[] = [
  'part',
  'points',
  'degree',
  'knots',
  'weights',
];

/** A curve on a knot vector, and the curve itself as a function of u. */
export interface KnotCurve {
  curve: Curve;
  at(u: number): Point;
}

/**
 * A general B-spline of degree p on the knot vector u, rational from the
 * NURBS scenes on (before them every weight is 1). Built afresh: `knotCurve`
 * keeps the state's; a scene that shows several knot vectors keeps its own.
 */
export function buildKnotCurve(state: KnotFields): KnotCurve {
  const { points, degree, knots } = state;
  const n = points.length;
  const weights = isRationalPart(state.part) ? state.weights : points.map(() => 1);
  const domain: [number, number] = [knots[degree], knots[n]];
  const at = (u: number) => nurbsPoint(points, weights, knots, degree, u);
  const segments: Segment[] = [];
  for (let j = degree; j < n; j++) {
    if (knots[j] === knots[j + 1]) continue;
    segments.push({
      from: knots[j],
      to: knots[j + 1],
      points: Array.from({ length: degree + 1 }, (_, k) => j - degree + k),
      samples: sampleRange(at, knots[j], knots[j + 1]),
    });
  }
  const curve: Curve = {
    control: points,
    owner: points.map((_, i) => i),
    degree,
    knots,
    weights,
    domain,
    segments,
    rows: basisRows(knots, degree),
    start: at(domain[0]),
    end: at(domain[1]),
    joins: knotJoins(knots, degree, n, at),
  };
  return { curve, at };
}

/** The state's curve, kept while the fields it reads are the same. */
export const knotCurve = memoOn<KnotFields, keyof KnotFields, KnotCurve>(
  KNOT_FIELDS,
  buildKnotCurve,
);

/** The cursor at t: u = u_p + t·(u_{m+1} − u_p), its segment, the Cox–de Boor triangle there. */
export function knotCursor({ curve, at }: KnotCurve, t: number): Cursor {
  const { domain, knots, degree, segments } = curve;
  // Within the domain, though u₀ + 1·(u₁ − u₀) can round past its end (−8.831 + 9.561 = 0.7300000000000004).
  const u = Math.min(domain[1], Math.max(domain[0], domain[0] + t * (domain[1] - domain[0])));
  const table = coxDeBoorTable(knots, degree, u);
  let segment = 0;
  while (segment + 1 < segments.length && segments[segment + 1].from <= u) segment++;
  const { from, to } = segments[segment];
  return {
    u,
    segment,
    local: (u - from) / (to - from),
    point: at(u),
    table,
    basis: table[degree],
  };
}

/** Each distinct knot inside the domain: its multiplicity k makes the curve C^(p−k) there. */
export function knotJoins(
  knots: readonly number[],
  degree: number,
  n: number,
  at: (u: number) => Point,
): KnotJoin[] {
  const joins: KnotJoin[] = [];
  for (let j = degree + 1; j < n; j++) {
    if (knots[j] === knots[j - 1] || knots[j] >= knots[n]) continue;
    let multiplicity = 1;
    while (knots[j + multiplicity] === knots[j]) multiplicity++;
    joins.push({
      u: knots[j],
      multiplicity,
      continuity: degree - multiplicity,
      at: at(knots[j]),
      // Knots u_j = … = u_{j+p−1}: every basis function but N_{j−1,p} is 0 there.
      through: multiplicity >= degree ? j - 1 : null,
    });
  }
  return joins;
}

/** Runs of equal knots: [first index, multiplicity]. */
export function knotRuns(knots: readonly number[]): [number, number][] {
  const runs: [number, number][] = [];
  for (let j = 0; j < knots.length; j++) {
    if (j > 0 && knots[j] === knots[j - 1]) runs[runs.length - 1][1]++;
    else runs.push([j, 1]);
  }
  return runs;
}
