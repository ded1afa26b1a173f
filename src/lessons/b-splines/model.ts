import {
  bezierToUniformBSpline,
  convexHull,
  coxDeBoorTable,
  nurbsPoint,
  projectiveMap,
  projectiveMapWeighted,
  sampleBezier,
  uniformBSplineBasis,
  uniformBSplinePoint,
  uniformBSplineSegments,
  type Point,
} from '../../math';
import { basisRows } from './basisSamples';
import { haloUnit } from './halo';
import { type Crossings, crossings } from './crossings';
import { type BSplineState, isRationalPart, isUniformPart } from './state';

/** Samples per curve segment (a polynomial piece between two knots). */
const SAMPLES = 48;

/** The lecture's affine map of the properties scene: a rotation with shear, moved to the right. */
export const AFFINE: number[][] = [
  [0.9, 0.5, 13],
  [-0.3, 1, 1],
  [0, 0, 1],
];

/**
 * The perspective map of the projective scene: (x, y) ↦ (x, y)/(0.08x + 0.06y + 1)
 * moved 9 to the right. Its vanishing line 0.08x + 0.06y + 1 = 0 is far to the lower left.
 */
export const PERSPECTIVE: number[][] = [
  [1 + 9 * 0.08, 9 * 0.06, 9],
  [0, 1, 0],
  [0.08, 0.06, 1],
];

/** The exact circle of the NURBS circle scene. */
export const CIRCLE = { centre: [0, 0] as Point, radius: 3 };

