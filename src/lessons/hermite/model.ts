import {
  type BasisSamples,
  type Continuity,
  type Point,
  add,
  bernstein,
  bezierDerivative,
  bezierPoint,
  bezierJointContinuity,
  bezierToPowerBasis,
  catmullRomTangents,
  cubicSplineSegments,
  hermiteBasis,
  hermiteCoefficients,
  hermitePoint,
  sampleBasis,
  scale,
} from '../../math';
import { type Bounds, boundsOf } from '../../render/projection';
import { memoOn } from '../../kit/memoOn';
import type { Revealed } from '../../kit/script';
import type { LectureData } from './formulas';
import { patchNote, pointsNote } from './notes';
import type { Reveal } from './script';
import { type HermiteState, patchCount } from './state';

/** The arrow for a gradient D is drawn D/3 long: its tip is where the Bézier control point sits. */
export const ARROW_SCALE = 1 / 3;

/** H0 … H3 over μ ∈ [0, 1]: the same for every state, so sampled once. */
const BASIS = sampleBasis(hermiteBasis, 200);

/** The chosen patch i: its end data, coefficients (equation 7), point and basis at μ. */
export interface Patch {
  index: number;
  p0: Point;
  p1: Point;
  d0: Point;
  d1: Point;
  /** The end data in the lecture's order (equation 6): Pi, Di, Pi+1, Di+1. */
  data: LectureData;
  /** a0 … a3 of P(μ) = a3μ³ + a2μ² + a1μ + a0. */
  coefficients: Point[];
  /** P(μ) on this patch. */
  point: Point;
  /** H0 … H3 at μ. */
  weights: readonly number[];
  /** The same cubic as a Bézier curve: B0 = Pi, B1 = Pi + Di/3, B2 = Pi+1 − Di+1/3, B3 = Pi+1. */
  bezier: readonly Point[];
  /** The Bézier curve multiplied out (lecture notes, equation 11): a0 … a3 from B0 … B3 alone. */
  power: Point[];
  /** The Bernstein weights of B0 … B3 at μ. */
  bernsteinWeights: readonly number[];
}

export interface Join {
  /** The point where patch k − 1 ends and patch k begins. */
  k: number;
  continuity: Continuity;
  /** dP/dμ at the end of the patch before and the start of the patch after. */
  before: Point;
  after: Point;
}

/** The spline itself: it reads only the points and the gradients, so a step or μ costs no new solve. */
export interface Spline {
  /** The gradients in force: the hand-set ones, or Catmull-Rom's from the neighbours. */
  gradients: Point[];
  /** Where each gradient's arrow ends: Pk + Dk/3 (a handle). */
  tips: Point[];
  /** Every patch as its cubic Bézier control points [Pi, Pi + Di/3, Pi+1 − Di+1/3, Pi+1]. */
  segments: Point[][];
  /** Continuity at every inner point, measured on the patches (not assumed). */
  joins: Join[];
  /** How many joins are C¹ but not C². */
  onlyC1: number;
  /** Every point and every tip: what the label of P(μ) keeps clear of. */
  marks: Point[];
  /** The points, the curve and every tip (each a handle once the gradients are shown). */
  bounds: Bounds;
  /** The same with every patch's Bézier control points: what the Bézier view fits. */
  bezierBounds: Bounds;
  /** Catmull-Rom with two points: both gradients are zero, the patch is a straight segment. */
  straight: boolean;
}

/** Everything the figures and the panel show, computed once per state. */
export interface HermiteModel extends Spline {
  state: HermiteState;
  /** Number of patches, m. */
  m: number;
  /** What the steps so far reveal: the gradients, the basis, how many patches, P(μ), the Bézier view. */
  shown: Revealed<Reveal>;
  patch: Patch;
  /** How many patches the curve shows so far (from the first). */
  built: number;
  /** What "fit" shows: every handle of the scene at every step, the curve, and the Bézier view's points. */
  bounds: Bounds;
  /** Why the figure shows less than one might expect, or null. */
  note: string | null;
  /** H0 … H3 over [0, 1], the same for every state. */
  basis: BasisSamples;
}

export const spline = memoOn<HermiteState, 'points' | 'handGradients' | 'mode', Spline>(
  ['points', 'handGradients', 'mode'],
  ({ points, handGradients, mode }) => {
    const gradients = mode === 'hand' ? handGradients : catmullRomTangents(points);
    const tips = points.map((p, k) => add(p, scale(gradients[k], ARROW_SCALE)));
    const segments = cubicSplineSegments(points, gradients);
    const joins = measureJoins(segments);
    return {
      gradients,
      tips,
      segments,
      joins,
      onlyC1: joins.filter((join) => join.continuity === 'C1').length,
      marks: points.flatMap((p, k) => [p, tips[k]]),
      ...fitBounds(points, tips, segments),
      straight: mode === 'catmull-rom' && points.length === 2,
    };
  },
);

export function derive(state: HermiteState, shown: Revealed<Reveal>): HermiteModel {
  const curve = spline(state);
  const m = patchCount(state);
  // While the patches are built one by one, the matrix and P(μ) are about the newest.
  const index = shown.is('patch') ? shown.index - 1 : state.patch;
  return {
    ...curve,
    state,
    m,
    shown,
    patch: patchAt(state, index, curve),
    built: state.bezier ? (shown.has('curve') ? m : 0) : shown.count('patch'),
    bounds: state.bezier ? curve.bezierBounds : curve.bounds,
    note:
      patchNote(state.points, index, curve.gradients) ?? pointsNote(state.points, curve.straight),
    basis: BASIS,
  };
}

function patchAt(state: HermiteState, i: number, { gradients, segments }: Spline): Patch {
  const [p0, p1, d0, d1] = [state.points[i], state.points[i + 1], gradients[i], gradients[i + 1]];
  return {
    index: i,
    p0,
    p1,
    d0,
    d1,
    data: [p0, d0, p1, d1],
    coefficients: hermiteCoefficients(p0, d0, p1, d1),
    point: hermitePoint(p0, d0, p1, d1, state.mu),
    weights: hermiteBasis(state.mu),
    bezier: segments[i],
    power: bezierToPowerBasis(segments[i]),
    bernsteinWeights: [0, 1, 2, 3].map((k) => bernstein(3, k, state.mu)),
  };
}

function measureJoins(segments: readonly Point[][]): Join[] {
  const hodographs = segments.map((segment) => bezierDerivative(segment));
  return segments.slice(1).map((right, j) => ({
    k: j + 1,
    continuity: bezierJointContinuity(segments[j], right),
    before: hodographs[j][hodographs[j].length - 1],
    after: hodographs[j + 1][0],
  }));
}

/** Points of the curve sampled per patch for "fit", besides its end points. */
const FIT_SAMPLES = 16;

/**
 * What "fit" shows: the points, the curve and every gradient's tip, which is
 * a handle to drag (a tip left off the figure cannot be grabbed); for the
 * Bézier view, every patch's control points too. The same at every step, so
 * the figure does not jump as the clicker reveals the gradients.
 */
function fitBounds(
  p: readonly Point[],
  tips: readonly Point[],
  segments: readonly Point[][],
): { bounds: Bounds; bezierBounds: Bounds } {
  const shown: Point[] = [...p, ...tips];
  for (const segment of segments)
    for (let sample = 1; sample < FIT_SAMPLES; sample++)
      shown.push(bezierPoint(segment, sample / FIT_SAMPLES));
  return {
    bounds: boundsOf(shown),
    bezierBounds: boundsOf([...shown, ...segments.flatMap((segment) => segment.slice(1, 3))]),
  };
}
