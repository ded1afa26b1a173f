import { type Point, bezierBasisMatrix, bezierPoint, sampleBezier } from '../../math';
import { type Bounds, boundsOf } from '../../render/projection';
import { degenerate, repeatsText } from '../../kit/degenerate';
import { memoOn } from '../../kit/memoOn';
import type { Revealed } from '../../kit/script';
import {
  type Compared,
  type ComparedShape,
  comparedAt,
  comparedShape,
  halfway,
} from './comparison';
import { type Family, family } from './families';
import { type Passes, passes } from './passes';
import type { Reveal } from './reveals';
import type { BlendingState } from './state';

export type { Compared } from './comparison';

/**
 * What the figures draw at this step, read off the step names of whichever
 * script the state walks (Bernstein's, a comparison's, or the symmetry's).
 */
export interface Drawn {
  /** How many Bernstein functions W(N, i, μ) are drawn, and faded behind another basis. */
  bernstein: number;
  faded: boolean;
  /** How many control points wear the halo of their weight at μ (with a dot on the plot). */
  weights: number;
  /** P(μ) and the Bézier curve. */
  point: boolean;
  curve: boolean;
  /** How many of the compared functions are drawn. */
  compared: number;
  /** Hermite's end points named, and its end gradients drawn. */
  data: boolean;
  tangents: boolean;
  /** The B-spline's ends, the compared curve, the convex hull. */
  ends: boolean;
  comparedCurve: boolean;
  hull: boolean;
  /** The compared functions' values at μ, and their point. */
  atMu: boolean;
  /** The second cursor at 1 − μ; the pairs W(N, i, μ) = W(N, N − i, 1 − μ) so far; P(1 − μ). */
  mirror: boolean;
  pairs: number;
  reversed: boolean;
  /** Each point's distance to the Lagrange curve written, then to the Bézier curve. */
  onLagrange: boolean;
  onBezier: boolean;
}

function drawnAt(shown: Revealed<Reveal>, n: number): Drawn {
  const whole = shown.has('bezier');
  const symmetry = shown.has('functions');
  // Interpolating or approximating: each curve comes with its weights on the plot.
  const bezierCurve = shown.has('bezierCurve');
  return {
    bernstein: whole || symmetry || bezierCurve ? n + 1 : shown.count('weight'),
    faded: whole && shown.count('basis') > 0,
    weights: whole ? n + 1 : shown.count('weight'),
    point: whole || shown.has('point') || shown.has('reversed'),
    curve: whole || shown.has('curve') || shown.has('reversed') || bezierCurve,
    compared: shown.has('lagrangeCurve') ? n + 1 : shown.count('basis'),
    data: shown.has('data'),
    tangents: shown.has('tangents'),
    ends: shown.has('ends'),
    comparedCurve: shown.has('spline') || shown.has('lagrangeCurve'),
    hull: shown.has('hull'),
    atMu: shown.has('atMu'),
    mirror: shown.has('mirror'),
    pairs: shown.count('pair'),
    reversed: shown.has('reversed'),
    onLagrange: shown.has('interpolating'),
    onBezier: shown.has('approximating'),
  };
}

/** Everything the figures and the panel show, computed once per state. */
export interface BlendingModel {
  state: BlendingState;
  /** Degree N. */
  n: number;
  /** What the steps so far reveal, and what the figures draw for it. */
  shown: Revealed<Reveal>;
  drawn: Drawn;
  bernstein: Family;
  /** W(N, i, μ) for every i, and their sum (1 up to rounding). */
  weights: number[];
  /**
   * What each control point's halo and number show: W(N, i, μ), or at a
   * comparison's values-at-μ step the compared functions' values at the
   * points they weight (Hermite's H₀ at P₀ and H₁ at P₃; null at P₁ and P₂,
   * which Hermite's data leaves out). The figure once wrote Bernstein's
   * weights there beside a caption on Lagrange's negative ones.
   */
  pointWeights: (number | null)[];
  sum: number;
  /** P(μ), and the curve sampled (interleaved x, y). */
  point: Point;
  /** P(1 − μ): the same curve's point with the weights reversed. */
  mirrored: Point;
  curve: Float64Array;
  compared: Compared | null;
  /** P(0.5): the curve's middle, the binomially weighted centroid. */
  centre: Point;
  /** M of P(μ) = U M P. */
  matrix: number[][];
  /** What "fit" shows in the curve figure, and the plot's range. */
  curveBounds: Bounds;
  plotBounds: Bounds;
  /** Height of the plot cursor's handle: at the top, clear of the curves. */
  handleY: number;
  /** What is degenerate about the control points and what it does to the curve, or null. */
  note: string | null;
  /** Interpolating or approximating: each point's distance to the Lagrange and the Bézier curve. */
  passes: Passes | null;
}

