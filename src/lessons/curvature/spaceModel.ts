import {
  type Point,
  bezierFrenetFrame,
  bezierPoint,
  bezierTangent,
  bezierTorsion,
  cross,
  dot,
  frenetInvariants,
  helixCurvature,
  helixDerivatives,
  helixFrame,
  helixTorsion,
  helixPoint,
  norm,
} from '../../math';
import { robustCap, runs, sizeOf } from './measure';
import type { PlaneModel } from './planeModel';
import { type CurvatureState, HELIX_TURNS } from './state';

/** The fields the space curve is made of: which curve, the helix's a and b, the cubic's Q0 … Q3. */
export type SpaceCurveFields = Pick<
  CurvatureState,
  'spaceCurve' | 'radius' | 'rise' | 'spacePoints'
>;

const SAMPLES = 240;
/** Frames drawn along the curve (step 5). */
const FRAMES_ALONG = 9;
const FLIP_WINDOW = 0.15;

/** The Frenet frame of the space curve at one t; normal and binormal null where κ = 0. */
export interface SpaceAt {
  t: number;
  point: Point;
  tangent: Point | null;
  normal: Point | null;
  binormal: Point | null;
  curvature: number | null;
  torsion: number | null;
  speed: number;
  why: string | null;
}

export interface SpaceModel {
  /** The curve sampled as 3D points. */
  curve: Point[];
  size: number;
  at: SpaceAt;
  /** The osculating circle at t (3D points), empty where κ = 0. */
  circle: Point[];
  along: SpaceAt[];
  /** κ(t) and τ(t) sampled (interleaved t, value), cut where undefined. */
  kappa: Float64Array[];
  tau: Float64Array[];
  /** Parameters where κ has a near-zero minimum and B turns over: the frame flips. */
  flips: number[];
  /**
   * The smallest κ along the curve (the helix's own a/(a² + b²); the cubic's
   * sampled), 0 where it is straight somewhere, null where no κ is defined.
   */
  least: number | null;
  /** |κ|, |τ| above which the plot clips (τ is huge where κ nearly vanishes). */
  cap: number;
  /** The closed forms (helix only). */
  closed: { curvature: number; torsion: number } | null;
}

const flipWhy =
  'κ = 0 here: P″ is parallel to P′, the curve is straight for an instant, so no plane osculates and N, B and τ are undefined.';

/** The frame at t of the helix (closed forms, θ = 2π·turns·t) or of the space cubic. */
export function spaceFrame(state: SpaceCurveFields, t: number): SpaceAt {
  if (state.spaceCurve === 'helix') {
    const theta = 2 * Math.PI * HELIX_TURNS * t;
    const f = helixFrame(state.radius, state.rise, theta);
    // κ and τ from the general formulas (the closed forms are shown beside them);
    // neither depends on the parameter, and dθ/dt = 2π·turns.
    const { curvature, torsion } = frenetInvariants(
      ...helixDerivatives(state.radius, state.rise, theta),
    );
    return { ...f, curvature, torsion, t, speed: f.speed * 2 * Math.PI * HELIX_TURNS, why: null };
  }
  return bezierFrame(state.spacePoints, t);
}

export function bezierFrame(q: readonly Point[], t: number): SpaceAt {
  const speed = norm(bezierTangent(q, t));
  let frame;
  try {
    frame = bezierFrenetFrame(q, t);
  } catch {
    const why = 'Cusp: P′(t) = 0, so T = P′/|P′| and the whole frame are undefined.';
    return { ...nothing(bezierPoint(q, t), t, speed), why };
  }
  let torsion: number;
  try {
    torsion = bezierTorsion(q, t);
  } catch {
    return {
      ...nothing(frame.point, t, speed),
      tangent: frame.tangent,
      curvature: 0,
      why: flipWhy,
    };
  }
  return { ...frame, binormal: frame.binormal ?? null, t, torsion, speed, why: null };
}

function nothing(point: Point, t: number, speed: number): SpaceAt {
  const empty = { tangent: null, normal: null, binormal: null, curvature: null, torsion: null };
  return { point, t, speed, ...empty, why: null };
}

/** The plane curve as a space curve in z = 0: B = T × N = ±e_z, τ = 0. */
export function liftPlane(plane: PlaneModel): SpaceAt {
  const { at } = plane;
  const lift = (v: Point | null) => (v ? [v[0], v[1], 0] : null);
  const tangent = lift(at.tangent);
  const normal = lift(at.normal);
  return {
    t: at.t,
    point: [at.point[0], at.point[1], 0],
    tangent,
    normal,
    binormal: tangent && normal ? cross(tangent, normal) : null,
    curvature: at.curvature === null ? null : Math.abs(at.curvature),
    torsion: at.normal ? 0 : null,
    speed: at.speed,
    why: at.why,
  };
}

