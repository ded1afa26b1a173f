import {
  type Point,
  add,
  bezierBasisMatrix,
  bezierPoint,
  bezierToHermite,
  convexHull,
  convexHullContains,
  lagrangePoint,
  sampleBezier,
  uniformBSplinePoint,
} from '../../math';
import { type Bounds, boundsOf } from '../../render/projection';
import { degenerate, repeatsText } from '../../kit/degenerate';
import { type Family, SAMPLES, equallySpacedNodes, family } from './families';
import { type BlendingState, type Comparison, type Revealed, degree, revealed } from './state';

/** Another basis beside Bernstein's, and what it makes of the same control points. */
export interface Compared extends Family {
  kind: Exclude<Comparison, 'none'>;
  /** Each function's value at μ, and their sum. */
  atMu: number[];
  sum: number;
  /** The dashed curve these functions give with the control points, if they weight points. */
  curve: Point[] | null;
  /** Its point at μ, where the functions weight these very points. */
  point: { at: Point; label: string } | null;
  /** Hermite data of the cubic: x0 → x0 + x0′ and x1 → x1 + x1′ (for N = 3). */
  arrows: [Point, Point][];
  /** Lagrange: the share of the curve's samples outside the control points' convex hull. */
  outside: number | null;
}

/** Everything the figures and the panel show, computed once per state. */
export interface BlendingModel {
  state: BlendingState;
  /** Degree N. */
  n: number;
  /** What the step shows. */
  shown: Revealed;
  bernstein: Family;
  /** W(N, i, μ) for every i, and their sum (1 up to rounding). */
  weights: number[];
  sum: number;
  /** P(μ), and the curve sampled (interleaved x, y). */
  point: Point;
  curve: Float64Array;
  compared: Compared | null;
  /** x(0.5): the curve's middle, the binomially weighted centroid. */
  centre: Point;
  /** M of x(u) = U M X. */
  matrix: number[][];
  /** What "fit" shows in the curve figure, and the plot's range. */
  curveBounds: Bounds;
  plotBounds: Bounds;
  /** Height of the plot cursor's handle: at the top, clear of the curves. */
  handleY: number;
  /** What is degenerate about the control points and what it does to the curve, or null. */
  note: string | null;
}

export function derive(state: BlendingState): BlendingModel {
  const n = degree(state);
  const bernstein = family('bernstein', n)!;
  const weights = [...bernstein.values(state.mu)];
  const compared = compare(state, n);
  const plotBounds = plotRange(compared);
  return {
    state,
    n,
    shown: revealed(state),
    bernstein,
    weights,
    sum: weights.reduce((a, b) => a + b, 0),
    point: bezierPoint(state.p, state.mu),
    curve: sampleBezier(state.p, Math.max(64, 24 * n)),
    compared,
    centre: bezierPoint(state.p, 0.5),
    matrix: bezierBasisMatrix(n),
    curveBounds: boundsOf([
      ...state.p,
      ...(compared?.curve ?? []),
      ...(compared?.arrows.map(([, tip]) => tip) ?? []),
    ]),
    plotBounds,
    handleY: plotBounds.maxY - 0.05 * (plotBounds.maxY - plotBounds.minY),
    note: noteFor(state.p),
  };
}

/** Coincident or collinear control points, in words: what the curve does then. */
function noteFor(p: readonly Point[]): string | null {
  const { allSame, collinear, repeats } = degenerate(p);
  if (allSame)
    return 'All control points are on one spot: every weighted average of them is that spot, so the whole curve is one point.';
  const notes: string[] = [];
  if (collinear)
    notes.push(
      'The control points lie on one line: an average of points on a line is on that line, so the curve is a stretch of it (it may run back along it).',
    );
  if (repeats.length)
    notes.push(
      `${repeatsText(repeats)}: that spot carries the weights of both points, so the curve is pulled harder towards it.`,
    );
  return notes.length ? notes.join(' ') : null;
}

function compare(state: BlendingState, n: number): Compared | null {
  if (state.b === 'none') return null;
  const basis = family(state.b, n)!;
  const atMu = [...basis.values(state.mu)];
  const nodes = equallySpacedNodes(n);
  const lagrange = state.b === 'lagrange';
  let curve: Point[] | null = null;
  if (lagrange) {
    // The same samples draw the curve and test it against the hull.
    curve = Array.from({ length: SAMPLES + 1 }, (_, k) =>
      lagrangePoint(nodes, state.p, k / SAMPLES),
    );
  } else if (state.b === 'bspline' && n >= 3) {
    const count = Math.max(96, 24 * n);
    curve = Array.from({ length: count + 1 }, (_, k) =>
      uniformBSplinePoint(state.p, (k / count) * (n - 2)),
    );
  }
  return {
    ...basis,
    kind: state.b,
    atMu,
    sum: atMu.reduce((a, b) => a + b, 0),
    curve,
    point: lagrange
      ? { at: lagrangePoint(nodes, state.p, state.mu), label: 'L(μ)' }
      : state.b === 'bspline' && n === 3
        ? { at: uniformBSplinePoint(state.p, state.mu), label: 'B(μ)' }
        : null,
    arrows: state.b === 'hermite' && n === 3 ? hermiteArrows(state.p) : [],
    outside: lagrange && curve ? shareOutside(state.p, curve) : null,
  };
}

/** The end tangents x0′ = 3(P1 − P0) and x1′ = 3(P3 − P2) at true length: the H2, H3 data. */
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

/** μ from 0 to 1; W from its lowest to its highest value, with room for the cursor's handle. */
function plotRange(compared: Compared | null): Bounds {
  const low = Math.min(0, compared?.samples.lowest.value ?? 0);
  const high = Math.max(1, compared?.samples.highest.value ?? 1);
  const span = high - low;
  return { minX: 0, maxX: 1, minY: low - 0.04 * span, maxY: high + 0.16 * span };
}
