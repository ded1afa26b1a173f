import {
  type Point,
  add,
  bezierToHermite,
  convexHull,
  convexHullContains,
  lagrangePoint,
  pointBetween,
  uniformBSplinePoint,
} from '../../math';
import { type Family, SAMPLES, equallySpacedNodes, family } from './families';
import type { Comparison } from './state';

/** The bases compared (interpolating or approximating asks the Lagrange curve). */
type Kind = Exclude<Comparison, 'none' | 'mirror' | 'interpolating'>;

/** Another basis beside Bernstein's, drawn for the control points alone (not yet at μ). */
export interface ComparedShape extends Family {
  kind: Kind;
  /** The dashed curve these functions give with the control points, if they weight points. */
  curve: Point[] | null;
  /** Hermite data of the cubic: P0 → P0 + D0 and P3 → P3 + D3 (for N = 3). */
  arrows: [Point, Point][];
  /** Lagrange: the share of the curve's samples outside the control points' convex hull. */
  outside: number | null;
  /** The convex hull of the control points, in order around it. */
  hull: Point[];
  /** Each function's largest value on [0, 1]. */
  highest: number[];
}

/** Another basis beside Bernstein's, and what it makes of the same control points at μ. */
export interface Compared extends ComparedShape {
  /** Each function's value at μ, and their sum. */
  atMu: number[];
  sum: number;
  /** Its point at μ, where the functions weight these very points. */
  point: { at: Point; label: string } | null;
}

/** The compared basis and its curve for these control points: it does not depend on μ. */
export function comparedShape(p: readonly Point[], comparison: Comparison): ComparedShape | null {
  if (comparison === 'none' || comparison === 'mirror') return null;
  const kind: Kind = comparison === 'interpolating' ? 'lagrange' : comparison;
  const n = p.length - 1;
  const basis = family(kind, n)!;
  let curve: Point[] | null = null;
  if (kind === 'lagrange') {
    // The same samples draw the curve and test it against the hull.
    const nodes = equallySpacedNodes(n);
    curve = Array.from({ length: SAMPLES + 1 }, (_, k) => lagrangePoint(nodes, p, k / SAMPLES));
  } else if (kind === 'bspline' && n >= 3) {
    const count = Math.max(96, 24 * n);
    curve = Array.from({ length: count + 1 }, (_, k) =>
      uniformBSplinePoint(p, (k / count) * (n - 2)),
    );
  }
  return {
    ...basis,
    kind,
    curve,
    arrows: kind === 'hermite' && n === 3 ? hermiteArrows(p) : [],
    outside: kind === 'lagrange' && curve ? shareOutside(p, curve) : null,
    hull: convexHull(p),
    highest: basis.samples.curves.map((c) => {
      let high = -Infinity;
      for (let k = 1; k < c.length; k += 2) high = Math.max(high, c[k]);
      return high;
    }),
  };
}

/** The compared basis at μ: each function's value, and the point it makes, if any. */
export function comparedAt(shape: ComparedShape, p: readonly Point[], mu: number): Compared {
  const n = p.length - 1;
  const atMu = [...shape.values(mu)];
  return {
    ...shape,
    atMu,
    sum: atMu.reduce((a, b) => a + b, 0),
    point:
      shape.kind === 'lagrange'
        ? { at: lagrangePoint(equallySpacedNodes(n), p, mu), label: 'L(μ)' }
        : shape.kind === 'bspline' && n === 3
          ? { at: uniformBSplinePoint(p, mu), label: 'B(μ)' }
          : null,
  };
}

/** The end gradients D0 = 3(P1 − P0) and D3 = 3(P3 − P2) at true length: the H2, H3 data. */
function hermiteArrows(p: readonly Point[]): [Point, Point][] {
  const [x0, d0, x1, d1] = bezierToHermite(p);
  return [
    [x0, add(x0, d0)],
    [x1, add(x1, d1)],
  ];
}

function shareOutside(p: readonly Point[], curve: readonly Point[]): number {
  const hull = convexHull(p);
  return curve.filter((q) => !convexHullContains(hull, q, 1e-9)).length / curve.length;
}

/** The point halfway from `from` to `tip`: a gradient's arrow drawn at half length. */
export const halfway = (from: Point, tip: Point): Point => pointBetween(from, tip, 0.5);
