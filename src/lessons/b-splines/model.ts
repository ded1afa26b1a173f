import type { Revealed } from '../../kit/script';
import type { Point } from '../../math';
import type { Crossings } from './crossings';
import { type ContinuityCase, type JoinCheck, continuityCurves } from './continuityGeometry';
import type { ContinuityReveal } from './continuityScript';
import { knotCurve, knotCursor } from './knotGeometry';
import { type KnotPoint, stateKnotPoints } from './meaningsGeometry';
import type { MeaningsReveal } from './meaningsScript';
import { circleCheck, projective, rational } from './nurbsGeometry';
import type { KnotReveal } from './knotScript';
import type { CircleReveal, NurbsReveal, ProjectiveReveal } from './nurbsScripts';
import type { ConvertReveal, LocalReveal, PropertiesReveal } from './cubicScripts';
import type { Reveal } from './scripts';
import { FAMILY, type BSplineState, isUniformPart } from './state';
import {
  localControl,
  properties,
  uniformCurve,
  uniformCursor,
  convertBack,
} from './uniformGeometry';
import type { UniformReveal } from './uniformScript';

/** One polynomial piece of the curve, between two knots. */
export interface Segment {
  /** Parameter interval [from, to]. */
  from: number;
  to: number;
  /** Indices into the points of the control points acting on it (four for the cubic, p + 1 in general). */
  points: number[];
  /** Sampled, interleaved x, y. */
  samples: Float64Array;
  /** Its cubic Bézier control points (uniform cubic only: drawn exactly). */
  bezier?: Point[];
}

/** A knot value inside the domain, and what it does to the curve there. */
export interface KnotJoin {
  u: number;
  multiplicity: number;
  /** The curve is C^(p − multiplicity) there (−1: it jumps). */
  continuity: number;
  at: Point;
  /** The control point the curve passes through (multiplicity ≥ p), else null. */
  through: number | null;
}

/** The curve: what its points, degree, knots and weights make, whatever the parameter. */
export interface Curve {
  /** The curve's control points (closed: P0 … Pm, P0, P1, P2). */
  control: Point[];
  /** Index into the points of each control point (closed: wraps). */
  owner: number[];
  degree: number;
  knots: number[];
  weights: number[];
  domain: [number, number];
  segments: Segment[];
  /** Sampled N_{i,r} over the whole knot range: rows[r][i] (interleaved u, N). */
  rows: Float64Array[][];
  start: Point;
  end: Point;
  joins: KnotJoin[];
}

/** The cursor: the parameter u and what is there. */
export interface Cursor {
  u: number;
  segment: number;
  /** Local parameter in the segment, 0 … 1 (uniform cubic: the t of B0(t) … B3(t)). */
  local: number;
  point: Point;
  /** The Cox–de Boor triangle at u: table[r][i] = N_{i,r}(u). */
  table: number[][];
  /** N_{i,p}(u) for every control point of the curve. */
  basis: number[];
}

/** What every scene's model holds: its family, its state, what its steps reveal, its curve and cursor. */
interface SceneModel<F, N extends string> extends Curve, Cursor {
  kind: F;
  state: BSplineState;
  shown: Revealed<N>;
}

/** The uniform cubic, with each segment as its Bézier curve. */
interface CubicModel<F, N extends string> extends SceneModel<F, N> {
  beziers: Point[][];
}

export interface LocalControl {
  /** The same points as one Bézier curve, now and before. */
  bezier: Float64Array;
  bezierBefore: Float64Array;
  /** The B-spline of the points before. */
  before: Float64Array[];
  /** Which segments changed, and which points moved. */
  changed: boolean[];
  moved: number[];
}

export interface Properties {
  hulls: Point[][];
  crossings: Crossings;
  /** The affine images: of the control points, of the curve built from them, and of the curve's samples. */
  image: Point[];
  imageSegments: Point[][];
  imageSamples: Point[];
  /** Largest distance between the mapped samples and the curve of the mapped points. */
  deviation: number;
}

