import { choice, int, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';
import { CURVE_SOURCES, type CurveSource, MAX_LINKED_POINTS } from '../../kit/lessonLinks';

/** The three parts of the lesson, in teaching order. */
export type Part = 'plane' | 'space' | 'arc';
/** The curve in space: the helix (closed forms) or a cubic Bézier with 3D control points. */
export type SpaceCurve = 'helix' | 'bezier';

/** Everything the curvature lesson shows, and all of it goes in the link. */
export interface CurvatureState {
  part: Part;
  /** Where the plane curve comes from: one Bézier curve, or another lesson's spline. */
  src: CurveSource;
  /** The plane curve's points: control points of a Bézier curve or a B-spline, or the points a spline passes through. */
  p: Point[];
  /** The gradients D0 … Dm of a Hermite spline (src=hermite). */
  d: Point[];
  /** Control points of the space cubic Q0 … Q3 (x, y, z). */
  q: Point[];
  curve: SpaceCurve;
  /** Helix radius a and rise b per radian: r(θ) = (a cos θ, a sin θ, bθ). */
  a: number;
  b: number;
  t: number;
  step: number;
  /** Arc length part: the number of equal steps (of t, and of arc length). */
  n: number;
}

/** The helix is drawn for θ = 2π·turns·t, t ∈ [0, 1]. */
export const HELIX_TURNS = 2;

/** The lecture's cubic. */
export const LECTURE_CUBIC: Point[] = [
  [0, 0],
  [1, 2],
  [3, 2],
  [4, 0],
];

/**
 * A space cubic whose top view is an S with a small lift: κ falls to 7% of its
 * largest value mid-way, and B swings round by about 150° there.
 */
export const TWISTED_CUBIC: Point[] = [
  [0, 0, 0],
  [1.5, 2.5, 0.5],
  [2.5, -2.5, 0.5],
  [4, 0, 0],
];

export const schema: Schema<CurvatureState> = {
  part: choice<Part>({ default: 'plane', values: ['plane', 'space', 'arc'] }),
  src: choice<CurveSource>({ default: 'bezier', values: CURVE_SOURCES }),
  p: points({ default: LECTURE_CUBIC, min: 2, max: MAX_LINKED_POINTS }),
  d: points({ default: [], min: 0, max: MAX_LINKED_POINTS }),
  q: points({ default: TWISTED_CUBIC, min: 4, max: 4, dimension: 3 }),
  curve: choice<SpaceCurve>({ default: 'helix', values: ['helix', 'bezier'] }),
  a: number({ default: 1, min: 0.1, max: 5 }),
  b: number({ default: 0.25, min: -3, max: 3 }),
  t: number({ default: 0.3, min: 0, max: 1 }),
  step: int({ default: 0, min: 0, max: 12 }),
  n: int({ default: 8, min: 2, max: 24 }),
};

/** The caption of every step of each part: step k shows what caption k adds. */
export const STEPS: Record<Part, readonly string[]> = {
  plane: [
    'The cubic Bézier curve and the point P(t)',
    'The velocity P′(t): its length |P′(t)| is the speed',
    'The unit tangent T = P′/|P′|',
    'The unit normal N: T turned a quarter turn anticlockwise',
    'The curvature κ and the osculating circle of radius 1/|κ|',
    'The curvature comb: teeth as long as |κ|, on the outside of every bend',
    'Inflections (κ = 0) and cusps (speed 0): there N is undefined',
  ],
  space: [
    'The curve in space and the point P(t)',
    'The unit tangent T = P′/|P′|',
    'The principal normal N, towards which T turns; κ = |P′ × P″|/|P′|³',
    'The binormal B = T × N; the torsion τ says how fast B turns',
    'The osculating plane spanned by T and N, with the osculating circle',
    'The frame carried along the curve',
    'Where κ → 0 the frame flips: N and B swing round fast (at κ = 0 they would jump)',
  ],
  arc: [
    'The curve and its parameter t',
    'Ticks at equal steps of t: they bunch where the curve is slow',
    'The arc length s(t) = ∫₀ᵗ |P′(u)| du against t',
    'The arc length table: s at equal steps of t',
    'Equal steps of arc length: t read back from the table',
    'Both sets of ticks: equal t against equal s',
  ],
};

export const stepCount = (state: CurvatureState) => STEPS[state.part].length - 1;

export const describeStep = (state: CurvatureState, k: number) =>
  STEPS[state.part][Math.min(k, stepCount(state))];
