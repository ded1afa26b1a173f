import { choice, int, stepField, linkKey, number, points } from '../../app/fields';
import type { Point } from '../../app/lesson';
import type { Schema } from '../../app/urlState';
import { CURVE_SOURCES, type CurveSource, MAX_LINKED_POINTS } from '../../kit/lessonLinks';

/**
 * The parts of the lesson, in teaching order: each is a family of scenes with
 * its own steps (joins: G², G³ and C^(n−1) at the joins of a spline).
 */
export type Part = 'plane' | 'space' | 'arc' | 'joins';
/** The curve in space: the helix (closed forms) or a cubic Bézier with 3D control points. */
export type SpaceCurve = 'helix' | 'bezier';

/**
 * Everything the curvature lesson shows, and all of it goes in the link
 * (under the short keys of lessonLinks.ts and of links made before: src, p, d, q, …).
 */
export interface CurvatureState {
  part: Part;
  /** Where the plane curve comes from: one Bézier curve, or another lesson's spline. */
  source: CurveSource;
  /** The plane curve's points: control points of a Bézier curve or a B-spline, or the points a spline passes through. */
  points: Point[];
  /** The gradients D0 … Dm of a Hermite spline (source hermite). */
  gradients: Point[];
  /** Control points of the space cubic Q0 … Q3 (x, y, z). */
  spacePoints: Point[];
  spaceCurve: SpaceCurve;
  /** Helix radius a and rise b per radian: r(θ) = (a cos θ, a sin θ, bθ). */
  radius: number;
  rise: number;
  t: number;
  step: number;
  /** Arc length part: the number n of equal steps (of t, and of arc length). */
  equalSteps: number;
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
  part: choice<Part>({ default: 'plane', values: ['plane', 'space', 'arc', 'joins'] }),
  source: linkKey(choice<CurveSource>({ default: 'bezier', values: CURVE_SOURCES }), 'src'),
  points: linkKey(points({ default: LECTURE_CUBIC, min: 2, max: MAX_LINKED_POINTS }), 'p'),
  gradients: linkKey(points({ default: [], min: 0, max: MAX_LINKED_POINTS }), 'd'),
  spacePoints: linkKey(points({ default: TWISTED_CUBIC, min: 4, max: 4, dimension: 3 }), 'q'),
  spaceCurve: linkKey(
    choice<SpaceCurve>({ default: 'helix', values: ['helix', 'bezier'] }),
    'curve',
  ),
  radius: linkKey(number({ default: 1, min: 0.1, max: 5 }), 'a'),
  rise: linkKey(number({ default: 0.25, min: -3, max: 3 }), 'b'),
  t: number({ default: 0.3, min: 0, max: 1 }),
  step: stepField(),
  equalSteps: linkKey(int({ default: 8, min: 2, max: 24 }), 'n'),
};
