import {
  type Point,
  catmullRomSegments,
  catmullRomTangents,
  clampedCubicTangents,
  closedCubicTangents,
  cubicSplineSegments,
  elevateDegree,
  lagrangePoint,
  naturalCubicTangents,
  quadraticSplineC1,
  uniformBSplineSegments,
} from '../../math';
import type { RoadInputs, RoadMethod } from './state';

/** Every answer the lesson can draw: the six methods, then the comparisons of the overlay. */
export type CurveId =
  | RoadMethod
  | 'lagrange'
  | 'catmull-uniform'
  | 'catmull-centripetal'
  | 'catmull-chordal'
  | 'bspline';

export interface CurveInfo {
  id: CurveId;
  /** Name in the method list and the legend. */
  name: string;
  /** Dash pattern in the overlay (with the colour, so 11 curves stay apart in print). */
  dash: number[];
}

/** The index in this list is the curve's number in the link (`compare=0,3,6`). */
export const CURVES: readonly CurveInfo[] = [
  { id: 'roman', name: 'Roman road (straight)', dash: [] },
  { id: 'quadratic', name: 'Quadratic pieces, C¹', dash: [] },
  { id: 'hermite', name: 'Hermite, parabola gradients, C¹', dash: [] },
  { id: 'natural', name: 'Natural cubic spline, C²', dash: [] },
  { id: 'clamped', name: 'Clamped cubic spline, C²', dash: [] },
  { id: 'ring', name: 'Ring road (closed spline)', dash: [] },
  { id: 'lagrange', name: 'Lagrange polynomial', dash: [2, 4] },
  { id: 'catmull-uniform', name: 'Catmull-Rom α = 0 (uniform)', dash: [10, 5] },
  { id: 'catmull-centripetal', name: 'Catmull-Rom α = ½ (centripetal)', dash: [10, 4, 2, 4] },
  { id: 'catmull-chordal', name: 'Catmull-Rom α = 1 (chordal)', dash: [4, 4] },
  { id: 'bspline', name: 'Cubic B-spline (approximating)', dash: [14, 6] },
];

/** Above this many villages the Lagrange polynomial is not drawn (its values overflow the map). */
export const LAGRANGE_LIMIT = 30;
const LAGRANGE_SAMPLES_PER_SEGMENT = 24;

/**
 * A road as the maths returns it: Bézier pieces (degree 1, 2 or 3, one per
 * segment, piece i for p̄ ∈ [i, i+1]); or, for the Lagrange polynomial, a
 * sampled polyline; or nothing, with the reason in words.
 */
export type Road =
  | { kind: 'pieces'; pieces: Point[][]; closed: boolean }
  | { kind: 'polyline'; coords: Float64Array }
  | { kind: 'missing'; why: string };

/** Pieces of degree 1 or 2 as the cubics they equal, so every road draws as exact cubics. */
export function asCubics(pieces: readonly Point[][]): Point[][] {
  return pieces.map((piece) => {
    let cubic = piece;
    while (cubic.length < 4) cubic = elevateDegree(cubic);
    return cubic;
  });
}

/** The first control point of the quadratic pieces: P0 + D0/2 (a quadratic's P′(0) = 2(B0 − P0)). */
export const quadraticControl = (state: RoadInputs): Point => [
  state.villages[0][0] + state.quadraticGradient[0] / 2,
  state.villages[0][1] + state.quadraticGradient[1] / 2,
];

/** The gradients D0 … Dm a Hermite-type method uses (undefined for the others). */
export function roadGradients(id: CurveId, state: RoadInputs): Point[] | undefined {
  const v = state.villages;
  switch (id) {
    case 'hermite': {
      // Parabola through P(i−1), Pi, P(i+1) at p̄ = i−1, i, i+1: its gradient at Pi
      // is (P(i+1) − P(i−1))/2, which is the uniform Catmull-Rom gradient.
      const tangents = catmullRomTangents(v);
      if (state.ends) {
        tangents[0] = state.startGradient;
        tangents[tangents.length - 1] = state.endGradient;
      }
      return tangents;
    }
    case 'natural':
      return naturalCubicTangents(v);
    case 'clamped':
      return clampedCubicTangents(v, state.startGradient, state.endGradient);
    case 'ring':
      return v.length >= 3 ? closedCubicTangents(v) : undefined;
    default:
      return undefined;
  }
}

/**
 * The road a curve draws through the state's villages; a Hermite-type curve
 * uses `gradients` when given (the ones the lesson's solve found), else its own.
 */
export function buildRoad(
  id: CurveId,
  state: RoadInputs,
  gradients: readonly Point[] | undefined = roadGradients(id, state),
): Road {
  const v = state.villages;
  const n = v.length;
  switch (id) {
    case 'roman': {
      const pieces: Point[][] = [];
      for (let i = 0; i + 1 < n; i++) pieces.push([v[i], v[i + 1]]);
      return { kind: 'pieces', pieces, closed: false };
    }
    case 'quadratic':
      return {
        kind: 'pieces',
        pieces: quadraticSplineC1(v, quadraticControl(state)),
        closed: false,
      };
    case 'hermite':
    case 'natural':
    case 'clamped':
      return {
        kind: 'pieces',
        pieces: cubicSplineSegments(v, gradients!),
        closed: false,
      };
    case 'ring':
      if (n < 3) {
        return {
          kind: 'missing',
          why: 'A ring road needs at least three villages: with two it would only go there and back.',
        };
      }
      return {
        kind: 'pieces',
        pieces: cubicSplineSegments(v, gradients!, true),
        closed: true,
      };
    case 'lagrange':
      return lagrangeRoad(v);
    case 'catmull-uniform':
      return { kind: 'pieces', pieces: catmullRomSegments(v, 0), closed: false };
    case 'catmull-centripetal':
      return { kind: 'pieces', pieces: catmullRomSegments(v, 0.5), closed: false };
    case 'catmull-chordal':
      return { kind: 'pieces', pieces: catmullRomSegments(v, 1), closed: false };
    case 'bspline':
      if (n < 4) {
        return {
          kind: 'missing',
          why: 'The cubic B-spline needs at least four villages as control points.',
        };
      }
      return { kind: 'pieces', pieces: uniformBSplineSegments(v), closed: false };
  }
}

/** The map is at most this far from the villages: a wild polynomial is cut off beyond it. */
const FAR = 1e6;

function lagrangeRoad(v: readonly Point[]): Road {
  const n = v.length;
  if (n > LAGRANGE_LIMIT) {
    return {
      kind: 'missing',
      why: `The Lagrange polynomial through ${n} villages has degree ${n - 1}; between the outer villages it swings so far off the map that it is not drawn above ${LAGRANGE_LIMIT} villages.`,
    };
  }
  // The lecture's parameter: village k at p̄ = k.
  const ts = v.map((_, k) => k);
  const steps = (n - 1) * LAGRANGE_SAMPLES_PER_SEGMENT;
  const coords = new Float64Array(2 * (steps + 1));
  for (let j = 0; j <= steps; j++) {
    const p = lagrangePoint(ts, v, j / LAGRANGE_SAMPLES_PER_SEGMENT);
    coords[2 * j] = Math.max(-FAR, Math.min(FAR, p[0]));
    coords[2 * j + 1] = Math.max(-FAR, Math.min(FAR, p[1]));
  }
  return { kind: 'polyline', coords };
}