export interface Rational {
  /** The same points and knots with every weight 1: the plain B-spline. */
  plain: Float64Array;
  /** Σ w_j N_j(u) at the cursor. */
  denominator: number;
  /** World length of one halo unit (the halo of weight 1), from the control points' extent. */
  haloUnit: number;
}

export interface CircleCheck {
  deviation: number;
  plainDeviation: number;
  samples: Point[];
}

export interface Projective {
  error: string | null;
  points: Point[];
  weights: number[];
  curve: Float64Array;
  /** The mapped curve samples H(P(u)). */
  mapped: Point[];
  /** The mapped points with the old weights: not the mapped curve. */
  plain: Float64Array;
  deviation: number;
  plainDeviation: number;
}

export type UniformModel = CubicModel<'uniform', UniformReveal>;
export type LocalModel = CubicModel<'local', LocalReveal> & { localControl: LocalControl };
/** The segment under the cursor converted back: its four B-spline points. */
export type ConvertModel = CubicModel<'convert', ConvertReveal> & { back: Point[] };
export type PropertiesModel = CubicModel<'properties', PropertiesReveal> & {
  properties: Properties;
};
export type KnotModel = SceneModel<'knots', KnotReveal>;
export type NurbsModel = SceneModel<'nurbs', NurbsReveal> & { rational: Rational };
export type CircleModel = SceneModel<'circle', CircleReveal> & {
  rational: Rational;
  circle: CircleCheck;
};
export type ProjectiveModel = SceneModel<'projective', ProjectiveReveal> & {
  projective: Projective;
};

/** The two meanings of “knots”: the parameter values, and P(u) at each of them. */
export type MeaningsModel = SceneModel<'meanings', MeaningsReveal> & { knotPoints: KnotPoint[] };
/** The step's curve (its degree and knots come from the step), every knot checked, one watched. */
export type ContinuityModel = SceneModel<'continuity', ContinuityReveal> & {
  knotCase: ContinuityCase;
  checks: JoinCheck[];
  watched: JoinCheck;
};

/** Everything the figures and the panel show, one kind per scene family. */
export type BSplineModel =
  | UniformModel
  | LocalModel
  | ConvertModel
  | PropertiesModel
  | KnotModel
  | NurbsModel
  | CircleModel
  | ProjectiveModel
  | MeaningsModel
  | ContinuityModel;

/**
 * The model of a state: its family's curve (kept while the fields it reads are
 * the same, so a step or a new t costs no new curve), the cursor at t, and what
 * the family adds.
 */
export function derive(state: BSplineState, shown: Revealed<Reveal>): BSplineModel {
  // `shown` comes from the family's own script (scripts.ts): its names are the family's.
  const named = shown as Revealed<never>;
  const family = FAMILY[state.part];
  if (isUniformPart(state.part)) {
    const curve = uniformCurve(state);
    const base = { state, shown: named, ...curve, ...uniformCursor(curve, state.t) };
    if (family === 'local') return { ...base, kind: family, localControl: localControl(state) };
    if (family === 'convert')
      return { ...base, kind: family, back: convertBack(curve, base.segment) };
    if (family === 'properties') return { ...base, kind: family, properties: properties(state) };
    return { ...base, kind: 'uniform' };
  }
  if (family === 'continuity') {
    // Step 0 shows the points alone; its (hidden) curve is the next step's.
    const name = shown.name === 'points' ? 'linear' : (shown.name as ContinuityCase);
    const { curve, checks, watched } = continuityCurves(state)[name];
    const base = { state, shown: named, ...curve.curve, ...knotCursor(curve, state.t) };
    return { ...base, kind: family, knotCase: name, checks, watched };
  }
  const knotted = knotCurve(state);
  const base = { state, shown: named, ...knotted.curve, ...knotCursor(knotted, state.t) };
  if (family === 'nurbs') return { ...base, kind: family, rational: rational(state, base) };
  if (family === 'circle')
    return { ...base, kind: family, rational: rational(state, base), circle: circleCheck(state) };
  if (family === 'projective') return { ...base, kind: family, projective: projective(state) };
  if (family === 'meanings') return { ...base, kind: family, knotPoints: stateKnotPoints(state) };
  return { ...base, kind: 'knots' };
}
