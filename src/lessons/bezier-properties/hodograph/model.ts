import { memoOn } from '../../../kit/memoOn';
import {
  type Point,
  add,
  bernstein,
  bezierDerivative,
  bezierPoint,
  bezierTangent,
  deCasteljau,
  distance,
  scale,
  subtract,
} from '../../../math';
import { type ExperimentBase, sampleCurve } from '../curve';
import type { PropertiesState } from '../state';

export interface HodographModel extends ExperimentBase {
  kind: 'hodograph';
  /** Degree n of the curve. */
  n: number;
  curve: Float64Array;
  /** The legs of the polygon as vectors, P_{i+1} − P_i. */
  differences: Point[];
  /** The derivative's control points n(P_{i+1} − P_i): a Bézier curve of degree n − 1. */
  hodograph: Point[];
  /** The point beside the curve that the vectors are drawn from. */
  origin: Point;
  /** The legs and the derivative's control points drawn from the origin, and its curve there. */
  placedDifferences: Point[];
  placed: Point[];
  placedCurve: Float64Array;
  /** The weights W(n − 1, i, t) of the derivative's control points at t. */
  weights: number[];
  point: Point;
  /** P′(t) from the derivative curve: Σ W(n − 1, i, t) n(P_{i+1} − P_i). */
  derivative: Point;
  /** The construction's last edge, P_{n−1,0} to P_{n−1,1}: the tangent at P(t). */
  edge: [Point, Point];
  /** n(P_{n−1,1} − P_{n−1,0}): P′(t) from the tangent of the construction. */
  fromEdge: Point;
  /** Largest distance of P′(t) from the edge's n(P_{n−1,1} − P_{n−1,0}) and from the maths' bezierTangent. */
  disagreement: number;
}

/** Where the vectors start: right of the control points, clear of them, at their middle height. */
function originBeside(points: readonly Point[], vectors: readonly Point[]): Point {
  const span = (values: number[]) => [Math.min(...values), Math.max(...values)];
  const [left, right] = span(points.map((q) => q[0]));
  const [low, high] = span(points.map((q) => q[1]));
  const [vectorLeft] = span([0, ...vectors.map((v) => v[0])]);
  const [vectorLow, vectorHigh] = span([0, ...vectors.map((v) => v[1])]);
  const gap = 0.3 * Math.max(right - left, high - low, 1);
  return [right + gap - vectorLeft, (low + high) / 2 - (vectorLow + vectorHigh) / 2];
}

export const deriveHodograph = memoOn<PropertiesState, 'points' | 't', HodographModel>(
  ['points', 't'],
  ({ points: controls, t }) => {
    const n = controls.length - 1;
    const differences = controls.slice(1).map((q, i) => subtract(q, controls[i]));
    const hodograph = bezierDerivative(controls);
    const origin = originBeside(controls, hodograph);
    const placed = hodograph.map((v) => add(origin, v));
    const levels = deCasteljau(controls, t);
    const edge: [Point, Point] = [levels[n - 1][0], levels[n - 1][1]];
    const fromEdge = scale(subtract(edge[1], edge[0]), n);
    const derivative = bezierPoint(hodograph, t);
    const point = levels[n][0];
    return {
      kind: 'hodograph',
      controls,
      extra: [origin, ...placed, add(point, derivative)],
      n,
      curve: sampleCurve(controls),
      differences,
      hodograph,
      origin,
      placedDifferences: differences.map((d) => add(origin, d)),
      placed,
      placedCurve: sampleCurve(placed),
      weights: hodograph.map((_, i) => bernstein(n - 1, i, t)),
      point,
      derivative,
      edge,
      fromEdge,
      disagreement: Math.max(
        distance(derivative, fromEdge),
        distance(derivative, bezierTangent(controls, t)),
      ),
    };
  },
);
