import {
  type BasisSamples,
  bezierPoint,
  clipToBand,
  cubicSplineSegments,
  lagrangeBasis,
  lebesgueConstant,
  naturalCubicTangents,
  parameterValues,
  type Point,
  sampleBasis,
} from '../../math';
import { type Bounds, boundsOf, unionBounds } from '../../render/projection';
import { degenerate, repeatsText } from '../../kit/degenerate';
import { memoOn } from '../../kit/memoOn';
import type { Revealed } from '../../kit/script';
import type { Reveal } from './script';
import type { LagrangeState } from './state';

/**
 * The basis is sampled at t = i / SAMPLES, once: the plot, the curve
 * Σ L_k(t) P_k, the largest Σ|L_k(t)| and the hover over a basis curve all
 * read these numbers.
 */
export const SAMPLES = 800;
/** The plot shows L_k between ±CLIP; beyond, the curves are cut and the figure says so. */
export const CLIP = 3;

/** Everything the two figures and the panel show, computed once per state. */
export interface LagrangeModel {
  state: LagrangeState;
  /** Degree n = number of points − 1. */
  n: number;
  /** What the steps so far reveal: how many Lₖ, the polynomial, the spline. */
  shown: Revealed<Reveal>;
  /** Points on one spot or one line, and what the polynomial does then; or null. */
  note: string | null;
  /** The parameter values t_k actually used. */
  ts: number[];
  /** Chord length was asked for but two neighbours coincide: which ones (then ts are uniform). */
  collapsed: [number, number] | null;
  /** Why the values are uniform after all: on the figure, and in the panel. */
  collapsedNote: string | null;
  collapsedWarning: string | null;
  /** Each L_k at t = i / SAMPLES (`basis.curves[k]`, interleaved [t, L_k(t), …]), and their extremes. */
  basis: BasisSamples;
  /** The polynomial at the same t's, interleaved [x, y, …]. */
  curve: Float64Array;
  /** The weights L_k(t) at the slider's t, their sum, and the point they give. */
  weights: number[];
  weightSum: number;
  at: Point;
  /** The natural cubic spline through the same points, compared with the polynomial (when asked for). */
  comparison: SplineComparison | null;
  /** The largest Σ|L_k(t)| (the Lebesgue constant, sampled) and where it is reached. */
  lebesgue: { value: number; t: number };
  /** "Fit view" of the curve figure: the points, and the polynomial's swings up to a point. */
  curveBounds: Bounds;
  /** The basis plot's range, and each L_k cut to it. */
  plotBounds: Bounds;
  basisPieces: Float64Array[][];
  /** Some L_k leaves ±CLIP. */
  basisCut: boolean;
}

/**
 * The natural cubic spline beside the polynomial: its gradients solve one
 * system for all the points together, so it is global (moving one point moves
 * every gradient), though far calmer than one polynomial of high degree.
 */
export interface SplineComparison {
  /** One cubic Bézier per gap, from the gradients D0 … Dn. */
  segments: Point[][];
  /** D0 … Dn of the natural spline (uniform parameter, one unit per piece). */
  gradients: Point[];
  /** On each piece, the largest distance between the polynomial and the spline. */
  gaps: number[];
  /** The point moved to show the coupling, and how far (up, in y). */
  moved: number;
  nudge: number;
  /** The spline after that move, and |ΔDₖ| for every gradient. */
  ghost: Point[][];
  gradientChange: number[];
  /** How many gradients changed (all, unless the points are symmetric about the moved one). */
  changed: number;
}

/** What depends on the points and the spacing only. */
type Polynomial = Omit<
  LagrangeModel,
  'state' | 'shown' | 'weights' | 'weightSum' | 'at' | 'comparison'
>;

/** The point moved to show the coupling: off the middle, so symmetry hides no change. */
export const movedPoint = (n: number) => Math.max(0, Math.ceil(n / 2) - 1);
/** How far it is moved, up. */
export const NUDGE = 1;

/** The id under the pointer when it is over L_k's curve (the panel marks L_k's row). */
export const basisId = (k: number) => `L${k}`;

