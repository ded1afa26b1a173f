import { type Point, bernsteinBasis, nearestOnBezierPieces, solveDense } from '../../math';

// Does a curve pass through its points? Each control point's distance to the
// curve, min over μ of |C(μ) − Pᵢ|, found exactly on the curve's Bézier form
// (nearestOnBezierPieces): 0 where the curve passes through the point.

/** Where a control point is nearest to a curve, and how far. */
export interface Nearest {
  /** The curve's point nearest to the control point. */
  point: Point;
  distance: number;
}

/** The distances of every control point to the Lagrange curve and to the Bézier curve. */
export interface Passes {
  /** The Lagrange curve of the points on the nodes μ = i/N, as one Bézier curve of degree N. */
  lagrangeControls: Point[];
  lagrange: Nearest[];
  bezier: Nearest[];
  /** Which points each curve passes through (distance 0 up to rounding). */
  onLagrange: boolean[];
  onBezier: boolean[];
}

/**
 * The Lagrange curve through Pᵢ at μ = i/N (equally spaced nodes, as the
 * Compare scene's) is a polynomial of degree N, so it is a Bézier curve of
 * degree N: its control points B solve Σₖ W(N, k, i/N) Bₖ = Pᵢ for every i.
 */
export function lagrangeAsBezier(p: readonly Point[]): Point[] {
  const n = p.length - 1;
  if (n === 0) return [p[0].slice()];
  const rows = Array.from({ length: n + 1 }, (_, i) => bernsteinBasis(n, i / n));
  return solveDense(rows, p);
}

/** Each point's nearest point on the Bézier curve of `controls`, and its distance. */
export function nearestTo(controls: readonly Point[], p: readonly Point[]): Nearest[] {
  return p.map((q) => {
    const found = nearestOnBezierPieces([controls], q)!;
    return { point: found.point, distance: found.distance };
  });
}

/** Below this share of the points' extent a distance is rounding: the curve passes through. */
const ON_CURVE = 1e-9;

/** Both curves' distances to every control point. */
export function passes(p: readonly Point[]): Passes {
  const lagrangeControls = lagrangeAsBezier(p);
  const lagrange = nearestTo(lagrangeControls, p);
  const bezier = nearestTo(p, p);
  const extent = Math.max(
    1,
    ...p.flatMap((q) => p.map((r) => Math.hypot(q[0] - r[0], q[1] - r[1]))),
  );
  const on = (list: Nearest[]) => list.map((near) => near.distance <= ON_CURVE * extent);
  return {
    lagrangeControls,
    lagrange,
    bezier,
    onLagrange: on(lagrange),
    onBezier: on(bezier),
  };
}