/** The curve and what depends on its points alone: dragging μ or stepping costs nothing. */
const shape = memoOn<
  Pick<BlendingState, 'p'>,
  'p',
  Pick<BlendingModel, 'n' | 'bernstein' | 'curve' | 'centre' | 'matrix' | 'note'>
>(['p'], ({ p }) => {
  const n = p.length - 1;
  return {
    n,
    bernstein: family('bernstein', n)!,
    curve: sampleBezier(p, Math.max(64, 24 * n)),
    centre: bezierPoint(p, 0.5),
    matrix: bezierBasisMatrix(n),
    note: noteFor(p),
  };
});

/** The basis compared with, its curve, and the ranges both figures show: μ does not move them. */
const comparison = memoOn<
  Pick<BlendingState, 'p' | 'comparison'>,
  'p' | 'comparison',
  Pick<BlendingModel, 'curveBounds' | 'plotBounds' | 'handleY'> & { shape: ComparedShape | null }
>(['p', 'comparison'], ({ p, comparison: kind }) => {
  const compared = comparedShape(p, kind);
  const plotBounds = plotRange(compared);
  return {
    shape: compared,
    curveBounds: boundsOf([
      ...p,
      ...(compared?.curve ?? []),
      // The gradients are drawn at half length (curveFigure).
      ...(compared?.arrows.map(([from, tip]) => halfway(from, tip)) ?? []),
    ]),
    plotBounds,
    handleY: plotBounds.maxY - 0.05 * (plotBounds.maxY - plotBounds.minY),
  };
});

/** Each point's distance to both curves, for interpolating or approximating only: μ does not move it. */
const passesOf = memoOn<
  Pick<BlendingState, 'p' | 'comparison'>,
  'p' | 'comparison',
  Pick<BlendingModel, 'passes'>
>(['p', 'comparison'], ({ p, comparison: kind }) => ({
  passes: kind === 'interpolating' ? passes(p) : null,
}));

/** Everything at μ: the weights, P(μ), and the compared functions' values. */
const atMu = memoOn<
  Pick<BlendingState, 'p' | 'mu' | 'comparison'>,
  'p' | 'mu' | 'comparison',
  Pick<BlendingModel, 'weights' | 'sum' | 'point' | 'mirrored' | 'compared'>
>(['p', 'mu', 'comparison'], (fields) => {
  const { p, mu } = fields;
  const weights = [...shape(fields).bernstein.values(mu)];
  const compared = comparison(fields).shape;
  return {
    weights,
    sum: weights.reduce((a, b) => a + b, 0),
    point: bezierPoint(p, mu),
    mirrored: bezierPoint(p, 1 - mu),
    compared: compared && comparedAt(compared, p, mu),
  };
});

export function derive(state: BlendingState, shown: Revealed<Reveal>): BlendingModel {
  const { curveBounds, plotBounds, handleY } = comparison(state);
  const common = shape(state);
  const drawn = drawnAt(shown, common.n);
  const values = atMu(state);
  return {
    ...common,
    ...values,
    pointWeights: pointWeightsOf(values, drawn, common.n),
    ...passesOf(state),
    curveBounds,
    plotBounds,
    handleY,
    state,
    shown,
    drawn,
  };
}

/** The weights the control points wear at this step (BlendingModel.pointWeights). */
function pointWeightsOf(
  { weights, compared }: Pick<BlendingModel, 'weights' | 'compared'>,
  drawn: Drawn,
  n: number,
): (number | null)[] {
  if (!drawn.atMu || !compared) return weights;
  if (compared.kind !== 'hermite') return compared.atMu;
  // H₀ weights the start point, H₁ the end point; H₂ and H₃ weight gradients.
  return weights.map((_, i) => (i === 0 ? compared.atMu[0] : i === n ? compared.atMu[1] : null));
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

/** μ from 0 to 1; W from its lowest to its highest value, with room for the cursor's handle. */
function plotRange(compared: Family | null): Bounds {
  const low = Math.min(0, compared?.samples.lowest.value ?? 0);
  const high = Math.max(1, compared?.samples.highest.value ?? 1);
  const span = high - low;
  return { minX: 0, maxX: 1, minY: low - 0.04 * span, maxY: high + 0.16 * span };
}