type Nodes = Pick<LagrangeState, 'points' | 'spacing'>;

/** t_k by the chosen spacing; chord length with two equal neighbours falls back to uniform. */
export function parameters({ points, spacing }: Nodes): Pick<LagrangeModel, 'ts' | 'collapsed'> {
  if (spacing === 'chord') {
    const ts = parameterValues(points, 1);
    for (let k = 1; k < ts.length; k++) {
      // Equal values: no polynomial can be at two places at one t.
      if (ts[k] === ts[k - 1]) return { ts: parameterValues(points, 0), collapsed: [k - 1, k] };
    }
    return { ts, collapsed: null };
  }
  return { ts: parameterValues(points, 0), collapsed: null };
}

/**
 * The basis and the polynomial: they read only the points and the spacing, so
 * a step, a moved t or the spline switched costs no new sampling.
 */
const polynomial = memoOn<Nodes, 'points' | 'spacing', Polynomial>(
  ['points', 'spacing'],
  (fields) => {
    const { points } = fields;
    const { ts, collapsed } = parameters(fields);
    const basis = sampleBasis((at) => lagrangeBasis(ts, at), SAMPLES);
    const curves = basis.curves;
    const curve = combine(curves, points);
    const plotBounds = basisBounds(basis);
    const note = noteFor(points, collapsed !== null);
    return {
      n: points.length - 1,
      note,
      ts,
      collapsed,
      collapsedNote: collapsed
        ? `P${collapsed[0]} and P${collapsed[1]} coincide, so chord length gives them the same t, and no polynomial is at two places at one t: equally spaced values are used instead.`
        : null,
      collapsedWarning: collapsed
        ? `P${collapsed[0]} and P${collapsed[1]} are the same point, so chord length gives them the same parameter value and no polynomial can pass both "at once". The curve uses equally spaced values until you move one of them.`
        : null,
      basis,
      curve,
      lebesgue: lebesgueConstant(curves),
      curveBounds: curveBounds(points, curve, collapsed !== null || note !== null),
      plotBounds,
      basisPieces: curves.map((c) => clipToBand(c, plotBounds.minY, plotBounds.maxY)),
      basisCut: basis.lowest.value < -CLIP || basis.highest.value > CLIP,
    };
  },
);

/** The natural cubic spline through the same points, when it is compared. */
const splineThrough = memoOn<
  LagrangeState,
  'points' | 'spacing' | 'spline',
  SplineComparison | null
>(['points', 'spacing', 'spline'], (fields) => {
  if (!fields.spline) return null;
  const { points } = fields;
  const gradients = naturalCubicTangents(points);
  const segments = cubicSplineSegments(points, gradients);
  const n = points.length - 1;
  const moved = movedPoint(n);
  const nudged = points.map((p, k): Point => (k === moved ? [p[0], p[1] + NUDGE] : p));
  const after = naturalCubicTangents(nudged);
  const gradientChange = gradients.map((d, k) =>
    Math.hypot(after[k][0] - d[0], after[k][1] - d[1]),
  );
  return {
    segments,
    gradients,
    gaps: pieceGaps(polynomial(fields), segments),
    moved,
    nudge: NUDGE,
    ghost: cubicSplineSegments(nudged, after),
    gradientChange,
    // A change below rounding is no change.
    changed: gradientChange.filter((c) => c > 1e-9).length,
  };
});

/**
 * On piece k (tₖ to tₖ₊₁ of the polynomial, 0 to 1 of the spline's piece), the
 * largest distance between the two curves at matching parameters.
 */
function pieceGaps({ ts, curve }: Pick<Polynomial, 'ts' | 'curve'>, segments: Point[][]): number[] {
  return segments.map((segment, k) => {
    let gap = 0;
    for (let i = 0; i <= SAMPLES; i++) {
      const t = i / SAMPLES;
      if (t < ts[k] || t > ts[k + 1]) continue;
      const [x, y] = bezierPoint(segment, (t - ts[k]) / (ts[k + 1] - ts[k]));
      gap = Math.max(gap, Math.hypot(curve[2 * i] - x, curve[2 * i + 1] - y));
    }
    return gap;
  });
}