/** One polynomial piece of the curve, between two knots. */
export interface Segment {
  /** Parameter interval [from, to]. */
  from: number;
  to: number;
  /** Indices into p of the control points acting on it (four for the cubic, p + 1 in general). */
  points: number[];
  /** Sampled, interleaved x, y. */
  samples: Float64Array;
  /** Its cubic Bézier control points (uniform cubic only). */
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

export interface BSplineModel {
  state: BSplineState;
  /** The curve's control points (closed: x0 … xm, x0, x1, x2). */
  control: Point[];
  /** Index into p of each control point (closed: wraps). */
  owner: number[];
  degree: number;
  knots: number[];
  weights: number[];
  domain: [number, number];
  segments: Segment[];
  /** The current parameter u and what is there. */
  u: number;
  segment: number;
  /** Local parameter in the segment, 0 … 1 (uniform cubic: the lecture's t). */
  local: number;
  point: Point;
  /** The Cox–de Boor triangle at u: table[r][i] = N_{i,r}(u). */
  table: number[][];
  /** N_{i,p}(u) for every control point of the curve. */
  basis: number[];
  /** Sampled N_{i,r} over the whole knot range: rows[r][i] (interleaved u, N). */
  rows: Float64Array[][];
  start: Point;
  end: Point;
  joins: KnotJoin[];
  localControl?: LocalControl;
  convert?: { bspline: Point[] };
  properties?: Properties;
  rational?: Rational;
  circle?: { deviation: number; plainDeviation: number; samples: Point[] };
  projective?: Projective;
}

export interface LocalControl {
  /** The same points as one Bézier curve, now and before. */
  bezier: Float64Array;
  bezierBefore: Float64Array;
  /** The B-spline of the points before. */
  before: Float64Array[];
  /** Which segments changed, and the largest change of the Bézier curve. */
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
  /** Rational basis R_i(u) = w_i N_i(u) / Σ w_j N_j(u). */
  rbasis: number[];
  denominator: number;
  /** World length of one halo unit (the halo of weight 1), from the control points' extent. */
  haloUnit: number;
}

export interface Projective {
  error: string | null;
  points: Point[];
  weights: number[];
  curve: Float64Array;
  /** The mapped curve samples H(C(u)). */
  mapped: Point[];
  /** The mapped points with the old weights: not the mapped curve. */
  plain: Float64Array;
  deviation: number;
  plainDeviation: number;
}

export function derive(state: BSplineState): BSplineModel {
  return isUniformPart(state.x) ? deriveUniform(state) : deriveKnots(state);
}

/** The lecture's uniform cubic: segment i blends x_i … x_{i+3} with the 1/6 matrix. */
function deriveUniform(state: BSplineState): BSplineModel {
  const n = state.p.length;
  const closed = state.x === 'closed';
  const owner = Array.from({ length: closed ? n + 3 : n }, (_, i) => i % n);
  const control = owner.map((i) => state.p[i]);
  const count = control.length - 3;
  const beziers = uniformBSplineSegments(control);
  const segments = beziers.map((bezier, i) => ({
    from: i,
    to: i + 1,
    points: [0, 1, 2, 3].map((k) => owner[i + k]),
    samples: sampleBezier(bezier, SAMPLES),
    bezier,
  }));
  // The lecture's s ∈ [0, m − 2] is u on the knots −3, −2, …: segment i is [i, i + 1].
  const knots = Array.from({ length: control.length + 4 }, (_, j) => j - 3);
  const u = state.t * count;
  const segment = Math.min(Math.floor(u), count - 1);
  const local = u - segment;
  const basis = control.map(() => 0);
  uniformBSplineBasis(local).forEach((b, k) => (basis[segment + k] = b));
  const model: BSplineModel = {
    state,
    control,
    owner,
    degree: 3,
    knots,
    weights: control.map(() => 1),
    domain: [0, count],
    segments,
    u,
    segment,
    local,
    point: uniformBSplinePoint(control, u),
    table: coxDeBoorTable(knots, 3, u),
    basis,
    rows: basisRows(knots, 3),
    start: beziers[0][0],
    end: beziers[count - 1][3],
    joins: [],
  };
  if (state.x === 'local') model.localControl = localControl(state, segments);
  if (state.x === 'convert') model.convert = { bspline: bezierToUniformBSpline(beziers[segment]) };
  if (state.x === 'properties') model.properties = properties(state, model);
  return model;
}

function localControl(state: BSplineState, segments: Segment[]): LocalControl {
  const q = state.q;
  const moved = state.p.flatMap((point, i) =>
    point[0] !== q[i][0] || point[1] !== q[i][1] ? [i] : [],
  );
  const before = uniformBSplineSegments(q).map((bezier) => sampleBezier(bezier, SAMPLES));
  const samples = Math.max(96, 16 * state.p.length);
  return {
    bezier: sampleBezier(state.p, samples),
    bezierBefore: sampleBezier(q, samples),
    before,
    changed: segments.map((segment) => segment.points.some((i) => moved.includes(i))),
    moved,
  };
}

function properties(state: BSplineState, model: BSplineModel): Properties {
  const hulls = model.segments.map((segment) => convexHull(segment.points.map((i) => state.p[i])));
  const image = projectiveMap(AFFINE, state.p);
  const imageSegments = uniformBSplineSegments(image);
  const imageSamples: Point[] = [];
  let deviation = 0;
  model.segments.forEach((_, i) => {
    for (let j = 0; j <= 8; j++) {
      const s = Math.min(i + j / 8, model.domain[1]);
      const mapped = projectiveMap(AFFINE, [uniformBSplinePoint(state.p, s)])[0];
      const direct = uniformBSplinePoint(image, s);
      deviation = Math.max(deviation, Math.hypot(mapped[0] - direct[0], mapped[1] - direct[1]));
      if (j < 8 || i === model.segments.length - 1) imageSamples.push(mapped);
    }
  });
  return {
    hulls,
    crossings: crossings(state.l, state.p, model.segments),
    image,
    imageSegments,
    imageSamples,
    deviation,
  };
}

/** A general B-spline of degree p on the knot vector u, rational from the NURBS scenes on. */
function deriveKnots(state: BSplineState): BSplineModel {
  const { p: points, d: degree, u: knots } = state;
  const n = points.length;
  const weights = isRationalPart(state.x) ? state.w : points.map(() => 1);
  const domain: [number, number] = [knots[degree], knots[n]];
  const at = (u: number) => nurbsPoint(points, weights, knots, degree, u);
  const segments: Segment[] = [];
  for (let j = degree; j < n; j++) {
    if (knots[j] === knots[j + 1]) continue;
    segments.push({
      from: knots[j],
      to: knots[j + 1],
      points: Array.from({ length: degree + 1 }, (_, k) => j - degree + k),
      samples: sampleRange(at, knots[j], knots[j + 1]),
    });
  }
  const u = domain[0] + state.t * (domain[1] - domain[0]);
  const table = coxDeBoorTable(knots, degree, u);
  let segment = 0;
  while (segment + 1 < segments.length && segments[segment + 1].from <= u) segment++;
  const { from, to } = segments[segment];
  const model: BSplineModel = {
    state,
    control: points,
    owner: points.map((_, i) => i),
    degree,
    knots,
    weights,
    domain,
    segments,
    u,
    segment,
    local: (u - from) / (to - from),
    point: at(u),
    table,
    basis: table[degree],
    rows: basisRows(knots, degree),
    start: at(domain[0]),
    end: at(domain[1]),
    joins: knotJoins(knots, degree, n, at),
  };
  if (isRationalPart(state.x)) {
    const plain = points.map(() => 1);
    const products = model.basis.map((b, i) => weights[i] * b);
    const denominator = products.reduce((a, b) => a + b, 0);
    model.rational = {
      plain: flatten(
        segments.map((s) =>
          sampleRange((v) => nurbsPoint(points, plain, knots, degree, v), s.from, s.to),
        ),
      ),
      rbasis: products.map((v) => v / denominator),
      denominator,
      haloUnit: haloUnit(points),
    };
  }
  if (state.x === 'circle') model.circle = circleCheck(model, at);
  if (state.x === 'projective') model.projective = projective(state, model, at);
  return model;
}

function sampleRange(at: (u: number) => Point, from: number, to: number): Float64Array {
  const out = new Float64Array(2 * (SAMPLES + 1));
  for (let k = 0; k <= SAMPLES; k++) {
    const point = at(k === SAMPLES ? to : from + ((to - from) * k) / SAMPLES);
    out[2 * k] = point[0];
    out[2 * k + 1] = point[1];
  }
  return out;
}

function flatten(parts: readonly Float64Array[]): Float64Array {
  const out = new Float64Array(parts.reduce((sum, part) => sum + part.length, 0));
  let offset = 0;
  for (const part of parts) {
    out.set(part, offset);
    offset += part.length;
  }
  return out;
}

/** Each distinct knot inside the domain: its multiplicity k makes the curve C^(p−k) there. */
export function knotJoins(
  knots: readonly number[],
  degree: number,
  n: number,
  at: (u: number) => Point,
): KnotJoin[] {
  const joins: KnotJoin[] = [];
  for (let j = degree + 1; j < n; j++) {
    if (knots[j] === knots[j - 1] || knots[j] >= knots[n]) continue;
    let multiplicity = 1;
    while (knots[j + multiplicity] === knots[j]) multiplicity++;
    joins.push({
      u: knots[j],
      multiplicity,
      continuity: degree - multiplicity,
      at: at(knots[j]),
      // Knots u_j = … = u_{j+p−1}: every basis function but N_{j−1,p} is 0 there.
      through: multiplicity >= degree ? j - 1 : null,
    });
  }
  return joins;
}

/** The circle scene: how far the sampled curve is from the circle (and would be with weights 1). */
function circleCheck(model: BSplineModel, at: (u: number) => Point) {
  const { centre, radius } = CIRCLE;
  const off = (point: Point) =>
    Math.abs(Math.hypot(point[0] - centre[0], point[1] - centre[1]) - radius);
  const samples: Point[] = [];
  const [a, b] = model.domain;
  for (let k = 0; k <= 200; k++) samples.push(at(a + ((b - a) * k) / 200));
  // The plain curve's samples are already there (every weight 1).
  const plain = model.rational!.plain;
  let plainDeviation = 0;
  for (let k = 0; k < plain.length; k += 2) {
    plainDeviation = Math.max(plainDeviation, off([plain[k], plain[k + 1]]));
  }
  return {
    deviation: Math.max(...samples.map(off)),
    plainDeviation,
    samples: samples.filter((_, k) => k % 5 === 0),
  };
}

/** The perspective map applied to the control points with their weights, and without. */
function projective(
  state: BSplineState,
  model: BSplineModel,
  at: (u: number) => Point,
): Projective {
  const { d: degree, u: knots } = state;
  let image: { points: Point[]; weights: number[] };
  try {
    image = projectiveMapWeighted(PERSPECTIVE, state.p, model.weights);
  } catch {
    return {
      error: 'A control point lies beyond the vanishing line of the map: move it back up or right.',
      points: [],
      weights: [],
      curve: new Float64Array(0),
      mapped: [],
      plain: new Float64Array(0),
      deviation: 0,
      plainDeviation: 0,
    };
  }
  const mappedAt = (u: number) => nurbsPoint(image.points, image.weights, knots, degree, u);
  const plainAt = (u: number) => nurbsPoint(image.points, model.weights, knots, degree, u);
  const curve = flatten(model.segments.map((s) => sampleRange(mappedAt, s.from, s.to)));
  const plain = flatten(model.segments.map((s) => sampleRange(plainAt, s.from, s.to)));
  const mapped: Point[] = [];
  let deviation = 0;
  let plainDeviation = 0;
  const [a, b] = model.domain;
  for (let k = 0; k <= 64; k++) {
    const u = a + ((b - a) * k) / 64;
    const expected = projectiveMap(PERSPECTIVE, [at(u)])[0];
    const got = mappedAt(u);
    const wrong = plainAt(u);
    mapped.push(expected);
    deviation = Math.max(deviation, Math.hypot(got[0] - expected[0], got[1] - expected[1]));
    plainDeviation = Math.max(
      plainDeviation,
      Math.hypot(wrong[0] - expected[0], wrong[1] - expected[1]),
    );
  }
  return { error: null, ...image, curve, mapped, plain, deviation, plainDeviation };
}