function osculating(at: SpaceAt): Point[] {
  if (!at.tangent || !at.normal || !at.curvature) return [];
  const r = 1 / at.curvature;
  const centre = at.point.map((v, d) => v + r * at.normal![d]);
  const circle: Point[] = [];
  for (let i = 0; i <= 96; i++) {
    const phi = (2 * Math.PI * i) / 96;
    circle.push(
      centre.map(
        (v, d) => v + r * (-Math.cos(phi) * at.normal![d] + Math.sin(phi) * at.tangent![d]),
      ),
    );
  }
  return circle;
}

/** Local minima of κ below a tenth of its largest value where B turns by more than 90° within Δt = ±0.15. */
function findFlips(state: SpaceCurveFields, kappa: readonly (number | null)[]): number[] {
  if (state.spaceCurve === 'helix') return [];
  const largest = Math.max(0, ...kappa.map((k) => k ?? 0));
  const flips: number[] = [];
  for (let i = 1; i < kappa.length - 1; i++) {
    const [before, here, after] = [kappa[i - 1], kappa[i], kappa[i + 1]];
    if (here === null || before === null || after === null) continue;
    if (!(here <= before && here < after && here < 0.1 * largest)) continue;
    const t = i / (kappa.length - 1);
    const a = bezierFrame(state.spacePoints, Math.max(0, t - FLIP_WINDOW)).binormal;
    const b = bezierFrame(state.spacePoints, Math.min(1, t + FLIP_WINDOW)).binormal;
    if (a && b && dot(a, b) < 0) flips.push(t);
  }
  return flips;
}

/** The plane curve (parts plane and arc) as a space curve lying in z = 0, with its frame at t. */
export function liftedSpace(plane: PlaneModel): SpaceModel {
  const at = liftPlane(plane);
  // At most about 240 points: the space view strokes each segment on its own.
  const samples = plane.curve.length / 2;
  const every = Math.max(1, Math.ceil((samples - 1) / 240));
  const curve: Point[] = [];
  for (let i = 0; i < samples; i += every)
    curve.push([plane.curve[2 * i], plane.curve[2 * i + 1], 0]);
  if ((samples - 1) % every) curve.push([plane.curve.at(-2)!, plane.curve.at(-1)!, 0]);
  return {
    curve,
    size: plane.size,
    at,
    circle: osculating(at),
    along: [],
    kappa: [],
    tau: [],
    flips: [],
    least: null,
    cap: 1,
    closed: null,
  };
}

/** Everything of the space model that does not depend on the cursor t: computed once per curve. */
export type SpaceCurveModel = Omit<SpaceModel, 'at' | 'circle'>;

export function deriveSpaceCurve(state: SpaceCurveFields): SpaceCurveModel {
  const curve: Point[] = [];
  const kappa: (number | null)[] = [];
  const tau: (number | null)[] = [];
  for (let i = 0; i <= SAMPLES; i++) {
    const t = i / SAMPLES;
    if (state.spaceCurve === 'helix') {
      curve.push(helixPoint(state.radius, state.rise, 2 * Math.PI * HELIX_TURNS * t));
      const f = spaceFrame(state, t);
      kappa.push(f.curvature);
      tau.push(f.torsion);
    } else {
      const f = bezierFrame(state.spacePoints, t);
      curve.push(f.point);
      kappa.push(f.curvature);
      tau.push(f.torsion);
    }
  }
  // The plot shows ±1.25 cap: runs are cut where a value leaves it (τ near κ = 0).
  const cap = robustCap([...kappa, ...tau]);
  const inside = (v: number | null) => (v !== null && Math.abs(v) <= 1.25 * cap ? v : null);
  const along = Array.from({ length: FRAMES_ALONG }, (_, k) =>
    spaceFrame(state, k / (FRAMES_ALONG - 1)),
  );
  const { radius: a, rise: b } = state;
  const closed =
    state.spaceCurve === 'helix'
      ? { curvature: helixCurvature(a, b), torsion: helixTorsion(a, b) }
      : null;
  const defined = kappa.filter((k): k is number => k !== null);
  return {
    curve,
    size: sizeOf(curve.filter((_, i) => i % 24 === 0)),
    along,
    kappa: runs(kappa.map(inside)),
    tau: runs(tau.map(inside)),
    flips: findFlips(state, kappa),
    least: closed ? closed.curvature : defined.length ? Math.min(...defined) : null,
    cap,
    closed,
  };
}

/** The space model at the cursor t: the curve's part reused, only the frame at t new. */
export function deriveSpace(
  curve: SpaceCurveModel,
  state: SpaceCurveFields,
  t: number,
): SpaceModel {
  const at = spaceFrame(state, t);
  return { ...curve, at, circle: osculating(at) };
}