export function derive(state: LagrangeState, shown: Revealed<Reveal>): LagrangeModel {
  const { points, t } = state;
  const geometry = polynomial(state);
  const weights = lagrangeBasis(geometry.ts, t);
  const comparison = splineThrough(state);
  return {
    ...geometry,
    // Beside the spline, its gradients' arrows (drawn at true length) stay on the figure too.
    curveBounds: comparison
      ? unionBounds(
          geometry.curveBounds,
          boundsOf(
            points.map((p, k) => [
              p[0] + comparison.gradients[k][0],
              p[1] + comparison.gradients[k][1],
            ]),
          ),
        )
      : geometry.curveBounds,
    state,
    shown,
    weights,
    weightSum: weights.reduce((a, b) => a + b, 0),
    at: [0, 1].map((d) => weights.reduce((sum, w, k) => sum + w * points[k][d], 0)),
    comparison,
  };
}

/** P(t_i) = Σ_k L_k(t_i) P_k at every sampled t_i, interleaved [x, y, …]. */
function combine(basis: readonly Float64Array[], p: readonly Point[]): Float64Array {
  const out = new Float64Array(basis[0].length);
  basis.forEach((curve, k) => {
    for (let i = 1; i < curve.length; i += 2) {
      out[i - 1] += curve[i] * p[k][0];
      out[i] += curve[i] * p[k][1];
    }
  });
  return out;
}

function curveBounds(p: readonly Point[], curve: Float64Array, note: boolean): Bounds {
  // The view fits the subject: the points, and the polynomial only as far as
  // it stays near them (half the points' smaller side, or a fifth of the
  // larger). A wild polynomial leaves the view, which is the lesson; the
  // legend is not given room of its own, so the points stay large.
  const points = boundsOf(p);
  const width = points.maxX - points.minX;
  const height = points.maxY - points.minY;
  const reach = 0.3 * Math.max(Math.min(width, height), 0.25 * Math.max(width, height), 1);
  let [minX, maxX, minY, maxY] = [points.minX, points.maxX, points.minY, points.maxY];
  for (let i = 0; i < curve.length; i += 2) {
    minX = Math.min(minX, curve[i]);
    maxX = Math.max(maxX, curve[i]);
    minY = Math.min(minY, curve[i + 1]);
    maxY = Math.max(maxY, curve[i + 1]);
  }
  const bounds = {
    minX: Math.max(points.minX - reach, minX),
    maxX: Math.min(points.maxX + reach, maxX),
    minY: Math.max(points.minY - reach, minY),
    maxY: Math.min(points.maxY + reach, maxY),
  };
  // A note about the points (on one line, on one spot) is read before the figure: room for it.
  return note ? { ...bounds, maxY: bounds.maxY + 0.7 * (bounds.maxY - bounds.minY || 1) } : bounds;
}

/** From a little below 0 to a little above 1, and as far as the L_k swing, up to ±CLIP. */
function basisBounds({ lowest, highest }: BasisSamples): Bounds {
  const low = Math.min(-0.3, lowest.value);
  const high = Math.max(1.2, highest.value);
  return { minX: 0, maxX: 1, minY: Math.max(-CLIP, low * 1.05), maxY: Math.min(CLIP, high * 1.05) };
}

/** Coincident or collinear points, in words: what the polynomial does through them. */
function noteFor(points: readonly Point[], collapsed: boolean): string | null {
  const { allSame, collinear, repeats } = degenerate(points);
  if (allSame) return 'All points are on one spot: the polynomial through them is that one point.';
  const notes: string[] = [];
  if (collinear)
    notes.push(
      'The points lie on one line: so does the polynomial, but it may overshoot a point and run back along the line.',
    );
  if (repeats.length && !collapsed)
    notes.push(
      `${repeatsText(repeats)}: the polynomial must be at that spot at two values of t, so it stops there or makes a loop.`,
    );
  return notes.length ? notes.join(' ') : null;
}
